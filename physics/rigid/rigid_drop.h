// The rigid drop experiment: a Box2D circle dropped on static terrain, reporting each
// bounce's apex, so `artillery drop --model rigid` can compare Box2D with the exact
// e^(2k) H of the particle layer. Shared by the verb, the tests and README.
#pragma once

#include "physics/rigid/rigid_types.h"

#include <vector>

namespace phys {

/// Settings of one rigid drop, with defaults and units.
struct RigidDropDef {
    /// Height of the ball's bottom above the floor at release, m, > 0. The floor is the
    /// surface a Box2D body rests on: the terrain line plus the part of Box2D's contact
    /// skin that the position solver leaves (b2_polygonRadius - b2_linearSlop = 5 mm).
    double height = 1.0;
    double restitution = 0.8;         ///< ball's coefficient of restitution, 0..1 (floor: 0)
    int bounces = 3;                  ///< apexes to report, >= 1
    double tickSeconds = 1.0 / 120.0; ///< fixed tick, s
    int substeps = 1;                 ///< Box2D steps per tick
    double radius = 0.0625;           ///< ball radius, m (a power of two: exact in float)
    double gravity = 9.81;            ///< m/s^2, downwards
    double restitutionThreshold = RigidWorldDef{}.restitutionThreshold; ///< m/s
    double maxSeconds = 60.0; ///< give up after this much simulated time, s
};

/// Apex heights (m, above the floor as defined above) of the first bounces, highest point
/// sampled at each tick (sampling error <= g tick^2 / 8 = 0.09 mm at 1/120 s). Fewer than
/// asked when the ball stops bouncing first: bounces slower than the restitution threshold
/// are fully inelastic in Box2D.
std::vector<double> rigidDropApexes(const RigidDropDef& def);

/// Same with the other settings at their defaults.
std::vector<double> rigidDropApexes(double height, double restitution, int bounces, double dt,
                                    int substeps);

} // namespace phys
