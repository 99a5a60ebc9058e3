// Section index
//   drawing    a picture's frame: sky, ground, a path, a flag, a ball
//   pictures   one function a picture, each from its chapter's formula
//   cache      LessonPictures::picture, lessonPictureNames, lessonPictureCaption
#include "ui/game/lesson_pictures.h"

#include "physics/ballistics.h"
#include "ui/game/palette.h"
#include "ui/render/gl.h"

#include <cmath>
#include <functional>
#include <numbers>

namespace ui {

namespace {

using namespace palette;
using phys::Vec2;

constexpr double kG = 9.81;
constexpr double kDeg = std::numbers::pi / 180.0;

// ---- drawing ------------------------------------------------------------------------------
void sky(Renderer2D& r) {
    const Camera& c = r.camera();
    r.fillRectGradient(c.visibleMin(), c.visibleMax(), Color::hex(0xcfe7f5), Color::hex(0x2f6db5));
}

void ground(Renderer2D& r, double y) {
    const Camera& c = r.camera();
    r.fillRectGradient({c.visibleMin().x, c.visibleMin().y}, {c.visibleMax().x, y},
                       Color::hex(0x4a3423), Color::hex(0x7a5a3a));
    r.line({c.visibleMin().x, y}, {c.visibleMax().x, y}, Color::hex(0x5c9e3f), 4.0f);
}

/// The closed form p0 + v0 t + g t^2 / 2 from 0 to `seconds`, as a polyline.
std::vector<Vec2> parabola(Vec2 p0, Vec2 v0, double g, double seconds) {
    std::vector<Vec2> path;
    for (int i = 0; i <= 100; ++i) {
        const double t = seconds * i / 100.0;
        path.push_back(p0 + v0 * t + Vec2{0.0, -0.5 * g * t * t});
    }
    return path;
}

void flag(Renderer2D& r, Vec2 at, double size) {
    r.line(at, at + Vec2{0.0, size}, Color::hex(0x5a3d24), 3.0f);
    const Vec2 cloth[] = {at + Vec2{0.0, size}, at + Vec2{0.0, 0.6 * size}, at + Vec2{0.55 * size, 0.8 * size}};
    r.fillConvex(cloth, kTargetRed);
}

void ball(Renderer2D& r, Vec2 at, double radius, Color c = kShell) {
    r.fillCircle(at, radius, c);
}

// ---- pictures -------------------------------------------------------------------------------
/// From (10, 2) at 30 m/s to the flag at (50, 20): the low and the high shot (39.1 and
/// 75.2 degrees, Rabin (ed.), ch. 4.3).
void firingSolution(Renderer2D& r) {
    r.begin(Camera::framing({0.0, -4.0}, {62.0, 48.0}, r.camera().width, r.camera().height));
    sky(r);
    ground(r, 0.0);
    const Vec2 from{10.0, 2.0}, to{50.0, 20.0};
    r.fillRectGradient({8.5, 0.0}, {11.5, 2.0}, kHit, kHit);
    r.fillRectGradient({46.0, 0.0}, {56.0, 20.0}, Color::hex(0x9c978c), Color::hex(0x9c978c));
    const Color colours[] = {kGold, team(0)};
    int k = 0;
    for (const phys::FiringSolution& s : phys::solveFiring(from, to, 30.0, kG))
        r.polyline(parabola(from, s.launchVelocity, kG, s.flightTime), colours[k++ % 2], 4.0f);
    flag(r, to, 5.0);
    ball(r, from, 1.0);
}

/// The same shot, 45 degrees at 15 m/s: on Earth (9.81 m/s^2) it lands 22.9 m away, on
/// the Moon (1.62) six times as far.
void moonVsEarth(Renderer2D& r) {
    r.begin(Camera::framing({-6.0, -6.0}, {146.0, 46.0}, r.camera().width, r.camera().height));
    sky(r);
    ground(r, 0.0);
    const Vec2 v0{15.0 * std::cos(45.0 * kDeg), 15.0 * std::sin(45.0 * kDeg)};
    r.polyline(parabola({0.0, 0.0}, v0, 1.62, 2.0 * v0.y / 1.62), Color::hex(0xe8e8f0), 4.0f);
    r.polyline(parabola({0.0, 0.0}, v0, kG, 2.0 * v0.y / kG), team(0), 4.0f);
    ball(r, {0.0, 0.0}, 1.6);
}

/// A tennis ball (e = 0.712) dropped from 1 m: each bounce climbs to e^2 of the last.
void bounce(Renderer2D& r) {
    r.begin(Camera::framing({-0.2, -0.12}, {3.6, 1.15}, r.camera().width, r.camera().height));
    sky(r);
    ground(r, 0.0);
    const double e = 0.712, vx = 0.45;
    double height = 1.0, x = 0.0;
    std::vector<Vec2> path = parabola({x, height}, {vx, 0.0}, kG, std::sqrt(2.0 * height / kG));
    x = path.back().x;
    for (int k = 0; k < 6; ++k) {
        const double up = e * std::sqrt(2.0 * kG * height); // the speed off the ground
        height *= e * e;
        const std::vector<Vec2> arc = parabola({x, 0.0}, {vx, up}, kG, 2.0 * up / kG);
        r.line({x - 0.1, height}, {x + 0.9, height}, Color::hex(0xffffff, 0.5f), 1.5f);
        path.insert(path.end(), arc.begin() + 1, arc.end());
        x = arc.back().x;
    }
    r.polyline(path, kGold, 3.0f);
    ball(r, {0.0, 1.0}, 0.05, Color::hex(0xd7e84a));
}

/// A golf ball's path under quadratic drag F = -1/2 rho Cd A |v - w| (v - w) in a wind w,
/// stepped here with the midpoint rule until it comes down.
std::vector<Vec2> dragPath(Vec2 v0, double windX) {
    const double k = 0.5 * 1.2 * 0.25 * std::numbers::pi * 0.0214 * 0.0214 / 0.0459; // rho Cd A / 2m
    auto accel = [&](Vec2 v) {
        const Vec2 air = v - Vec2{windX, 0.0};
        return Vec2{0.0, -kG} - air * (k * length(air));
    };
    std::vector<Vec2> path{{0.0, 0.0}};
    Vec2 p{0.0, 0.0}, v = v0;
    for (const double dt = 0.01; p.y >= 0.0 && path.size() < 4000;) {
        const Vec2 vm = v + accel(v) * (0.5 * dt);
        p += vm * dt;
        v += accel(vm) * dt;
        path.push_back(p);
    }
    return path;
}

/// A golf ball at 40 m/s, 40 degrees: in a vacuum (the parabola), through still air and
/// into a 10 m/s headwind, each shorter and steeper at its end.
void dragVsVacuum(Renderer2D& r) {
    r.begin(Camera::framing({-6.0, -8.0}, {170.0, 48.0}, r.camera().width, r.camera().height));
    sky(r);
    ground(r, 0.0);
    const Vec2 v0{40.0 * std::cos(40.0 * kDeg), 40.0 * std::sin(40.0 * kDeg)};
    r.polyline(parabola({0.0, 0.0}, v0, kG, 2.0 * v0.y / kG), Color::hex(0xffffff, 0.8f), 3.0f);
    r.polyline(dragPath(v0, 0.0), team(1), 4.0f);
    r.polyline(dragPath(v0, -10.0), kGold, 4.0f);
    ball(r, {0.0, 0.0}, 1.5, Color::hex(0xf4f4f4));
}

/// A mass on a spring: omega = sqrt(k / m) sets the swing, the same for any amplitude.
void spring(Renderer2D& r) {
    r.begin(Camera::framing({-1.0, -1.6}, {11.0, 1.6}, r.camera().width, r.camera().height));
    r.fillRectGradient(r.camera().visibleMin(), r.camera().visibleMax(), Color::hex(0x1d2236),
                       Color::hex(0x2f3a5a));
    // The spring, stretched to the mass's place at t = 0, then x(t) = A cos(omega t).
    std::vector<Vec2> coil;
    for (int i = 0; i <= 24; ++i) coil.push_back({-0.8 + 0.06 * i, (i % 2 ? 0.25 : -0.25) * (i % 24 != 0)});
    r.polyline(coil, Color::hex(0xc9a86b), 3.0f);
    std::vector<Vec2> swing;
    for (int i = 0; i <= 400; ++i) {
        const double t = 10.0 * i / 400.0;
        swing.push_back({0.8 + t, 1.2 * std::cos(2.0 * std::numbers::pi * t / 3.0)});
    }
    r.line({0.8, 0.0}, {10.8, 0.0}, Color::hex(0xffffff, 0.3f), 1.5f);
    r.polyline(swing, kGold, 3.0f);
    ball(r, {0.8, 1.2}, 0.18, kTargetRed);
}

/// A block tips once its centre of mass is past the edge of its base.
void topple(Renderer2D& r) {
    r.begin(Camera::framing({-3.0, -0.6}, {5.0, 4.0}, r.camera().width, r.camera().height));
    sky(r);
    ground(r, 0.0);
    const double a = 28.0 * kDeg, w = 1.0, h = 3.0;
    const Vec2 pivot{1.0, 0.0}, up{-std::sin(a), std::cos(a)}, side{std::cos(a), std::sin(a)};
    const Vec2 q[] = {pivot, pivot - side * w, pivot - side * w + up * h, pivot + up * h};
    r.fillConvex(q, Color::hex(0x9a6b3f));
    r.polyline(q, Color::hex(0x5a3d24), 2.0f, true);
    const Vec2 com = pivot - side * (0.5 * w) + up * (0.5 * h);
    r.line(com, {com.x, 0.0}, kGold, 2.5f);
    ball(r, com, 0.12, kGold);
    ball(r, pivot, 0.08, kTargetRed);
}

/// Explicit Euler's steps of `dt` from the same shot as the exact path: each step uses
/// the start's velocity, so the path climbs g dt t / 2 above the parabola (Rabin (ed.),
/// ch. 4.3).
std::vector<Vec2> eulerSteps(Vec2 v0, double dt) {
    std::vector<Vec2> steps{{0.0, 0.0}};
    Vec2 p{0.0, 0.0}, v = v0;
    while (p.y >= 0.0 && steps.size() < 400) {
        p += v * dt;
        v += Vec2{0.0, -kG} * dt;
        steps.push_back(p);
    }
    return steps;
}

/// Explicit Euler at 0.2 s drifts off the exact path; at 0.05 s it hugs it.
void stepSize(Renderer2D& r) {
    r.begin(Camera::framing({-2.0, -3.0}, {40.0, 20.0}, r.camera().width, r.camera().height));
    sky(r);
    ground(r, 0.0);
    const Vec2 v0{12.0, 16.0};
    r.polyline(parabola({0.0, 0.0}, v0, kG, 2.0 * v0.y / kG), Color::hex(0xffffff, 0.9f), 3.0f);
    const std::vector<Vec2> large = eulerSteps(v0, 0.2), small = eulerSteps(v0, 0.05);
    r.polyline(large, kTargetRed, 3.0f);
    for (const Vec2 s : large) ball(r, s, 0.35, kTargetRed);
    r.polyline(small, kGold, 2.0f);
    for (const Vec2 s : small) ball(r, s, 0.18, kGold);
}

/// The arsenal's eight moves side by side, a column each (cluster, bouncer, roller,
/// grenade, mortar, airburst, digger, sticky), each sketched from its rule.
void arsenal(Renderer2D& r) {
    r.begin(Camera::framing({-1.0, -4.0}, {81.0, 14.0}, r.camera().width, r.camera().height));
    sky(r);
    ground(r, 0.0);
    const Color path = Color::hex(0xffffff, 0.85f), burst = Color::hex(0xffb347, 0.9f);
    auto arc = [&](Vec2 from, Vec2 v, double seconds) { r.polyline(parabola(from, v, kG, seconds), path, 2.5f); };
    // cluster: splits in four at its apex
    arc({1.0, 0.0}, {3.0, 10.0}, 10.0 / kG);
    for (const double vx : {-2.0, 0.0, 2.0, 4.0}) arc({1.0 + 30.0 / kG, 50.0 / kG}, {vx, 0.0}, 1.0);
    // bouncer: e = 0.9, bounce after bounce
    double x = 12.0, up = 9.0;
    for (int k = 0; k < 3; ++k, up *= 0.9) {
        arc({x, 0.0}, {2.0, up}, 2.0 * up / kG);
        x += 4.0 * up / kG;
    }
    // roller: comes down and rolls along the ground
    arc({22.0, 0.0}, {2.0, 8.0}, 16.0 / kG);
    r.line({22.0 + 32.0 / kG, 0.15}, {30.0, 0.15}, path, 2.5f);
    ball(r, {30.0, 0.5}, 0.5, kShell);
    // grenade: bounces until its fuse burns down, then bursts
    arc({32.0, 0.0}, {2.0, 7.0}, 14.0 / kG);
    arc({32.0 + 28.0 / kG, 0.0}, {2.0, 3.5}, 7.0 / kG);
    r.fillCircle({32.0 + 42.0 / kG, 0.6}, 1.4, burst);
    // mortar: heavy and finned, the near-vacuum arc
    arc({42.0, 0.0}, {2.0, 11.0}, 22.0 / kG);
    // airburst: bursts 5 m above the ground
    arc({52.0, 0.0}, {2.5, 11.0}, 1.6);
    r.fillCircle(Vec2{52.0, 0.0} + Vec2{2.5 * 1.6, 11.0 * 1.6 - 0.5 * kG * 1.6 * 1.6}, 1.8, burst);
    // digger: a tunnel under the ground
    arc({61.0, 0.0}, {2.0, 8.0}, 16.0 / kG);
    r.fillRectGradient({61.0 + 32.0 / kG, -2.2}, {69.0, -0.6}, Color::hex(0x1a120c), Color::hex(0x1a120c));
    // sticky: e = 0 against a wall, stuck where it struck
    r.fillRectGradient({78.0, 0.0}, {79.2, 10.0}, Color::hex(0x9c978c), Color::hex(0x9c978c));
    arc({71.0, 0.0}, {5.0, 9.0}, 7.0 / 5.0);
    ball(r, Vec2{71.0, 0.0} + Vec2{7.0, 9.0 * 1.4 - 0.5 * kG * 1.4 * 1.4}, 0.5, kTargetRed);
}

/// One scene, a model for each thing: the closed-form parabola (white), the shell
/// integrated through air (red), a rope of rods (gold) and a rigid block (brown).
void models(Renderer2D& r) {
    r.begin(Camera::framing({-2.0, -3.0}, {60.0, 24.0}, r.camera().width, r.camera().height));
    sky(r);
    ground(r, 0.0);
    const Vec2 v0{16.0, 14.0};
    r.polyline(parabola({0.0, 0.0}, v0, kG, 2.0 * v0.y / kG), Color::hex(0xffffff, 0.9f), 3.0f);
    r.polyline(dragPath(v0 * 1.6, 0.0), kTargetRed, 3.0f);
    std::vector<Vec2> rope;
    for (int i = 0; i <= 10; ++i) {
        const double t = i / 10.0;
        rope.push_back({34.0 + 14.0 * t, 16.0 - 5.0 * std::sin(std::numbers::pi * t)});
    }
    r.line({34.0, 0.0}, {34.0, 16.0}, Color::hex(0x5a3d24), 4.0f);
    r.line({48.0, 0.0}, {48.0, 16.0}, Color::hex(0x5a3d24), 4.0f);
    r.polyline(rope, kGold, 3.0f);
    for (const Vec2 p : rope) ball(r, p, 0.3, kGold);
    const Vec2 block[] = {{51.0, 0.0}, {56.0, 0.0}, {56.0, 5.0}, {51.0, 5.0}};
    r.fillConvex(block, Color::hex(0x9a6b3f));
    r.polyline(block, Color::hex(0x5a3d24), 2.0f, true);
}

struct Picture {
    const char* name;
    void (*draw)(Renderer2D&);
    const char* caption;
};

// In campaign order, as game::lessonPictures() names them.
const Picture kPictures[] = {
    {"firing-solution", firingSolution,
     "From (10, 2) at 30 m/s two angles reach the flag at (50, 20): 39.1° and 75.2°."},
    {"moon-vs-earth", moonVsEarth,
     "The same shot, 45° at 15 m/s: 22.9 m on Earth (blue), six times as far on the Moon."},
    {"drag-vs-vacuum", dragVsVacuum,
     "A golf ball at 40 m/s: in a vacuum (white), through still air (red), into a 10 m/s headwind (gold)."},
    {"bounce", bounce, "e = 0.712: each bounce climbs to e² = 0.51 of the one before."},
    {"arsenal", arsenal,
     "Cluster, bouncer, roller, grenade, mortar, airburst, digger, sticky: each moves by its own rule."},
    {"spring", spring, "x(t) = A cos(ωt): the same period, whatever the swing."},
    {"topple", topple, "Past the edge of its base, the centre of mass pulls the block over."},
    {"step-size", stepSize,
     "Explicit Euler at dt = 0.2 s (red) climbs above the exact parabola (white); at 0.05 s (gold) it hugs it."},
    {"models", models,
     "A model for each thing: the closed form (white), a shell through air (red), a rope of rods, a rigid block."},
};

const Picture* find(const std::string& name) {
    for (const Picture& p : kPictures)
        if (name == p.name) return &p;
    return nullptr;
}

} // namespace

// ---- cache ----------------------------------------------------------------------------------
const std::vector<std::string>& lessonPictureNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all;
        for (const Picture& p : kPictures) all.push_back(p.name);
        return all;
    }();
    return names;
}

std::string lessonPictureCaption(const std::string& name) {
    const Picture* p = find(name);
    return p ? p->caption : "";
}

const TextureTarget* LessonPictures::picture(const std::string& name, int width, int height,
                                             unsigned restoreFbo) {
    const Picture* p = find(name);
    if (!p) return nullptr;
    const std::string key = name + "@" + std::to_string(width) + "x" + std::to_string(height);
    if (const auto it = pictures_.find(key); it != pictures_.end()) return it->second.get();
    auto target = std::make_unique<TextureTarget>();
    if (!target->create(width, height, 4)) return nullptr;
    if (!renderer_) renderer_ = std::make_unique<Renderer2D>();
    target->bind();
    gl::fn.Viewport(0, 0, width, height);
    Camera size;
    size.width = width;
    size.height = height;
    renderer_->begin(size);
    p->draw(*renderer_);
    renderer_->flush();
    target->finish(restoreFbo);
    return (pictures_[key] = std::move(target)).get();
}

} // namespace ui
