// Watching a replay: a hotseat Session fed with the replay's commands as
// their ticks come round, so the match shown is the recorded one. It steps, seeks either
// way and can be taken over: the session then plays on live, its recording holding the
// commands up to that tick, a new replay branching from there.
//
// Seeking back re-simulates (Session::rewindTo): Box2D worlds cannot be copied, but a
// deterministic re-run gives the very state the match had. It starts from the nearest
// restart point at or before the target (game/replay_restarts.h: matches parked every
// few seconds, built a slice at a time by prepareRestartPoints between frames), or from
// the start while none is parked there.
// Playing forward compares every stored checkpoint and the final hash, so a replay that
// no longer re-simulates (another build, changed physics) is reported where it first
// differs, not hidden.
#pragma once

#include "game/level.h"
#include "game/replay.h"
#include "game/replay_restarts.h"
#include "game/session.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace game {

/// Where the re-simulation first differed from the recording.
struct ReplayDivergence {
    std::uint64_t tick = 0;
    /// "particles", "bodies", "game" (or a combination), "match", or "final state".
    std::string what;
};

class ReplayPlayer {
  public:
    /// `level` is the replay's own (game::levelForReplay finds it and checks its hash).
    ReplayPlayer(const Level& level, Replay replay);

    /// One tick forward: the replay's commands for this tick, then the step; the
    /// checkpoint stored for the new tick, if any, is compared. Nothing at the end.
    void step();
    /// Goes to `tick`, clamped to [0, lastTick()]: forward by stepping, back by
    /// re-simulation from the start.
    void seek(std::uint64_t tick);
    /// Builds restart points for seeking back, re-simulating at most `tickBudget` ticks;
    /// true when all are built. Call it between frames; seeking works without it.
    bool prepareRestartPoints(std::uint64_t tickBudget);
    const RestartPoints& restartPoints() const { return restarts_; }
    /// Ticks the last seek back re-simulated (from its restart point or the start).
    std::uint64_t lastSeekResimulated() const { return lastSeekResimulated_; }

    std::uint64_t tick() const { return session_.match().tick(); }
    /// Length of the recording (ticks).
    std::uint64_t lastTick() const { return replay_.ticks; }
    bool atEnd() const { return tick() >= lastTick(); }

    const Match& match() const { return session_.match(); }
    const Replay& replay() const { return replay_; }
    /// The first checkpoint (or the final hash) that did not match, if any was found.
    const std::optional<ReplayDivergence>& divergence() const { return divergence_; }
    /// Stored checkpoints compared so far (the furthest the replay was played).
    std::size_t checkpointsChecked() const { return checkpointsChecked_; }
    /// Replay commands the match refused (a hand-edited file; a recorded one has none).
    std::size_t refusedCommands() const { return refused_; }

    /// Ticks at which a shell was fired (the replay's fire commands), in order.
    const std::vector<std::uint64_t>& shotTicks() const { return shots_; }
    /// The last shot before `tick`, and the first one after it.
    std::optional<std::uint64_t> shotBefore(std::uint64_t tick) const;
    std::optional<std::uint64_t> shotAfter(std::uint64_t tick) const;
    std::optional<std::uint64_t> previousShot() const { return shotBefore(tick()); }
    std::optional<std::uint64_t> nextShot() const { return shotAfter(tick()); }

    /// Turns the player into a live session at the current tick: its recording holds
    /// the replay's commands before this tick (and its checkpoints up to it); play goes
    /// on under `options` (difficulty, recording file, hotseat). The player is spent.
    Session takeOver(const SessionOptions& options) &&;

  private:
    void compareCheckpoint();

    Replay replay_;
    Session session_;
    RestartPoints restarts_;
    std::uint64_t lastSeekResimulated_ = 0;
    std::size_t nextCommand_ = 0;    ///< first replay command not yet submitted
    std::size_t nextCheckpoint_ = 0; ///< first stored checkpoint after the current tick
    std::size_t checkpointsChecked_ = 0;
    std::size_t refused_ = 0;
    std::uint64_t furthest_ = 0; ///< the furthest tick reached (compared up to it)
    std::vector<std::uint64_t> shots_;
    std::optional<ReplayDivergence> divergence_;
};

} // namespace game
