// The drop experiment of Claypool's "Game Physics" lecture: a ball dropped from rest at
// height H onto a floor
// bounces to e^2 H, then e^4 H, ..., e^(2k) H (e = sqrt(h/H) is how e was measured).
// The `drop` verb and the drop tests run it through the whole world step, so it tests
// detection, time of impact and response together, with any integrator and step.
#pragma once

#include "physics/collision/collision_def.h"
#include "physics/integrators.h"
#include "physics/materials.h"

#include <optional>
#include <vector>

namespace phys {

struct DropDef {
    double height = 1.0;                   ///< H, m: the ball's lowest point above the floor, > 0
    MaterialId material = material::kGolf; ///< the ball's material (against "floor")
    std::optional<double>
        restitution; ///< if set, a pair entry ball-floor with this e overrides the table
    int bounces = 3; ///< apexes to report, >= 1
    Integrator integrator = Integrator::VelocityVerlet;
    double dt = 1.0 / 120.0; ///< s, the world's tick (one sub-step)
    double gravity = 9.81;   ///< m/s^2, > 0
    double radius = 0.02;    ///< m (the apex does not depend on it)
    double mass = 0.05;      ///< kg (nor on this)
    CollisionDef collision;  ///< contact settings (continuous detection etc.)
    double maxTime = 600.0;  ///< s of simulated time before giving up
};

struct DropBounce {
    double apex = 0.0;          ///< m, the ball's lowest point at the top of the bounce
    double expected = 0.0;      ///< e^(2k) H, m
    double relativeError = 0.0; ///< (apex - expected) / expected; apex - expected if expected is 0
};

struct DropResult {
    double restitution = 0.0; ///< the e the pair ball-floor resolved to
    std::vector<DropBounce> bounces;
    bool cameToRest = false; ///< a contact became resting before all bounces were seen
    /// m, the deepest the ball went into the floor at a tick's end: ~1e-9 with impulses;
    /// the penalty model sinks by about g / w^2 and more on impact.
    double maxPenetration = 0.0;
    long long steps = 0; ///< world ticks simulated
};

/// Runs the drop. Apexes are the top of the path the integrator followed within the
/// tick (the parabola through the tick's start and end, time_of_impact.h), not just the
/// sampled positions, so the sampling of dt does not hide or add error. Once the ball
/// rests on the floor every further apex is 0.
DropResult simulateDrop(const DropDef& def);

} // namespace phys
