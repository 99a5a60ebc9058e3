#include "game/weapon_text.h"

#include "game/weapons.h"

#include <cstdio>

namespace game {

std::optional<std::string> weaponOnKey(int key) {
    const auto all = weapons();
    if (key < 1 || static_cast<std::size_t>(key) > all.size()) return std::nullopt;
    return std::string(all[static_cast<std::size_t>(key - 1)].name);
}

std::optional<int> keyOfProjectile(const std::string& name) {
    const auto all = weapons();
    for (std::size_t i = 0; i < all.size(); ++i)
        if (name == all[i].name) return static_cast<int>(i + 1);
    return std::nullopt;
}

std::string projectileLabel(const CannonState& c, std::size_t i) {
    const std::string& name = c.def.projectiles[i];
    const auto key = keyOfProjectile(name);
    std::string out = key ? std::to_string(*key) + "  " + name : name;
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

std::string weaponIntroduction(const std::string& name) {
    const Weapon* w = weaponFromName(name);
    if (!w) return "";
    // The summaries that open with an article describe the weapon ("a heavy finned
    // bomb: ..."); the others say what it does ("splits into 4 ...").
    const std::string summary = w->summary;
    const bool noun = summary.rfind("a ", 0) == 0;
    return "New: the " + name + (noun ? ", " : " ") + summary;
}

} // namespace game
