#include "ui/demo/demo_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace ui {

namespace {

constexpr double kDegrees = std::numbers::pi / 180.0;

// Palette: a clear afternoon.
const Color kSkyTop = Color::hex(0x3d7cc9);
const Color kSkyHorizon = Color::hex(0xbfe0f5);
const Color kHillFar = Color::hex(0x8fb3a8);
const Color kHillNear = Color::hex(0x6e9c6a);
const Color kGrass = Color::hex(0x4f8a3c);
const Color kSoilTop = Color::hex(0x6b4f33);
const Color kSoilDeep = Color::hex(0x3f2e1f);
const Color kWood = Color::hex(0x7a5535);
const Color kIron = Color::hex(0x2f3338);
const Color kLabel = Color::hex(0xffffff);

void drawSky(Renderer2D& r, const DemoScene& scene) {
    const Camera& c = r.camera();
    const Vec2 lo = c.visibleMin(), hi = c.visibleMax();
    const double ground = scene.def().groundY;
    // The gradient runs from the horizon to a fixed height, so it does not slide with zoom.
    const double top = ground + 40.0;
    r.fillRectGradient({lo.x, ground}, {hi.x, std::max(top, ground)}, kSkyHorizon, kSkyTop);
    if (hi.y > top) r.fillRectGradient({lo.x, top}, {hi.x, hi.y}, kSkyTop, kSkyTop);
    // Sun and a few clouds: soft discs.
    r.fillCircle({6.0, 26.0}, 2.6, Color::hex(0xfff4c2, 0.35f));
    r.fillCircle({6.0, 26.0}, 1.9, Color::hex(0xfff7d6));
    const Vec2 clouds[] = {{17.0, 25.0}, {33.0, 28.0}, {41.0, 21.0}};
    for (const Vec2 cl : clouds) {
        const Color white = Color::hex(0xffffff, 0.82f);
        r.fillCircle(cl, 1.6, white);
        r.fillCircle(cl + Vec2{1.7, -0.3}, 1.3, white);
        r.fillCircle(cl + Vec2{-1.7, -0.4}, 1.1, white);
        r.fillCircle(cl + Vec2{0.6, 0.8}, 1.1, white);
    }
}

/// Rolling hills behind the playfield: a sum of sines, filled down to the ground.
void drawHills(Renderer2D& r, double ground, double height, double phase, Color color) {
    const Camera& c = r.camera();
    const double x0 = c.visibleMin().x - 1.0, x1 = c.visibleMax().x + 1.0;
    const int n = 96;
    Vec2 prev{};
    for (int i = 0; i <= n; ++i) {
        const double x = x0 + (x1 - x0) * i / n;
        const double y = ground + height * (0.6 + 0.25 * std::sin(0.09 * x + phase) +
                                            0.15 * std::sin(0.23 * x + 2.0 * phase));
        const Vec2 p{x, y};
        if (i > 0) {
            const Vec2 quad[] = {{prev.x, ground}, {p.x, ground}, p, prev};
            r.fillConvex(quad, color);
        }
        prev = p;
    }
}

void drawGround(Renderer2D& r, double ground) {
    const Camera& c = r.camera();
    const Vec2 lo = c.visibleMin(), hi = c.visibleMax();
    r.fillRectGradient({lo.x, std::min(lo.y, ground - 1.0)}, {hi.x, ground}, kSoilDeep, kSoilTop);
    r.fillRectGradient({lo.x, ground - 0.35}, {hi.x, ground}, kGrass, kGrass);
    r.line({lo.x, ground}, {hi.x, ground}, Color::hex(0x7bc45a), 2.0f);
    // Range marks every 10 m along the ground: the ruler a player reads landings against.
    const double first = std::ceil(lo.x / 10.0) * 10.0;
    for (double x = first; x <= hi.x; x += 10.0) {
        r.line({x, ground - 0.35}, {x, ground - 1.0}, Color::hex(0xe8dcc0, 0.7f), 1.5f);
        char text[16];
        std::snprintf(text, sizeof text, "%.0f m", x + 0.0); // + 0.0: no "-0 m"
        r.label({x, ground - 1.0}, text, Color::hex(0xe8dcc0), {-12.0, 2.0}, 0.8f);
    }
}

void drawCannon(Renderer2D& r, const DemoScene& scene) {
    const DemoDef& d = scene.def();
    const double a = d.angleDeg * kDegrees;
    const Vec2 dir{std::cos(a), std::sin(a)}, side = phys::perp(dir);
    const Vec2 pivot = d.cannonPivot;
    // Barrel: a tapered quad from breech to muzzle, with a muzzle ring.
    const Vec2 breech = pivot - dir * 0.5;
    const Vec2 muzzle = scene.muzzle();
    const Vec2 barrel[] = {breech + side * 0.42, breech - side * 0.42, muzzle - side * 0.28,
                           muzzle + side * 0.28};
    r.fillConvex(barrel, kIron);
    const Vec2 ring[] = {muzzle - dir * 0.25 + side * 0.36, muzzle - dir * 0.25 - side * 0.36,
                         muzzle - side * 0.36, muzzle + side * 0.36};
    r.fillConvex(ring, Color::hex(0x474d55));
    r.fillCircle(breech, 0.42, kIron);
    // Carriage and wheel.
    const Vec2 carriage[] = {{pivot.x - 1.2, d.groundY + 0.3},
                             {pivot.x + 0.6, d.groundY + 0.3},
                             {pivot.x + 0.3, pivot.y + 0.1},
                             {pivot.x - 0.6, pivot.y + 0.1}};
    r.fillConvex(carriage, kWood);
    const Vec2 wheel{pivot.x, d.groundY + 0.75};
    r.fillCircle(wheel, 0.75, Color::hex(0x5a3d24));
    r.strokeCircle(wheel, 0.68, Color::hex(0x2b1d12), 3.0f);
    for (int k = 0; k < 6; ++k) {
        const double t = k * std::numbers::pi / 3.0;
        r.line(wheel, wheel + Vec2{std::cos(t), std::sin(t)} * 0.65, Color::hex(0x2b1d12), 2.0f);
    }
    r.fillCircle(wheel, 0.14, kIron);
}

void drawGallows(Renderer2D& r, const DemoScene& scene) {
    const DemoDef& d = scene.def();
    const Vec2 top = d.chainAnchor;
    const double ground = d.groundY;
    const double postX = top.x - 3.0;
    const Vec2 post[] = {{postX - 0.25, ground},
                         {postX + 0.25, ground},
                         {postX + 0.25, top.y + 0.5},
                         {postX - 0.25, top.y + 0.5}};
    r.fillConvex(post, kWood);
    const Vec2 beam[] = {{postX - 0.25, top.y + 0.1},
                         {top.x + 0.5, top.y + 0.1},
                         {top.x + 0.5, top.y + 0.5},
                         {postX - 0.25, top.y + 0.5}};
    r.fillConvex(beam, kWood);
    r.line({postX, top.y - 1.6}, {postX + 1.6, top.y + 0.1}, kWood, 5.0f);
}

void drawTrails(Renderer2D& r, const DemoScene& scene) {
    const double now = scene.world.time();
    for (const Landing& l : scene.landings()) {
        // Old flights fade out over a few seconds.
        const float fade = static_cast<float>(std::clamp(1.0 - (now - l.time) / 6.0, 0.0, 1.0));
        if (fade <= 0.0f) continue;
        const Color c =
            l.vacuum ? Color::hex(0xffffff, 0.45f * fade) : Color::hex(0xffb347, 0.55f * fade);
        r.polyline(l.trail, c, 2.0f);
    }
    for (const ShellTrack& s : scene.shells()) {
        const Color c = s.vacuum ? Color::hex(0xffffff, 0.6f) : Color::hex(0xffb347, 0.85f);
        r.polyline(s.trail, c, 2.5f);
    }
}

void drawLandings(Renderer2D& r, const DemoScene& scene, bool labels) {
    const double now = scene.world.time();
    for (const Landing& l : scene.landings()) {
        const float fade = static_cast<float>(std::clamp(1.0 - (now - l.time) / 6.0, 0.25, 1.0));
        const Color c = l.vacuum ? Color::hex(0xffffff, fade) : Color::hex(0xff8a1e, fade);
        const Vec2 ground{l.at.x, scene.def().groundY};
        r.fillCircle(ground, 0.45, Color::hex(0x2a1d12, 0.6f * fade)); // scorch
        r.line(ground, ground + Vec2{0.0, 1.6}, c, 2.0f);
        r.fillConvex(std::array<Vec2, 3>{ground + Vec2{0.0, 1.6}, ground + Vec2{0.9, 1.35},
                                         ground + Vec2{0.0, 1.1}},
                     c);
        if (labels) {
            char text[32];
            std::snprintf(text, sizeof text, "%.1f m%s", l.range, l.vacuum ? " (vacuum)" : "");
            r.label(ground + Vec2{0.0, 1.6}, text, c.withAlpha(1.0f),
                    {0.0, l.vacuum ? -38.0 : -20.0}, 0.85f, 0.5f);
        }
    }
}

} // namespace

