// Work-precision: for each integrator and a sweep of dt, how wrong the scene ends up
// (error against its reference) and what it cost (CPU time per simulated second,
// median of repeats; and force evaluations, which do not depend on the machine).
#pragma once

#include "game/bench/accuracy_scenes.h"

#include <functional>
#include <string>
#include <vector>

namespace game::bench {

struct WorkPrecisionPoint {
    AccuracyScene scene;
    phys::Integrator integrator;
    double dt = 0.0;                 ///< s
    long steps = 0;
    double error = 0.0;              ///< m; infinity when the run blew up
    double cpuSecondsPerSimSecond = 0.0; ///< median over repeats
    double evaluationsPerSimSecond = 0.0; ///< force evaluations (per the integrator's table)
};

struct WorkPrecisionDef {
    AccuracyScene scene = AccuracyScene::ProjectileDrag;
    std::vector<phys::Integrator> integrators; ///< empty: all of them
    double largestDt = 0.1;   ///< s, first dt of the sweep
    int halvings = 8;         ///< dt, dt/2, ... dt/2^halvings
    int repeats = 3;          ///< timing repeats (the median is kept)
};

/// Runs the sweep. `progress` (may be empty) is told "k of n" as it goes.
std::vector<WorkPrecisionPoint> runWorkPrecision(
    const WorkPrecisionDef& def, const std::function<void(int, int)>& progress = {});

/// Least-squares slope of log(y) against log(x) over the pairs whose y is finite and
/// above `floor` (and x positive); NaN with fewer than two.
double logLogSlope(const std::vector<double>& x, const std::vector<double>& y, double floor);

/// Least-squares slope of log(error) against log(dt) over the points of one integrator
/// whose error is finite and above the rounding floor `floor` (m). The order of accuracy.
double convergenceSlope(const std::vector<WorkPrecisionPoint>& points, phys::Integrator m,
                        double floor = 1e-11);

/// The cheapest (least CPU time per simulated second) point whose error is at most
/// `tolerance`, or nullptr when none is accurate enough.
const WorkPrecisionPoint* cheapestWithin(const std::vector<WorkPrecisionPoint>& points,
                                         double tolerance);

/// CSV with a header row: scene,integrator,dt_s,steps,error_m,cpu_s_per_sim_s,evals_per_sim_s.
std::string toCsv(const std::vector<WorkPrecisionPoint>& points);

} // namespace game::bench
