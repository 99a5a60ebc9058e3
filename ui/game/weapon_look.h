// How each weapon looks in flight and in the picker: a colour and a mark of its own
// (the bouncer's rubber ring, the grenade's fuse burning down, the mortar's fins, the
// digger's tip, ...), so a player tells them apart at a glance. Reads the match only.
#pragma once

#include "game/match.h"
#include "ui/render/renderer2d.h"

#include <optional>
#include <string>

namespace ui {

/// Draws the shell in flight (and a cluster's fragments) with its weapon's look, over
/// the plain shell; nothing for balls and the cannonball. `radius` is the drawn radius.
void drawWeaponShell(Renderer2D& r, const game::Match& m, double radius);

/// The HUD's line under the selected weapon: what it does (its picker summary).
std::string weaponHudLine(const game::Ammo& ammo);

/// The projectile bar: an icon a projectile of the cannon, with its key (a weapon's fixed
/// number, 1 .. 8 as docs/weapons.md lists them; Tab for the balls) and its shots left, a
/// tooltip with what it does and its formula; spent ones are greyed out. Returns the one
/// clicked, if a different one was.
std::optional<std::size_t> projectileBar(const game::CannonState& c);

/// The cannon's projectile for weapon key `number` (1 .. 8), whatever the level's order;
/// none, and why in `why`, when the level has no such weapon.
std::optional<std::size_t> weaponByKey(const game::CannonState& c, int number, std::string& why);
/// Tab: the cannon's next ball after the one chosen (the next projectile where it has no
/// balls), skipping the spent ones; none when there is no other.
std::optional<std::size_t> nextBall(const game::CannonState& c);

} // namespace ui