Camera demoCamera(const DemoScene& scene, int width, int height) {
    const double g = scene.def().groundY;
    return Camera::framing({-6.0, g - 3.0}, {66.0, g + 30.0}, width, height);
}

void drawDemo(Renderer2D& r, const DemoScene& scene, const DemoViewOptions& o) {
    const double ground = scene.def().groundY;
    drawSky(r, scene);
    drawHills(r, ground, 9.0, 0.7, kHillFar);
    drawHills(r, ground, 5.0, 2.9, kHillNear);
    drawGround(r, ground);
    drawGallows(r, scene);
    if (o.trails) drawTrails(r, scene);
    drawLandings(r, scene, o.labels);
    drawCannon(r, scene);
    drawWorld(r, scene.world, o.world);
    const double wind = scene.world.def().forces.wind.x;
    if (wind != 0.0) {
        // The wind as an arrow in the sky, 0.5 m of arrow per m/s (a 10 m/s wind spans 5 m).
        const Vec2 from{22.0 - 0.25 * wind, 31.0};
        r.arrow(from, from + Vec2{0.5 * wind, 0.0}, Color::hex(0xffffff, 0.9f), 3.0f, 12.0f);
        if (o.labels) {
            char text[32];
            std::snprintf(text, sizeof text, "wind %.1f m/s", wind);
            r.label({22.0, 31.0}, text, kLabel, {0.0, 8.0}, 0.85f, 0.5f);
        }
    }
    if (o.labels) {
        const DemoDef& d = scene.def();
        char text[64];
        std::snprintf(text, sizeof text, "%.0f m/s at %.0f\xc2\xb0", d.muzzleSpeed, d.angleDeg);
        r.label(d.cannonPivot + Vec2{-5.0, 3.4}, text, kLabel, {}, 0.85f);
        r.label(d.chainAnchor + Vec2{0.8, 0.5}, "spring chain", kLabel, {0.0, -20.0}, 0.85f);
    }
}

} // namespace ui
