#include "game/weapon_text.h"

#include "game/weapons.h"

#include <cstdio>

namespace game {

std::string projectileLabel(const CannonState& c, std::size_t i) {
    std::string out = std::to_string(i + 1) + "  " + c.def.projectiles[i];
    if (i < c.ammoLeft.size() && c.ammoLeft[i] >= 0)
        out += "  (" + (c.ammoLeft[i] == 0 ? std::string("none") : std::to_string(c.ammoLeft[i])) +
               " left)";
    return out;
}

std::string projectileDescription(const std::string& name) {
    if (const Weapon* w = weaponFromName(name)) return std::string(w->summary) + "\n" + w->physics;
    const auto p = phys::projectileFromName(name);
    if (!p) return name + ": not a projectile this game knows";
    char line[160];
    std::snprintf(line, sizeof line, "%s: a ball, %.3g kg, %.0f mm, Cd %.2f; %s", p->name, p->mass,
                  p->diameter * 1000.0, p->dragCoefficient,
                  name == "cannonball" ? "bursts on impact"
                                       : "bounces by its material's restitution");
    return line;
}

} // namespace game
