#include "game/ammo.h"

#include "game/weapons.h"

namespace game {

std::optional<Ammo> ammoFromName(const std::string& name) {
    if (const Weapon* w = weaponFromName(name)) return ammoOf(*w);
    auto preset = phys::projectileFromName(name);
    if (!preset) return std::nullopt;
    Ammo a;
    a.preset = *preset;
    if (name == "cannonball") {
        // A shell with a bursting charge: a 3 m blast, a 2 m crater.
        a.blastRadius = 3.0;
        a.blastImpulse = 150.0;
        a.craterRadius = 2.0;
        a.behaviour.onImpact = OnImpact::Burst;
    }
    return a;
}

} // namespace game
