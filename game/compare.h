// Compare: the same shot fired with every integrator at once,
// each path against the reference, with its error where it comes back down to the
// launch height.
//
// Reference: with gravity alone (wind without drag included) the closed form
// p0 + v0 t + g t^2/2 (exact at any dt); with drag or water, RK4 at 1/16 of the tick
// (order 4, so its own error is 16^4 = 65536 times below RK4 at the tick). Every path
// flies through the level's forces but past its blocks and targets, and lands where it
// first goes down through the level's terrain as it is now (craters included), or, for a
// clean comparison on a level line, where it comes back down to the launch height.
#pragma once

#include "game/match.h"
#include "physics/integrators.h"
#include "physics/vec2.h"

#include <string>
#include <vector>

namespace game {

/// What a path's landing error is measured against.
enum class LandingReference {
    ClosedForm, ///< exact under uniform gravity: p0 + v0 t + g t^2/2
    FineRK4,    ///< RK4 at tick / CompareDef::referenceRefinement (drag or water act)
};
const char* landingReferenceName(LandingReference r);

/// Where a path lands.
enum class LandingSurface {
    Terrain,      ///< the level's ground, as the shot would hit it
    LaunchHeight, ///< the horizontal line through the muzzle
};

struct CompareDef {
    double tickSeconds = 0.0;     ///< s; 0 = the match's tick
    int referenceRefinement = 16; ///< the fine RK4 reference runs at tick / this, >= 1
    double maxSeconds = kMaxFlightSeconds; ///< a path not down by then stops, s
    LandingSurface surface = LandingSurface::Terrain;
};

struct IntegratorPath {
    phys::Integrator integrator = phys::Integrator::RK4;
    std::string name;            ///< "rk4", ..., or "closed-form" / "rk4 (dt/16)" for the reference
    bool isReference = false;    ///< the path the others are measured against
    std::vector<phys::Vec2> points; ///< the shell at each tick from the muzzle, m
    bool landed = false;         ///< came down to the landing surface within maxSeconds
    phys::Vec2 landing;          ///< where it first went down through the surface, m
    double flightTime = 0.0;     ///< s, to the landing
    double landingError = 0.0;   ///< |landing - reference landing|, m (0 for the reference)
    long steps = 0;              ///< ticks flown, to the landing (flown paths)
    LandingReference reference = LandingReference::ClosedForm;
};

/// The shell the compare fires: the current cannon's selected projectile, from the muzzle
/// at (angleDeg, speedMps).
phys::ParticleDef compareShell(const Match& match, double angleDeg, double speedMps);

/// `shell` flown with `integrator` at `tickSeconds` through the match's forces, past its
/// blocks and targets, to where it goes down through def.surface (within def.maxSeconds).
/// The landing inside the last tick is on the cubic Hermite interpolant of the states
/// either side of it. `keepPoints` false keeps only the muzzle and the landing.
IntegratorPath flyPath(const Match& match, phys::Integrator integrator, double tickSeconds,
                       const phys::ParticleDef& shell, const CompareDef& def,
                       bool keepPoints = true);

/// The path the others are measured against, sampled at `tickSeconds`: the closed form
/// where it is exact (Match::closedFormExact), else RK4 at tickSeconds /
/// def.referenceRefinement.
IntegratorPath referencePath(const Match& match, double tickSeconds,
                             const phys::ParticleDef& shell, const CompareDef& def);

/// Fires the current cannon's selected projectile from the muzzle at (angleDeg,
/// speedMps) once per integrator in phys::integrators(), under the match's forces,
/// tick and sub-steps (model policy Integrate, so every integrator really runs), and
/// appends the reference path last (isReference). An integrator whose states are exact
/// (RK4, velocity Verlet under gravity) lands exactly.
std::vector<IntegratorPath> compareIntegrators(const Match& match, double angleDeg,
                                               double speedMps, const CompareDef& def = {});

} // namespace game
