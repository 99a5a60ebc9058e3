// The guard that runs after every tick: NaN, infinity and runaway speed are found, the
// offending particles are removed (with the springs and rods that held them), and the
// report names the setting that caused it, so the game carries on and says why
// ("explicit-euler with springs of 5000 N/m is unstable at dt = 8.3 ms ...").
// Nothing non-finite is left for the renderer.
#pragma once

#include "physics/stability.h"
#include "physics/world.h"

#include <string>

namespace phys {

struct GuardDef {
    double maxSpeed = 5000.0;      ///< m/s: faster than any shell the game fires (railgun 1000)
    double maxCoordinate = 1e6;    ///< m: farther than any level reaches
};

struct GuardReport {
    int nonFinite = 0;   ///< particles whose position or velocity was NaN or infinite
    int runaway = 0;     ///< finite but faster than maxSpeed or beyond maxCoordinate
    int removed = 0;     ///< particles removed
    int springsCut = 0;  ///< springs and constraints removed with them
    std::string cause;   ///< which setting caused it and what to change ("" when all is well)
    bool tripped() const { return removed > 0; }
};

/// Checks every particle; removes offenders and explains. O(particles + springs).
GuardReport guardWorld(World& world, const GuardDef& def = {});

} // namespace phys
