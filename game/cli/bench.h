// `artillery bench`: speed against accuracy. Sub-commands work-precision, stability,
// scaling (each writes CSV, a PNG chart and prints its key figures) and choose (the
// cheapest integrator and dt within a tolerance). The measuring lives here; the PNG is
// drawn by ui/ through BenchPlots (game/ knows no GL).
#pragma once

#include "game/bench/scaling.h"
#include "game/bench/stability.h"
#include "game/bench/work_precision.h"
#include "game/cli/args.h"

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace game::cli {

/// Everything `bench stability` measures.
struct StabilityReport {
    std::vector<bench::StabilityRow> rows;
    std::vector<bench::GrowthCurve> curves;
};

/// Draws the bench's PNGs; each returns "" on success, else why not.
struct BenchPlots {
    std::function<std::string(const std::vector<bench::WorkPrecisionPoint>&, const std::string&)>
        workPrecision;
    std::function<std::string(const StabilityReport&, const std::string&)> stability;
    std::function<std::string(const bench::ScalingReport&, const std::string&)> scaling;
};

/// The full --help text of `artillery bench`.
extern const char* const kBenchUsage;
/// Options of `artillery bench` that take no value.
std::set<std::string> benchFlags();

/// Runs `artillery bench SUBCOMMAND ...`; `plots` may be null (then --png is refused).
int runBench(const Args& args, std::ostream& out, const BenchPlots* plots);

} // namespace game::cli
