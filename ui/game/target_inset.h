// The target close-up: when the level's framing shows what the player aims at too small
// to read (a castle of 1 m blocks 140 m from the cannon is a few dozen pixels tall at
// 1280x720), a picture in the picture at the top right shows it at a readable scale,
// drawn by the same MatchView as the main view. It is a view only: it reads the match.
//
// What is aimed at: the targets not yet hit, the target blocks and blobs still standing,
// and in a duel the other players' cannons. The close-up hides itself once the main view
// shows them big enough (the camera following a shell closes in on them); discs alone,
// drawn larger than life where they are small, never need it.
#pragma once

#include "ui/game/match_view.h"
#include "ui/render/camera.h"
#include "ui/render/pixel_rect.h"
#include "ui/render/renderer2d.h"

#include <optional>

namespace game {
class Match;
}

namespace ui {
struct ScreenLayout;
}

namespace ui {

struct TargetInsetDef {
    double readablePx = 64.0;  ///< what is aimed at reads well from this tall on screen, px
    double smallestPx = 10.0;  ///< a target reads from this across, px
    double widthFraction = 0.3; ///< the close-up's width, fraction of the screen's
    double topPx = 84.0;        ///< below the top panels, px
    double rightPx = 12.0;      ///< from the right edge, px
    double marginM = 4.0;       ///< room around what is framed, m
};

/// The close-up: its camera (its own pixel size) and where it sits on the screen (its
/// top-left corner, px from the screen's top-left).
struct TargetInset {
    Camera camera;
    Vec2 cornerPx;
};

/// The world box of what the current player aims at; empty when nothing is left.
std::optional<std::pair<Vec2, Vec2>> aimedAtBox(const game::Match& match);

/// The close-up for a frame seen through `screen`, or nothing when the screen already
/// shows what is aimed at readably: every target in it at least `def.smallestPx` across,
/// and, where there is a shape to read (target blocks or blobs standing, a duel's
/// castles), at least `def.readablePx` tall (or nothing is aimed at). With `layout`, it stands
/// where it covers none of the layout's objects and overlays (the top right under the
/// HUD's band, else the top left, else the bottom corners; smaller if it must), and
/// nothing when no place is clear.
std::optional<TargetInset> targetInset(const game::Match& match, const Camera& screen,
                                       const TargetInsetDef& def = {},
                                       const ScreenLayout* layout = nullptr);

/// `def` with the close-up moved left of `panel` where the panel covers its place, if
/// there is room left of it; else `def` as it is.
TargetInsetDef clearOf(TargetInsetDef def, const Camera& screen, const PixelRect& panel);

/// Draws the close-up over the frame just drawn through `screen` (no HUD, no preview,
/// the effects as in the main view), with a frame and the distance from the cannon. With
/// `options.layout`, it goes in as the overlay "inset", and its objects as view "inset".
void drawTargetInset(Renderer2D& renderer, MatchView& view, const game::Match& match,
                     const Camera& screen, const TargetInset& inset,
                     MatchViewOptions options);

} // namespace ui
