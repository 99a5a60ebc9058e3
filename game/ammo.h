// What a cannon fires: a projectile preset (material, mass, diameter, drag coefficient)
// and whether it is an explosive shell. Shells burst on their first impact, carving a
// crater and pushing everything near by a blast; solid balls bounce and roll. The
// weapons (game/weapons.h) add behaviours: a fuse, a bounce count, a split at the apex,
// an airburst height, a tunnel, a sticky charge.
#pragma once

#include "physics/projectiles.h"

#include <optional>
#include <string>

namespace game {

/// What a projectile does when it touches something.
enum class OnImpact {
    Bounce, ///< bounces by its restitution (balls; fused or counted weapons)
    Burst,  ///< bursts at once (shells)
    Dig,    ///< tunnels `digLength` along its incoming path, then bursts
    Stick,  ///< stops dead where it touched (e = 0, no slip), bursts `stickSeconds` later
};

/// A weapon's behaviour as data: every field off (0) leaves the plain shell or ball.
struct Behaviour {
    OnImpact onImpact = OnImpact::Bounce;
    double fuseSeconds = 0.0;       ///< > 0: bursts this long after firing, wherever it is
    int burstAfterBounces = 0;      ///< > 0: bursts on its Nth impact
    bool burstAtRest = false;       ///< bursts when it comes to rest (a roller)
    double airburstHeight = 0.0;    ///< > 0: bursts descending at this height above ground, m
    int apexFragments = 0;          ///< > 0 (even): splits at its apex into this many
    double fragmentSpreadMps = 0.0; ///< fragments' speed relative to the centre of mass, m/s
    double digLength = 0.0;         ///< Dig: tunnel length along the incoming direction, m
    double digRadius = 0.0;         ///< Dig: radius of the tunnel, m
    double stickSeconds = 0.0;      ///< Stick: delay from sticking to bursting, s
    double restitution = -1.0;      ///< >= 0: e against the reference floor (own material)
    double friction = -1.0;         ///< >= 0: dynamic friction mu_d (own material)
};

struct Ammo {
    phys::ProjectilePreset preset;
    double blastRadius = 0.0;  ///< m; 0 = not explosive
    double blastImpulse = 0.0; ///< N s at the centre (linear falloff)
    double craterRadius = 0.0; ///< m
    Behaviour behaviour;
    bool weapon = false; ///< from the weapons table (its own material, its behaviour)
};

/// A projectile preset or a weapon by name.
std::optional<Ammo> ammoFromName(const std::string& name);

} // namespace game
