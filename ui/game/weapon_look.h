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

/// The projectile picker of the match panel: one entry per projectile with the shots
/// left, a tooltip with what it does and its formula; spent weapons are greyed out.
/// Returns the entry chosen, if a different one was.
std::optional<std::size_t> projectilePicker(const game::CannonState& c);

} // namespace ui
