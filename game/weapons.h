// The arsenal: eight weapons whose difference is physics, each one row of one table
// (weapons.cpp). A row is data: the body (mass, diameter, drag coefficient, material),
// the blast, and the behaviour fields of game/ammo.h (fuse, bounce count, apex split,
// airburst height, tunnel, stick, restitution and friction overrides). The match reads
// the fields; no weapon has a code path of its own. docs/weapons.md gives each one's
// physics and formula.
#pragma once

#include "game/ammo.h"

#include <span>
#include <string>
#include <string_view>
#include <utility>

namespace game {

struct Weapon {
    const char* name;
    const char* summary; ///< one line for the weapon picker
    const char* physics; ///< the formula that makes it different, one line
    phys::ProjectilePreset body;
    double blastRadius;  ///< m
    double blastImpulse; ///< N s at the centre
    double craterRadius; ///< m
    Behaviour behaviour;
};

/// Every weapon, in the order the docs list them.
std::span<const Weapon> weapons();
const Weapon* weaponFromName(std::string_view name);
/// "cluster, bouncer, ..." for messages.
std::string weaponNameList();
/// The ammunition a weapon fires.
Ammo ammoOf(const Weapon& w);
/// True for a preset or a weapon name.
bool knownProjectile(std::string_view name);

/// The material a weapon's shell bounces with: the table's entry of the weapon's own
/// name, added when missing as a copy of its body's material with the weapon's
/// restitution and friction overrides.
phys::MaterialId weaponMaterial(phys::MaterialTable& table, const Ammo& ammo);

class Node;
/// One entry of a cannon's `projectiles`: a name (unlimited shots, count -1) or
/// {"name": NAME, "count": N} with N in 1..100 and NAME a preset or a weapon.
/// Throws LoadError naming the file and path.
std::pair<std::string, int> readProjectileEntry(const Node& entry);

} // namespace game
