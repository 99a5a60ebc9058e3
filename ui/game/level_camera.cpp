#include "ui/game/level_camera.h"

#include "ui/render/design_canvas.h"

#include <algorithm>
#include <cmath>

namespace ui {

namespace {

using game::Match;
using phys::Vec2;

/// The lowest point of what the player aims at or fires from (cannons, targets, blocks,
/// blobs), m; infinity where there is none.
double lowestThingStanding(const Match& m) {
    const game::Level& l = m.level();
    double lowest = INFINITY;
    for (const auto& c : m.cannons())
        lowest = std::min(lowest, c.def.position.y - game::kCannonRadius);
    for (const auto& t : m.targets())
        lowest = std::min(lowest, t.position.y - t.def.radius);
    for (const auto& b : l.blocks)
        lowest = std::min(lowest, b.position.y - 0.5 * b.size.y);
    for (const auto& b : l.blobs)
        lowest = std::min(lowest, b.center.y - b.radius);
    return lowest;
}

} // namespace

double coveredBottom(const PixelRect& panel, double width, double height) {
    if (!(height > 0.0)) return 0.0;
    double top = height - kHudBottomBand * hudScale(width, height); // the aim readout's
    if (panel.y1 >= 0.9 * height) top = std::min(top, panel.y0);
    return std::clamp((height - top) / height, 0.0, 1.0);
}
Camera levelCamera(const Match& m, int width, int height, double coveredBottom, double coveredTop) {
    const game::Level& l = m.level();
    double ground = INFINITY, top = -INFINITY;
    for (const Vec2 p : m.terrain().points()) ground = std::min(ground, p.y), top = std::max(top, p.y);
    for (const auto& c : m.cannons()) top = std::max(top, c.def.position.y + 3.0);
    for (const auto& t : m.targets()) top = std::max(top, t.position.y + t.def.radius + 2.0);
    for (const auto& b : l.blocks) top = std::max(top, b.position.y + b.size.y + 2.0);
    for (const auto& o : l.obstacles)
        for (const Vec2 p : o.points) top = std::max(top, p.y + 2.0);
    // The width: from the leftmost to the rightmost thing to see, with room around them,
    // within the level's bounds.
    double left = INFINITY, right = -INFINITY;
    auto see = [&](Vec2 p) { left = std::min(left, p.x), right = std::max(right, p.x); };
    for (const auto& c : m.cannons()) see(c.def.position);
    for (const auto& t : m.targets()) {
        see(t.position);
        for (const Vec2 p : t.def.path) see(p);
    }
    for (const auto& b : l.blocks) see(b.position);
    for (const auto& r : l.ropes) see(r.from), see(r.to);
    for (const auto& b : l.blobs) see(b.center);
    const double margin = 0.08 * (right - left) + 8.0;
    const double xMin = std::max(l.worldMin.x, left - margin);
    const double xMax = std::min(l.worldMax.x, right + margin);
    const double aspect = static_cast<double>(height) / width;
    // The whole width of the level, with a band of soil under the lowest ground (the
    // bottom HUD sits on it) and the sky above for the arcs. When the things to see are
    // taller than the width allows, the height decides and the view is centred on x.
    // The soil is deeper where the panels along the bottom reach higher: what stands
    // lowest (a cannon, a target, a block, a blob: not a pit's floor) is 3 % of the
    // height above them.
    const double lowest = lowestThingStanding(m);
    const double clear = std::isfinite(coveredBottom) ? std::min(coveredBottom, 0.5) + 0.03 : 0.0;
    auto soilFor = [&](double visible) {
        const double standing = std::isfinite(lowest) ? std::max(0.0, lowest - ground) : 0.0;
        return std::max(0.22, clear - standing / visible);
    };
    const double widthHeight = (xMax - xMin) * aspect;
    double visibleHeight = widthHeight, soilFraction = 0.22;
    for (int pass = 0; pass < 2; ++pass) { // the soil sets the height, which sets the soil
        soilFraction = std::max(soilFraction, soilFor(visibleHeight));
        // Room for the things to see above the soil, whatever its depth.
        // The top band the HUD's boxes stand in stays clear of them too.
        const double open = std::max(0.2, 1.0 - soilFraction - std::clamp(coveredTop, 0.0, 0.4));
        const double needed = std::max((top - ground) * 1.35 + soilFraction * widthHeight,
                                       (top - ground) / open);
        visibleHeight = std::max(widthHeight, needed);
    }
    Camera cam;
    cam.width = width;
    cam.height = height;
    cam.pixelsPerMetre = height / visibleHeight;
    const double bottom = ground - soilFraction * visibleHeight;
    cam.center = {0.5 * (xMin + xMax), bottom + 0.5 * visibleHeight};
    // A view wider than the things to see (the height decided) slides inside the level's
    // bounds where they are wide enough: what lies outside them cannot be reached (a
    // sandbox spawn there is refused), so it is not shown as if it were ground and sky.
    // [xMin, xMax] stays in view: it lies within the bounds and is no wider than the view.
    const double halfWidth = 0.5 * width / cam.pixelsPerMetre;
    if (l.worldMax.x - l.worldMin.x >= 2.0 * halfWidth)
        cam.center.x = std::clamp(cam.center.x, l.worldMin.x + halfWidth, l.worldMax.x - halfWidth);
    return cam;
}

Camera levelCameraLeftOf(const Match& m, int width, int height, double coveredRight,
                         double coveredBottom, double coveredTop) {
    const double right = std::isfinite(coveredRight) ? std::clamp(coveredRight, 0.0, 0.5) : 0.0;
    if (right <= 0.0) return levelCamera(m, width, height, coveredBottom, coveredTop);
    const int open = std::max(1, static_cast<int>(std::lround(width * (1.0 - right))));
    Camera cam = levelCamera(m, open, height, coveredBottom, coveredTop);
    cam.width = width;
    cam.center.x += 0.5 * (width - open) / cam.pixelsPerMetre;
    return cam;
}

} // namespace ui
