// Restart points for seeking back in a replay: whole matches parked at fixed ticks.
//
// A Box2D world cannot be copied, so a match cannot be snapshotted and restored; but a
// replay's commands are fixed, so a match re-simulated from the start to tick s is the
// very match the replay had at s. RestartPoints keeps such matches at s = k * spacing,
// built a slice of ticks at a time between frames (build()), so seeking back to t
// re-simulates at most `spacing` ticks from the nearest point at or before t instead of
// all t ticks from the start. A point handed out (take()) is moving on as the viewer's
// match; it is rebuilt from the start by later build() calls.
//
// Cost: building every point re-simulates spacing * K (K + 1) / 2 ticks for K points
// (each from the start: a parked match cannot be forked), done once per replay and
// spread over frames; memory is K matches.
#pragma once

#include "game/level.h"
#include "game/match.h"
#include "game/replay.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace game {

struct RestartPointsDef {
    std::uint64_t spacing = 600; ///< ticks between points (5 s at 120 Hz)
    std::size_t maxPoints = 32;  ///< longer replays space their points wider
};

class RestartPoints {
  public:
    /// Points for `replay` on `level` (the replay's own, as ReplayPlayer has it).
    RestartPoints(const Level& level, const Replay& replay, const RestartPointsDef& def = {});

    /// Re-simulates at most `tickBudget` ticks towards the next missing point; returns
    /// true when every point is parked.
    bool build(std::uint64_t tickBudget);
    /// The parked match with the greatest tick <= `tick`, removed from its point (which
    /// build() then makes again); null when none is parked there.
    std::unique_ptr<Match> take(std::uint64_t tick);

    std::uint64_t spacing() const { return spacing_; }
    std::size_t points() const { return slots_.size(); }
    std::size_t parked() const;

  private:
    struct Slot {
        std::uint64_t tick = 0;
        std::unique_ptr<Match> match; ///< null while missing
    };
    /// A match on its way to a missing slot, with the next replay command to apply.
    struct Builder {
        std::unique_ptr<Match> match;
        std::size_t nextCommand = 0;
        std::size_t slot = 0;
    };

    Level level_;                   ///< copies: the points outlive no one's data
    std::vector<Command> commands_; ///< the replay's commands, in tick order
    std::uint64_t spacing_;
    std::vector<Slot> slots_;
    Builder builder_;
};

/// Plays `match` forward to `tick` with the replay's commands, as ReplayPlayer::step does:
/// every command of a tick is applied before that tick's step. `nextCommand` is the index
/// of the first command not yet applied, and is advanced.
void playReplayTo(Match& match, const std::vector<Command>& commands, std::size_t& nextCommand,
                  std::uint64_t tick);

} // namespace game
