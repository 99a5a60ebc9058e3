#include "physics/collision/collision_def.h"

#include <cmath>

namespace phys {

std::string validate(const CollisionDef& d) {
    if (!(d.gridCellSize >= 0.0) || !std::isfinite(d.gridCellSize))
        return "grid cell size must be >= 0 m (0: automatic)";
    if (d.bisectionHalvings < 0 || d.bisectionHalvings > 60)
        return "collision bisection halvings must be in 0..60";
    if (!(d.toiTolerance > 0.0) || !(d.toiTolerance <= 1e-3))
        return "collision time-of-impact tolerance must be in (0, 1e-3] m";
    if (d.maxAdvanceIterations < 1 || d.maxAdvanceIterations > 10000)
        return "collision advance iterations must be in 1..10000";
    if (d.maxPasses < 1 || d.maxPasses > 1000) return "collision passes must be in 1..1000";
    if (d.relaxVelocitySweeps < 1 || d.relaxVelocitySweeps > 1000)
        return "contact solver velocity sweeps must be in 1..1000";
    if (d.relaxPositionSweeps < 1 || d.relaxPositionSweeps > 1000)
        return "contact solver position sweeps must be in 1..1000";
    if (!(d.restingSpeed >= 0.0) || !std::isfinite(d.restingSpeed))
        return "resting speed must be >= 0 m/s";
    if (!(d.sleepSpeed >= 0.0) || !std::isfinite(d.sleepSpeed))
        return "sleep speed must be >= 0 m/s";
    if (!(d.sleepTime >= 0.0) || !std::isfinite(d.sleepTime)) return "sleep time must be >= 0 s";
    if (!(d.penaltyHertz > 0.0) || !std::isfinite(d.penaltyHertz))
        return "penalty stiffness must be > 0 Hz";
    if (d.constraintIterations < 1 || d.constraintIterations > 10000)
        return "constraint iterations must be in 1..10000";
    if (!(d.constraintTolerance >= 0.0) || !(d.constraintTolerance < 1.0))
        return "constraint tolerance must be in [0, 1)";
    return {};
}

const char* broadPhaseName(BroadPhase b) {
    switch (b) {
    case BroadPhase::Grid:
        return "grid";
    case BroadPhase::SortAndSweep:
        return "sort-and-sweep";
    case BroadPhase::AllPairs:
        return "all-pairs";
    }
    return "?";
}

const char* contactModelName(ContactModel m) {
    switch (m) {
    case ContactModel::Impulse:
        return "impulse";
    case ContactModel::Penalty:
        return "penalty";
    case ContactModel::None:
        return "none";
    }
    return "?";
}

} // namespace phys
