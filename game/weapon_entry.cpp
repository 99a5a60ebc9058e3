// A level's `cannons[].projectiles` entry: "name" or {"name": NAME, "count": N}.
#include "game/files/json_reader.h"
#include "game/weapons.h"

namespace game {

std::pair<std::string, int> readProjectileEntry(const Node& entry) {
    if (!entry.isObject()) return {entry.string(64), -1};
    const std::string name = entry.string("name");
    if (!knownProjectile(name))
        entry.at("name").fail("expected a weapon (" + weaponNameList() +
                              ") or a projectile preset (" + phys::projectileNameList() +
                              "), got \"" + name + "\"");
    const int count = static_cast<int>(entry.integer("count", 1, 1, 100));
    entry.finish();
    return {name, count};
}

} // namespace game
