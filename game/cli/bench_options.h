// What the sub-commands of `artillery bench` share (game/cli/bench.cpp and
// bench_scaling.cpp): the run's size, its progress line, and its outputs, which are
// checked before anything is measured and written whole or not at all.
#pragma once

#include "game/cli/args.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <iosfwd>
#include <string>

namespace game::cli {
struct BenchPlots;
}

namespace game::cli::benchcli {

enum class Size { Quick, Default, Full };

/// --full, --quick or neither.
Size sizeOption(const Args& args);

/// Progress on stderr ("\r" so it updates in place on a terminal).
std::function<void(int, int)> progressLine(const std::string& what);

/// The file of the required option --`name`, refused now when it cannot be written.
std::string outputPath(const Args& args, const std::string& name);

/// Writes `text` to `path` atomically; a failure is the work's (WorkError, exit 3).
void writeText(const std::string& path, const std::string& text);

/// A number for JSON: null when not finite.
inline nlohmann::json jnum(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

/// The exit code once the chart was (or was not) drawn: a chart that could not be
/// written is said on stderr and is the work's failure (exit 3).
int chartOutcome(const std::string& png, const std::string& plotError);

/// " and PNG" when the chart was drawn: the end of the "wrote CSV" line.
std::string andChart(const std::string& png, const std::string& plotError);

/// `artillery bench scaling` (game/cli/bench_scaling.cpp).
int runScalingCommand(const Args& args, std::ostream& out, const BenchPlots* plots);

} // namespace game::cli::benchcli
