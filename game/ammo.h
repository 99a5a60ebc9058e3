// What a cannon fires: a projectile preset (material, mass, diameter, drag coefficient)
// and whether it is an explosive shell. Shells burst on their first impact, carving a
// crater and pushing everything near by a blast; solid balls bounce and roll.
#pragma once

#include "physics/projectiles.h"

#include <optional>
#include <string>

namespace game {

struct Ammo {
    phys::ProjectilePreset preset;
    double blastRadius = 0.0;  ///< m; 0 = not explosive
    double blastImpulse = 0.0; ///< N s at the centre (linear falloff)
    double craterRadius = 0.0; ///< m
};

std::optional<Ammo> ammoFromName(const std::string& name);

} // namespace game
