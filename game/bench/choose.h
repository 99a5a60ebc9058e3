// "Accurate enough, fastest": from measured work-precision data, the integrator and time
// step with the least CPU cost whose error on a scene stays within a tolerance. The
// command line (`artillery bench choose`) and the physics panel call the same function.
#pragma once

#include "game/bench/work_precision.h"

#include <optional>

namespace game::bench {

struct MethodChoice {
    AccuracyScene scene = AccuracyScene::ProjectileDrag;
    double tolerance = 0.0;              ///< m, what was asked for
    phys::Integrator integrator = phys::Integrator::SymplecticEuler;
    double dt = 0.0;                     ///< s, the step that meets the tolerance
    double error = 0.0;                  ///< m, measured at that step
    double cpuSecondsPerSimSecond = 0.0; ///< measured cost
    /// Sub-steps per game tick that give a step no longer than dt (for WorldDef::substeps).
    int substepsPerTick(double tickSeconds) const;
};

/// A sweep small enough to run when the user asks (about a second on this machine):
/// every integrator, dt from `largestDt` down by 7 halvings, 3 timing repeats.
WorkPrecisionDef choiceSweep(AccuracyScene scene);

/// Measures `sweep` (or takes already measured `points`) and returns the cheapest
/// setting within `tolerance`, or nothing when no point of the sweep is accurate enough.
std::optional<MethodChoice> chooseCheapest(AccuracyScene scene, double tolerance,
                                           const std::vector<WorkPrecisionPoint>& points);
std::optional<MethodChoice> chooseCheapest(AccuracyScene scene, double tolerance);

} // namespace game::bench
