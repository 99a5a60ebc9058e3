#include "ui/game/target_inset.h"

#include "game/match.h"
#include "ui/game/level_camera.h"
#include "ui/game/screen_layout.h"
#include "ui/render/design_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ui {

namespace {

struct Box {
    Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
    bool empty() const { return lo.x > hi.x; }
    void add(Vec2 p, double r = 0.0) {
        lo = {std::min(lo.x, p.x - r), std::min(lo.y, p.y - r)};
        hi = {std::max(hi.x, p.x + r), std::max(hi.y, p.y + r)};
    }
    void add(Vec2 p, Vec2 half) {
        lo = {std::min(lo.x, p.x - half.x), std::min(lo.y, p.y - half.y)};
        hi = {std::max(hi.x, p.x + half.x), std::max(hi.y, p.y + half.y)};
    }
    bool overlaps(Vec2 p, Vec2 half) const {
        return p.x + half.x >= lo.x && p.x - half.x <= hi.x && p.y + half.y >= lo.y &&
               p.y - half.y <= hi.y;
    }
};

} // namespace

std::optional<std::pair<Vec2, Vec2>> aimedAtBox(const game::Match& m) {
    Box box;
    for (const game::TargetState& t : m.targets())
        if (!t.hit) box.add(t.position, t.def.radius);
    for (const game::BlockState& b : m.blocks())
        if (b.def.target && !b.toppled) box.add(m.rigid().state(b.body).position, turnedHalf(m, b));
    for (const game::BlobState& b : m.blobs())
        if (b.def.target && !b.toppled) box.add(m.world().particles.position(b.center), b.def.radius);
    for (std::size_t i = 0; i < m.cannons().size(); ++i) {
        const game::CannonState& c = m.cannons()[i];
        const bool opponent = c.def.player != m.cannon().def.player;
        if (m.level().mode == game::Mode::Duel && opponent && c.hitPoints > 0) {
            box.add(c.def.position, game::kCannonRadius);
            // With the ground it stands on (and its pedestal, where it stands above it): a
            // cannon framed alone floats in the sky, and where the shell must land is not shown.
            box.add({c.def.position.x, m.terrain().heightAt(c.def.position.x)});
        }
    }
    if (box.empty()) return std::nullopt;
    // The structure the targets stand in reads as one thing: take in every block that
    // touches what is framed so far (a tower's plain blocks around its marked ones).
    const Box marked = box;
    for (const game::BlockState& b : m.blocks()) {
        const Vec2 p = m.rigid().state(b.body).position;
        Box near = marked;
        near.lo = near.lo - Vec2{6.0, 6.0};
        near.hi = near.hi + Vec2{6.0, 6.0};
        if (near.overlaps(p, turnedHalf(m, b))) box.add(p, turnedHalf(m, b));
    }
    return std::pair{box.lo, box.hi};
}

namespace {

/// The smallest of the targets still standing as drawn, m across: discs at their drawn
/// radius, target blocks and blobs by their shorter side; infinity where there is none.
double smallestTarget(const game::Match& m, const Camera& screen) {
    double smallest = INFINITY;
    for (const game::TargetState& t : m.targets())
        if (!t.hit) smallest = std::min(smallest, 2.0 * targetDrawRadius(t, screen));
    for (const game::BlockState& b : m.blocks())
        if (b.def.target && !b.toppled) smallest = std::min({smallest, b.def.size.x, b.def.size.y});
    for (const game::BlobState& b : m.blobs())
        if (b.def.target && !b.toppled) smallest = std::min(smallest, 2.0 * b.def.radius);
    return smallest;
}

/// A target block or blob still standing: something whose fall depends on its shape.
bool aimsAtStructures(const game::Match& m) {
    for (const game::BlockState& b : m.blocks())
        if (b.def.target && !b.toppled) return true;
    for (const game::BlobState& b : m.blobs())
        if (b.def.target && !b.toppled) return true;
    return false;
}

/// Where the close-up may stand, w x h px, in order: the top right under the HUD's band,
/// the top left under it, the bottom right and the bottom left over the aim's band.
std::vector<PixelRect> insetPlaces(const Camera& screen, const TargetInsetDef& def, double w, double h) {
    const double W = screen.width, H = screen.height, m = def.rightPx, top = def.topPx;
    const double bottom = H - kHudBottomBand * hudScale(W, H) - h;
    return {{W - m - w, top, W - m, top + h}, {m, top, m + w, top + h},
            {W - m - w, bottom, W - m, bottom + h}, {m, bottom, m + w, bottom + h}};
}

} // namespace

