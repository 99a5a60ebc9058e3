// Projectile presets: a material paired with the mass, diameter and drag coefficient
// of a real ball, so a shot and its bounce both behave like the thing it is named for.
#pragma once

#include "physics/materials.h"
#include "physics/particles.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace phys {

struct ProjectilePreset {
    const char* name;
    MaterialId material;
    double mass;            ///< kg
    double diameter;        ///< m
    double dragCoefficient; ///< Cd of the sphere at the speeds the game fires it
};

/// Every preset (sources in projectiles.cpp).
std::span<const ProjectilePreset> projectilePresets();
std::optional<ProjectilePreset> projectileFromName(std::string_view name);
/// "cannonball, golf-ball, ..." for messages and --help.
std::string projectileNameList();
/// A particle definition for the preset at `position` with `velocity` (radius = d/2).
ParticleDef particleDef(const ProjectilePreset& p, Vec2 position = {}, Vec2 velocity = {});

} // namespace phys
