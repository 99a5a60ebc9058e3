// What scrubbing a recorded game costs: the viewer seeks back by re-simulating, from the
// start (the whole replay: the slowest seek without restart points) or from the nearest
// restart point (game/replay_restarts.h: at most one spacing of ticks). Timed per replay
// file, side by side, with the load average beside each figure.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace game::bench {

struct ReplayTiming {
    std::string file;        ///< the replay's file name (no folder)
    std::uint64_t ticks = 0; ///< its length
    double worstSeekMs = 0;  ///< from its end back to its last tick from the start, median
    double restartSeekMs = 0; ///< slowest seek back to a tick just before a restart point
    double buildMs = 0;       ///< building every restart point once
    std::size_t restartPoints = 0;
    double load = NAN;       ///< 1-minute load average when measured
    double msPerTick() const { return ticks ? worstSeekMs / static_cast<double>(ticks) : 0.0; }
};

/// Times every `*.replay.json` in `folder` (sorted by name; at most `limit` of them):
/// each one is played to its end, then sought back to its last tick `repeats` times.
/// Throws LoadError for a replay (or its level) that cannot be read.
std::vector<ReplayTiming> timeReplays(const std::string& folder, int repeats = 3,
                                      std::size_t limit = SIZE_MAX);

} // namespace game::bench
