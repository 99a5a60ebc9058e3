// Headless runs: a level played from a replay or a commands script with no window, for
// tests, replays and charts. Rendering is optional and lives in ui/: the runner hands
// each K-th tick to a FrameSink.
#pragma once

#include "game/match.h"
#include "game/replay.h"
#include "game/session.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace game {

/// Receives frames to draw (implemented by ui/ with the same drawing code as the window).
class FrameSink {
  public:
    virtual ~FrameSink() = default;
    /// Called after tick `match.tick()` for every K-th tick.
    virtual void frame(const Match& match) = 0;
};

struct HeadlessOptions {
    std::vector<Command> commands;     ///< applied at their ticks
    std::optional<std::uint64_t> ticks;///< how long; default: until the match is over or
                                       ///< 60 s after the last command or the computer's
                                       ///< last shot
    SessionOptions session;            ///< difficulty, cpu seed, recording
    FrameSink* sink = nullptr;
    std::uint64_t every = 1;           ///< frame every K ticks
    /// Views that want every tick besides the frames (the sound track); they only read.
    std::vector<FrameSink*> listeners;
};

struct HeadlessSummary {
    std::uint64_t ticks = 0;
    std::uint64_t finalHash = 0;
    int score = 0;
    int shots = 0;
    bool over = false;
    int winner = -1;
    std::vector<GameEvent> events;
    double simMs = 0.0;    ///< wall time spent simulating
    double renderMs = 0.0; ///< wall time spent in the frame sink
    Replay recording;
};


HeadlessSummary runHeadless(const Level& level, const HeadlessOptions& options);

} // namespace game
