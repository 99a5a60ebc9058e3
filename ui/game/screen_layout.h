// What the screen shows the player, as rectangles in window pixels (y down): the overlays,
// everything drawn that is not the world (HUD boxes, panels, the close-up, labels, pop-ups,
// cards), and the objects the player must see (targets, cannons, the shell in flight, the
// point of impact), as drawn. The one layout rule of the game: no overlay covers an object.
// The game screen gathers a frame's layout as it draws: the world's objects first, then
// each overlay, placed where it covers none of them (firstClear); `play --json` reports the
// last frame's, and the tests check the rule on every level.
#pragma once

#include "ui/render/pixel_rect.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ui {

struct LayoutOverlay {
    std::string name; ///< "hud.score", "inset", "panel.Physics", "label", "card", ...
    PixelRect rect;
};

struct LayoutObject {
    std::string kind; ///< "target", "cannon", "shell" or "impact"
    std::string view; ///< "main", or "inset" for the close-up's copies
    PixelRect rect;
};

struct ScreenLayout {
    int width = 0, height = 0;
    std::vector<LayoutOverlay> overlays;
    std::vector<LayoutObject> objects;

    void clear(int w, int h);
    void addOverlay(std::string name, const PixelRect& rect);
    void addObject(std::string kind, std::string view, const PixelRect& rect);
    /// The objects' rectangles (of every view), for placing an overlay clear of them.
    std::vector<PixelRect> objectRects() const;
    /// The overlays' rectangles so far, for placing one more clear of them too.
    std::vector<PixelRect> overlayRects() const;
    /// What one more overlay must stand clear of: the objects and the overlays so far.
    std::vector<PixelRect> taken() const;
    /// The first of `candidates` clear of taken() and on the screen, added as the overlay
    /// `name`; nothing (and nothing added) when none is clear.
    std::optional<PixelRect> placeOverlay(std::string name, std::span<const PixelRect> candidates);
};

/// An overlay over an object: their indices in the layout.
struct Covering {
    std::size_t overlay = 0, object = 0;
};
/// Every overlay that covers an object (their rectangles intersect); none when the rule holds.
std::vector<Covering> coverings(const ScreenLayout& layout);
/// One line a covering: "hud.score [x, y, w, h] covers target (main) [x, y, w, h]".
std::string describe(const ScreenLayout& layout, const Covering& c);

/// The layout as JSON: {"size": [W, H], "overlays": [{"name", "rect": [x, y, w, h]}],
/// "objects": [{"kind", "view", "rect"}]}, rectangles in whole pixels.
std::string layoutJson(const ScreenLayout& layout);

/// The first of `candidates` that overlaps none of `avoid` and lies inside `screen`.
std::optional<PixelRect> firstClear(std::span<const PixelRect> candidates,
                                    std::span<const PixelRect> avoid, const PixelRect& screen);
/// `r` grown by `px` on every side.
PixelRect grown(const PixelRect& r, double px);
/// Whether `inner` lies inside `outer`.
bool inside(const PixelRect& inner, const PixelRect& outer);

} // namespace ui