std::optional<TargetInset> targetInset(const game::Match& m, const Camera& screen,
                                       const TargetInsetDef& def, const ScreenLayout* layout) {
    const auto aimed = aimedAtBox(m);
    if (!aimed) return std::nullopt;
    const auto [lo, hi] = *aimed;
    // Shown readable already: no target in it is too small to make out, and a structure
    // (a castle to knock down, a duel's cover) stands tall enough to read its shape. Discs
    // alone, drawn at their readable size, need nothing more.
    const double shownPx = std::max(hi.y - lo.y, 1.0) * screen.pixelsPerMetre;
    const double smallestPx = smallestTarget(m, screen) * screen.pixelsPerMetre;
    const bool shapeToRead = m.level().mode == game::Mode::Duel || aimsAtStructures(m);
    if (smallestPx >= def.smallestPx && (!shapeToRead || shownPx >= def.readablePx)) return std::nullopt;
    const std::vector<PixelRect> avoid = layout ? layout->taken() : std::vector<PixelRect>{};
    const PixelRect whole{0.0, 0.0, static_cast<double>(screen.width), static_cast<double>(screen.height)};
    // As large as a clear place allows: its full size, else smaller.
    for (const double fraction : {def.widthFraction, 0.75 * def.widthFraction, 0.55 * def.widthFraction}) {
        const int w = static_cast<int>(std::lround(fraction * screen.width));
        const int h = static_cast<int>(std::lround(w * 9.0 / 16.0));
        const auto place = firstClear(insetPlaces(screen, def, w, h), avoid, whole);
        if (!place) continue;
        TargetInset inset;
        const Vec2 margin{def.marginM, def.marginM};
        inset.camera = Camera::framing(lo - margin, hi + margin, w, h);
        inset.cornerPx = {place->x0, place->y0};
        return inset;
    }
    return std::nullopt;
}

TargetInsetDef clearOf(TargetInsetDef def, const Camera& screen, const PixelRect& panel) {
    const double w = std::round(def.widthFraction * screen.width), h = std::round(w * 9.0 / 16.0);
    const double x1 = screen.width - def.rightPx;
    const double gap = def.rightPx;
    if (!panel.overlaps({x1 - w, def.topPx, x1, def.topPx + h}) || panel.x0 - gap - w < gap)
        return def;
    def.rightPx = screen.width - panel.x0 + gap;
    return def;
}

void drawTargetInset(Renderer2D& r, MatchView& view, const game::Match& m, const Camera& screen,
                     const TargetInset& inset, MatchViewOptions o) {
    o.hud = false;
    o.trajectoryPreview = false;
    o.solutionHint = false;
    o.pending.reset();
    o.charge.reset();
    o.banner.clear();
    if (o.layout) {
        const PixelRect rect{inset.cornerPx.x, inset.cornerPx.y,
                             inset.cornerPx.x + inset.camera.width, inset.cornerPx.y + inset.camera.height};
        o.layout->addOverlay("inset", rect);
        o.layoutView = "inset";
        o.layoutOffset = inset.cornerPx;
        o.layoutClip = rect;
    }
    const int x = static_cast<int>(std::lround(inset.cornerPx.x));
    const int yUp = screen.height - static_cast<int>(std::lround(inset.cornerPx.y)) -
                    inset.camera.height; // GL counts rows from the bottom
    r.beginInset(inset.camera, x, yUp);
    view.draw(r, m, o);
    r.endInset(screen);
    // A frame around it, and how far it is from the cannon that fires now.
    const Vec2 a = screen.toWorld(inset.cornerPx);
    const Vec2 b = screen.toWorld(inset.cornerPx + Vec2{static_cast<double>(inset.camera.width),
                                                         static_cast<double>(inset.camera.height)});
    const Vec2 corners[4] = {{a.x, a.y}, {b.x, a.y}, {b.x, b.y}, {a.x, b.y}};
    r.polyline(corners, Color::hex(0x1b2433, 0.9f), 3.0f, true);
    r.flush();
    const Vec2 centre = 0.5 * (inset.camera.visibleMin() + inset.camera.visibleMax());
    char text[64];
    std::snprintf(text, sizeof text, "target  %.0f m", std::abs(centre.x - m.cannon().def.position.x));
    r.screenLabel(inset.cornerPx + Vec2{8.0, 6.0}, text, Color::hex(0xffffff, 0.95f), 0.9f);
}

} // namespace ui
