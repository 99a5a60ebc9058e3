// A session drives a match the way a player sees it: commands from the window, a script
// or a replay are stamped with the current tick, applied and recorded; the computer
// takes its turns after a short pause, aiming visibly (game/ai_turn.h); the recording
// is a replay with checkpoints, saved atomically at the end of every turn so a crash
// loses at most the last turn.
#pragma once

#include "game/ai_turn.h"
#include "game/match.h"
#include "game/replay.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace game {

struct SessionOptions {
    Difficulty difficulty = Difficulty::Normal;
    std::uint64_t cpuSeed = 1;
    /// Ticks the computer "thinks" before it starts to aim (so a player can see its turn);
    /// its barrel and power then move for kAimSweepSeconds before it fires.
    std::uint64_t cpuDelayTicks = 60;
    std::uint64_t checkpointEvery = kDefaultCheckpointEvery;
    /// Replay file written at the end of every turn and of the match ("" = none).
    std::string recordFile;
    /// Told why, when a save at a turn's end fails; the match goes on (the recording is
    /// kept in memory and saved again at the next turn's end). Without it such a failure
    /// throws std::runtime_error out of step(), as a headless run wants.
    std::function<void(const std::string& why)> onSaveFailure;
    /// The computer plays every cannon (demos, golden replays), not only "cpu" ones.
    bool autoplay = false;
    /// The computer plays no cannon: people take every turn ("cpu" cannons included), or
    /// a replay supplies every command, the computer's recorded ones among them.
    bool hotseat = false;
};

class Session {
  public:
    Session(const Level& level, const SessionOptions& options = {});

    /// Applies a command at the current tick and records it. Returns "" or why refused
    /// (refused commands are not recorded: they changed nothing).
    std::string submit(Command command);
    /// Runs the computer's turn if it is due, then advances one tick, recording
    /// checkpoints; saves the recording when a turn or the match ends.
    void step();

    Match& match() { return *match_; }
    const Match& match() const { return *match_; }
    const Replay& recording() const { return replay_; }
    /// The recording as it stands, with the current tick and final hash filled in.
    Replay finishedRecording() const;
    /// Writes the recording now (atomically); throws std::runtime_error on failure.
    void save(const std::string& file) const;
    /// Goes back to `tick` (<= now) by re-simulating the recorded commands from the start:
    /// the result is the very state the match had then (snapshots of Box2D worlds cannot
    /// be copied, but a deterministic re-run can). Commands after `tick` are dropped, so
    /// play continues from there as a new branch.
    void rewindTo(std::uint64_t tick);
    /// The same, re-simulating from `start` instead of from the start: a match of this
    /// session's level at a tick <= `tick` that got there through the same commands (a
    /// replay's restart point, game/replay_restarts.h).
    void rewindTo(std::uint64_t tick, std::unique_ptr<Match> start);
    /// Plays on from the current tick under other options: a replay taken over (the
    /// computer plays its cannons again unless `hotseat`; the branch is saved to
    /// `recordFile`). The recording so far is kept, and so is its checkpoint spacing.
    void continueAs(const SessionOptions& options);

  private:
    void saveAtTurnEnd();
    std::unique_ptr<Match> match_;
    SessionOptions options_;
    ComputerTurns cpu_;
    Replay replay_;
    std::size_t eventsSeen_ = 0;
};

} // namespace game
