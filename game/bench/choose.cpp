#include "game/bench/choose.h"

#include <algorithm>
#include <cmath>

namespace game::bench {

int MethodChoice::substepsPerTick(double tickSeconds) const {
    if (!(dt > 0.0) || !(tickSeconds > 0.0)) return 1;
    // A hair of slack so dt = tick / 4 gives 4, not 5, after rounding.
    return std::max(1, static_cast<int>(std::ceil(tickSeconds / dt - 1e-9)));
}

WorkPrecisionDef choiceSweep(AccuracyScene scene) {
    WorkPrecisionDef d;
    d.scene = scene;
    d.largestDt = 0.05;
    d.halvings = 7;
    d.repeats = 3;
    return d;
}

std::optional<MethodChoice> chooseCheapest(AccuracyScene scene, double tolerance,
                                           const std::vector<WorkPrecisionPoint>& points) {
    std::vector<WorkPrecisionPoint> ofScene;
    std::copy_if(points.begin(), points.end(), std::back_inserter(ofScene),
                 [&](const WorkPrecisionPoint& p) { return p.scene == scene; });
    const WorkPrecisionPoint* best = cheapestWithin(ofScene, tolerance);
    if (!best) return std::nullopt;
    MethodChoice c;
    c.scene = scene;
    c.tolerance = tolerance;
    c.integrator = best->integrator;
    c.dt = best->dt;
    c.error = best->error;
    c.cpuSecondsPerSimSecond = best->cpuSecondsPerSimSecond;
    return c;
}

std::optional<MethodChoice> chooseCheapest(AccuracyScene scene, double tolerance) {
    return chooseCheapest(scene, tolerance, runWorkPrecision(choiceSweep(scene)));
}

} // namespace game::bench
