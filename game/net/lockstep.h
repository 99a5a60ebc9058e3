// Lockstep on the command stream: both peers run the same match and exchange only
// commands and checkpoint hashes. The player whose turn it is runs freely and sends
// its commands at their ticks plus "advance" marks ("every command before tick N is
// sent"); the other side applies those commands at their ticks and may step only up to
// the last mark it received. So the simulation never waits on the network while it is
// one's own turn, and waits at most one network round at a turn boundary: the side
// whose turn ends stops at that tick and hands over.
//
// A peer may send only its own cannon's duel commands (aim, power, select, fire,
// end_turn), only in its turn, in order, never for a tick already simulated; anything
// else is a protocol error that closes the connection. Both sides send the state
// hashes of every replay checkpoint (particles, bodies and the game part separately);
// a mismatch stops the match with "desync at tick N (particles differ)".
//
// No sockets here: the transport hands received messages to receive() and sends what
// takeOutbox() returns, so every rule is unit-tested without a network.
#pragma once

#include "game/ai_turn.h"
#include "game/match.h"
#include "game/net/message.h"
#include "game/replay.h"

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace game::net {

/// Spectator "cannon".
inline constexpr int kSpectator = -1;
/// Most remote commands that may wait for their tick, and checkpoints ahead of ours.
inline constexpr std::size_t kMaxPending = 4096;

struct LockstepOptions {
    int localCannon = 0;   ///< 0 host, 1 joiner, kSpectator watches
    bool autoplay = false; ///< the computer plays the local cannon
    Difficulty difficulty = Difficulty::Normal;
    std::uint64_t cpuSeed = 1;
    std::uint64_t cpuDelayTicks = 60;
    std::uint64_t checkpointEvery = kDefaultCheckpointEvery;
    std::uint64_t advanceEvery = 6; ///< ticks between advance marks in one's own turn
    /// Test hook: from this tick on, the first tick with a shell in flight gets its
    /// velocity nudged by 1 mm/s (a tampered client).
    std::optional<std::uint64_t> tamperTick;
};

class Lockstep {
  public:
    Lockstep(const Level& level, const LockstepOptions& options);

    /// A local command (window, script), stamped with the current tick. Refused when it
    /// is not a duel command, not the local cannon's turn, or the match refuses it.
    std::string submit(Command command);
    /// True when the next tick may run now (own turn, or the peer's mark is ahead).
    bool canStep() const;
    /// Runs the computer's turn if due, applies the received commands due now, steps one
    /// tick, checks the checkpoint. Does nothing when !canStep().
    void step();
    /// In one's own turn, an advance mark at the current tick now rather than at the next
    /// multiple of advanceEvery: a side about to leave tells how far it played, so the
    /// other side plays the match to the same tick.
    void markProgress();

    /// A message from the peer (for the host: from the joining player; for a spectator:
    /// from the host). Returns "" or the protocol error that must close the connection.
    std::string receive(const Message& m);
    /// Messages for the peer, in order.
    std::vector<Message> takeOutbox();
    /// Host only: the stream a spectator follows (every command, the host's tick,
    /// checkpoints), in order.
    std::vector<Message> takeSpectatorOutbox();
    /// What a peer joining now (spectator, or a player resuming) needs: every command
    /// from `fromIndex` on, then the sender's current mark.
    std::vector<Message> catchUp(std::uint32_t fromIndex, bool forSpectator) const;
    /// The peer resumes: resend our own commands it lacks (it holds `peerHas` commands).
    void resume(std::uint32_t peerHas);
    /// A peer rejoined (host side): what the old connection had announced but not
    /// delivered is forgotten; the new one resends or replaces it.
    void forgetPeerProgress();
    /// A rejoining side (perhaps a new process) replays the host's stream, its own old
    /// commands included, up to `tick` before it plays again.
    void catchUpTo(std::uint64_t tick) { replayUntil_ = tick; }
    bool catchingUp() const { return match_->tick() < replayUntil_; }

    const Match& match() const { return *match_; }
    int localCannon() const { return options_.localCannon; }
    bool localTurn() const;
    bool over() const { return match_->over(); }
    /// The desync or protocol error that stopped the match ("" while it runs).
    const std::string& stopped() const { return stopped_; }
    std::uint32_t commandCount() const { return static_cast<std::uint32_t>(commands_.size()); }
    /// Commands received and not yet applied.
    std::size_t pending() const { return pending_.size(); }
    std::uint64_t peerMark() const { return peerMark_; }
    /// The match as a replay (same bytes on both sides of a clean match).
    Replay recording(const std::string& levelFile) const;

  private:
    void send(Message m, bool toSpectators = true);
    void applyPending();
    void checkpoint();
    void compare(const Checkpoint& mine, const Message& theirs);
    void stop(std::string why);
    void computerTurn();

    std::unique_ptr<Match> match_;
    LockstepOptions options_;
    ComputerTurns cpu_;
    std::string levelHash_;
    std::vector<Command> commands_;
    std::vector<int> players_; ///< whose cannon each command is
    std::vector<Checkpoint> checkpoints_;
    std::deque<Message> pending_;
    std::map<std::uint64_t, Message> peerCheckpoints_;
    std::uint64_t peerMark_ = 0;
    std::uint64_t lastMarkSent_ = 0;
    std::vector<Message> outbox_, spectatorOutbox_;
    std::string stopped_;
    bool tampered_ = false;
    std::uint64_t replayUntil_ = 0;
};

/// "desync at tick N (particles differ)": which parts of two checkpoints differ.
std::string desyncMessage(std::uint64_t tick, const Checkpoint& a, const Checkpoint& b);

} // namespace game::net
