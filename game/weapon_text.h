// What the projectile bar, the picker and the HUD say about a cannon's projectiles: each
// entry's label with its key and the shots left, a description of its physics, the one
// line shown the first time a weapon appears, and the fixed keys of the arsenal (game-level
// text, so the window only draws it and tests read it).
//
// Keys: 1 to 8 name the eight weapons by identity, in the arsenal's order (cluster,
// bouncer, roller, grenade, mortar, airburst, digger, sticky), whatever a level's list
// holds; the balls have no number (the window cycles through them). A key or a `select`
// for a weapon the level lacks is refused with "this level has no cluster".
#pragma once

#include "game/match.h"

#include <optional>
#include <string>

namespace game {

/// The weapon on number key `key` (1..8), or nullopt for any other key.
std::optional<std::string> weaponOnKey(int key);
/// The number key of a weapon (1..8), or nullopt for a ball.
std::optional<int> keyOfProjectile(const std::string& name);

/// "4  grenade  (1 left)" (a weapon: its key, its name, the shots left when counted) or
/// "cannonball" (a ball: no key): entry i of the cannon.
std::string projectileLabel(const CannonState& c, std::size_t i);
/// One line on what it is and does, then one line with its formula (weapons), or its
/// mass, diameter and drag coefficient (balls).
std::string projectileDescription(const std::string& name);
/// The one line that introduces a weapon the first time a player meets it:
/// "New: the grenade bounces (e = 0.5) until its 3 s fuse burns down, then bursts";
/// empty for a ball.
std::string weaponIntroduction(const std::string& name);

} // namespace game
