// The level's framing ("home"): a camera that shows the whole level with the ground low
// and the sky above for the arcs, and keeps what the player aims at or fires from clear
// of the bands the HUD's boxes and the panels along the bottom stand in.
#pragma once

#include "game/match.h"
#include "ui/render/camera.h"
#include "ui/render/pixel_rect.h"

namespace ui {

/// How tall the bands at the bottom and the top of the screen are that the HUD's boxes
/// stand in, in design pixels (1280x720, design_canvas.h): the aim readout and the score,
/// each with its margin.
inline constexpr double kHudBottomBand = 104.0;
inline constexpr double kHudTopBand = 80.0;

/// How much of the screen's height, from the bottom, the boxes and panels along it cover
/// (a fraction, for the follow camera to frame the shot above it): the aim readout's band
/// and `panel` (the replay viewer's, in the same pixels as width and height) while it
/// stands on the bottom; moved up, it is left out (folded, the caller passes an empty rect).
double coveredBottom(const PixelRect& panel, double width, double height);

/// A camera that shows the level: its whole width, the ground near the bottom, and
/// every cannon, target and block inside. Under the lowest ground lies a band of soil,
/// 22 % of the height, or deeper where the window's panels cover the bottom higher
/// (`coveredBottom`, a fraction of the height: see coveredBottom()), so that nothing to
/// aim at or fire from stands under them; the highest of them stays under the top
/// `coveredTop` of the height.
Camera levelCamera(const game::Match& match, int width, int height, double coveredBottom = 0.0,
                   double coveredTop = 0.0);
/// levelCamera() in the part of the view left of its rightmost `coveredRight` (a fraction
/// of the width, where panels stand along the right edge): the same framing in a narrower
/// view, moved so its middle is the open part's.
Camera levelCameraLeftOf(const game::Match& match, int width, int height, double coveredRight,
                         double coveredBottom = 0.0, double coveredTop = 0.0);

} // namespace ui
