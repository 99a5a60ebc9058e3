// The state a weapon's behaviour keeps while its shell flies: impacts counted, the
// split done, the fragments still flying, where it stuck, how far it has tunnelled.
#pragma once

#include "physics/particles.h"
#include "physics/vec2.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace game {

struct ShellFlight {
    double flown = 0.0;      ///< seconds since firing
    int impacts = 0;         ///< ticks on which a new impact began
    bool touching = false;   ///< an impact (closing faster than 1 m/s) on the last tick
    bool inContact = false;  ///< touching anything on the last tick
    phys::Vec2 lastVelocity; ///< the shell's velocity on the previous tick, m/s
    bool split = false;      ///< the cluster has split
    double apexMass = 0.0;   ///< the shell's mass when it split, kg
    phys::Vec2 apexVelocity; ///< its velocity when it split, m/s
    std::vector<phys::ParticleId> fragments; ///< fragments flying besides the shell
    std::optional<std::uint64_t> stuckTick;  ///< Stick: the tick it stuck
    bool digging = false;                    ///< Dig: tunnelling
    phys::Vec2 digOrigin, digDirection;      ///< where the tunnel starts, unit direction
    double digSpeed = 0.0;                   ///< m/s along the tunnel
    double dug = 0.0;                        ///< m tunnelled so far
    double carvedTo = 0.0;                   ///< m of tunnel already carved
    // The landing (game/landing.h): how it left the muzzle, where it was a tick ago,
    // and whether its first contact has been reported.
    phys::Vec2 launchPosition, launchVelocity;
    phys::Vec2 lastPosition;
    phys::Vec2 preLandingPosition, preLandingVelocity; ///< the tick before the first contact
    bool landed = false;
};

} // namespace game
