#include "game/ammo.h"

namespace game {

std::optional<Ammo> ammoFromName(const std::string& name) {
    auto preset = phys::projectileFromName(name);
    if (!preset) return std::nullopt;
    Ammo a;
    a.preset = *preset;
    if (name == "cannonball") {
        // A shell with a bursting charge: a 3 m blast, a 2 m crater.
        a.blastRadius = 3.0;
        a.blastImpulse = 150.0;
        a.craterRadius = 2.0;
    }
    return a;
}

} // namespace game
