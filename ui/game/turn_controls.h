// The keys and the mouse of a player's turn at the cannon, as commands: one mapping for
// every window that plays a turn (the game's, the network duel's), so a duel across the
// network plays as one at home.
//
//   drag from anywhere   aim: direction = angle, length = power (AimInput), drawn as a
//                        rubber band; a click leaves the aim alone
//   arrow keys           angle and power: a tap steps 0.5 deg or 0.5 m/s (Shift 0.1),
//                        held they repeat, faster the longer; settle on release
//   Space                hold to charge from zero, release to fire; a tap fires at the
//                        power set
//   Enter, F             fire at the aim set
//   E                    end the turn
//   1-8                  a weapon by its own number (docs/weapons.md's order: cluster,
//                        bouncer, roller, grenade, mortar, airburst, digger, sticky);
//                        one the level lacks is refused with a message
//   Tab                  the next ball
//
// The gestures live in AimInput (no SDL); this is the SDL side of it.
#pragma once

#include "game/command.h"
#include "game/match.h"
#include "ui/game/aim_input.h"

#include <SDL.h>

#include <optional>
#include <vector>

namespace ui {

/// A turn key pressed in one's own turn: the commands it makes (none for Space, whose
/// release fires), or nullopt for a key that is not a turn key. A charge starts only
/// while no shell flies. A weapon key the level has no weapon for says so in `message`.
std::optional<std::vector<game::Command>> pressTurnKey(SDL_Keycode key, AimInput& aim,
                                                       const game::Match& m,
                                                       std::string* message = nullptr);

/// Space released after a charge: aim, power, fire (nothing without a charge).
std::vector<game::Command> releaseTurnKey(SDL_Keycode key, AimInput& aim, const game::Match& m);

/// The left mouse button aims by dragging, in one's own turn while no shell flies: a
/// press starts, motion follows, release commits (the commands). `pivotPx` is the
/// cannon's pivot in framebuffer pixels, `pixelsPerPoint` what a window point is in them
/// (more than 1 on a high-DPI screen). False for an event that is not the drag's.
bool dragToAim(const SDL_Event& e, AimInput& aim, const game::Match& m, bool myTurn,
               phys::Vec2 pivotPx, phys::Vec2 pixelsPerPoint, std::vector<game::Command>& out);

/// The arrow keys held now as angle and power axes, -1..1 (a fifth with Shift held).
struct HeldAxes {
    double angle = 0.0, power = 0.0; ///< the arrow keys: they repeat after a delay
    double padPower = 0.0;           ///< a controller's triggers: at once, analog
};
HeldAxes heldArrowKeys();

/// Once a frame: held `axes` move the aim; when they are let go (and no drag or charge
/// is on) the aim settles as commands; a charge rises. Outside one's own turn, or while
/// a shell flies, a charge is dropped. Then the aim shows the cannon's unless edited.
std::vector<game::Command> holdToAim(HeldAxes axes, double dt, AimInput& aim,
                                     const game::Match& m, bool myTurn);

} // namespace ui
