// What the weapon picker and the HUD say about a cannon's projectiles: each entry's
// label with the shots left, and a description of its physics (game-level text, so the
// window only draws it and tests read it).
#pragma once

#include "game/match.h"

#include <string>

namespace game {

/// "2  grenade  (1 left)" or "1  cannonball" (unlimited): entry i of the cannon.
std::string projectileLabel(const CannonState& c, std::size_t i);
/// One line on what it is and does, then one line with its formula (weapons), or its
/// mass, diameter and drag coefficient (balls).
std::string projectileDescription(const std::string& name);

} // namespace game
