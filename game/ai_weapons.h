// Which weapon the computer fires. It weighs the weapons of the arsenal its cannon
// still has against what it aims at, by their physics: against a cannon in a duel the
// widest blast (a burst within kCannonRadius + blast / 2 hits it); against a structure
// the most momentum delivered, m v plus the blast impulse; against a target disc,
// which only a passing shell scores, the least drag, k = rho Cd A / (2 m). Plain
// balls and the cannonball are left to the player's pick (the computer keeps them),
// unless what is selected has run out.
#pragma once

#include "game/match.h"

#include <optional>
#include <string>

namespace game {

/// The weapon to select before aiming at `target`, or nullopt to keep the selection.
std::optional<std::string> chooseWeapon(const Match& match, phys::Vec2 target);

} // namespace game
