#include "ui/icon/game_icon.h"

#include "physics/ballistics.h"
#include "ui/charts/chart_png.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <ostream>
#include <vector>

namespace ui {

namespace {

// The icon is designed on the unit square (y up) and mapped onto the picture.
constexpr double kCorner = 0.18;    ///< radius of the rounded square's corners
constexpr double kLaunchDeg = 62.0; ///< the barrel's elevation
constexpr double kGravity = 1.0;    ///< in icon units: only the arc's shape matters
const Color kSky = Color::hex(0x24406b);
const Color kSkyLow = Color::hex(0x4f7fae);
const Color kGround = Color::hex(0x4f8f3a);
const Color kIron = Color::hex(0x2a2a2e);
const Color kWheel = Color::hex(0x6b4a2b);
const Color kArc = Color::hex(0xf1f1e6);
const Color kShell = Color::hex(0xe4572e);
const Color kBlock = Color::hex(0xc9a66b);
const Color kBlockEdge = Color::hex(0x7a5c34);

/// The hill's top: concave, so the ground below it within the rounded square is convex.
double hill(double x) {
    return 0.26 + 0.11 * std::sin(std::numbers::pi * x);
}

struct Frame {
    charts::Rect area;
    Vec2 at(double x, double y) const { return {area.x + x * area.w, area.y + y * area.h}; }
    double size(double s) const { return s * std::min(area.w, area.h); }
};

/// The rounded square's outline from angle a0 to a1 around the corner centred at c.
void cornerArc(std::vector<Vec2>& out, Vec2 c, double a0, double a1) {
    constexpr int kSteps = 12;
    for (int i = 0; i <= kSteps; ++i) {
        const double a = a0 + (a1 - a0) * i / kSteps;
        out.push_back({c.x + kCorner * std::cos(a), c.y + kCorner * std::sin(a)});
    }
}

/// The part of the rounded square at or below height `top` (x from 0 to 1 along the
/// top is the caller's), counter-clockwise from the right side down.
std::vector<Vec2> roundedBottom() {
    constexpr double pi = std::numbers::pi;
    std::vector<Vec2> p;
    cornerArc(p, {1.0 - kCorner, kCorner}, 0.0, -pi / 2);
    cornerArc(p, {kCorner, kCorner}, -pi / 2, -pi);
    return p;
}

void drawSky(Renderer2D& r, const Frame& f) {
    constexpr double pi = std::numbers::pi;
    std::vector<Vec2> outline = roundedBottom();
    cornerArc(outline, {kCorner, 1.0 - kCorner}, pi, pi / 2);
    cornerArc(outline, {1.0 - kCorner, 1.0 - kCorner}, pi / 2, 0.0);
    for (Vec2& v : outline)
        v = f.at(v.x, v.y);
    r.fillConvex(outline, kSky);
    // The horizon's glow: lighter towards the ground, inside the straight sides.
    r.fillRectGradient(f.at(0.0, kCorner), f.at(1.0, 0.62), kSkyLow, kSky);
}

void drawGround(Renderer2D& r, const Frame& f) {
    std::vector<Vec2> ground = roundedBottom();
    constexpr int kSteps = 24;
    for (int i = 0; i <= kSteps; ++i) {
        const double x = static_cast<double>(i) / kSteps;
        ground.push_back({x, hill(x)});
    }
    for (Vec2& v : ground)
        v = f.at(v.x, v.y);
    r.fillConvex(ground, kGround);
}

void drawTower(Renderer2D& r, const Frame& f, double x0, double width) {
    const double base = hill(x0 + width) - 0.01, h = 0.085;
    for (int i = 0; i < 3; ++i) {
        const double inset = i == 2 ? 0.02 : 0.0;
        r.fillRectGradient(f.at(x0 + inset, base + i * h),
                           f.at(x0 + width - inset, base + (i + 1) * h), kBlockEdge, kBlock);
    }
}

/// The cannon at `pivot` and the shot it fires at `target`, by the game's firing solution.
void drawShot(Renderer2D& r, const Frame& f, Vec2 pivot, Vec2 target, int dots) {
    const double a = kLaunchDeg * std::numbers::pi / 180.0;
    const Vec2 dir{std::cos(a), std::sin(a)};
    const Vec2 muzzle = pivot + dir * 0.17;
    // The speed that lands the shot on the target at this elevation: on the parabola,
    // dy = dx tan(a) - g dx^2 / (2 v^2 cos^2 a).
    const double dx = target.x - muzzle.x, dy = target.y - muzzle.y;
    const double v =
        std::sqrt(kGravity * dx * dx / (2.0 * std::cos(a) * std::cos(a) * (dx * std::tan(a) - dy)));
    const double flight = dx / (v * std::cos(a));
    const Vec2 g{0.0, -kGravity};
    for (int i = 1; i <= dots; ++i) {
        const double t = flight * 0.8 * i / dots;
        const Vec2 p = phys::ballisticState(muzzle, dir * v, g, t).position;
        r.fillCircle(f.at(p.x, p.y), f.size(0.014), kArc, 0.6f);
    }
    const Vec2 shell = phys::ballisticState(muzzle, dir * v, g, flight * 0.9).position;
    r.fillCircle(f.at(shell.x, shell.y), f.size(0.045), kShell, 1.0f);
    // The barrel: a thick line from the pivot out along the elevation, then the wheel.
    r.line(f.at(pivot.x, pivot.y), f.at(muzzle.x, muzzle.y), kIron,
           static_cast<float>(f.size(0.085)));
    r.fillCircle(f.at(pivot.x, pivot.y - 0.02), f.size(0.065), kWheel, 1.0f);
    r.fillCircle(f.at(pivot.x, pivot.y - 0.02), f.size(0.022), kIron, 0.5f);
}

constexpr const char* kIconUsage = R"(usage: artillery icon --size N --png FILE [--json]

Draws the game's icon (a cannon on a hill, the arc of its shot, the shell coming down on
a tower of blocks) as an N x N PNG with transparent corners, headless (OSMesa, EGL
fallback), with the game's own renderer. The install draws it at the sizes of the
desktop's icon theme.

  --size N     width and height in pixels, 16..1024
  --png FILE   where to write the picture (.png)
  --json       {"png":FILE,"size":N}
)";

int runIcon(const game::cli::Args& args, std::ostream& out) {
    const int size = static_cast<int>(args.integer("size", 0, 16, 1024));
    if (!args.has("size")) args.fail("--size N is required (16..1024)");
    const std::string png = args.text("png", "");
    const bool json = args.flag("json");
    args.rejectUnknown();
    if (png.empty()) args.fail("--png FILE is required");
    if (std::filesystem::path(png).extension() != ".png")
        args.fail("--png expects a file name ending in .png, got '" + png + "'");
    const std::string error = charts::renderChartPng(
        png, size, size, [](Renderer2D& r, charts::Rect area) { drawGameIcon(r, area); },
        Color{0, 0, 0, 0});
    if (!error.empty()) {
        std::cerr << "artillery icon: cannot draw " << png << ": " << error << "\n";
        return game::cli::kCheckFailed;
    }
    if (json)
        out << nlohmann::json{{"png", png}, {"size", size}}.dump() << "\n";
    else
        out << "wrote " << png << " (" << size << "x" << size << ")\n";
    return game::cli::kOk;
}

} // namespace

void drawGameIcon(Renderer2D& r, charts::Rect area) {
    const Frame f{area};
    drawSky(r, f);
    drawGround(r, f);
    const double towerX = 0.72, towerW = 0.14;
    drawTower(r, f, towerX, towerW);
    // Fewer, larger-looking dots on a small icon: about one per 10 pixels of arc.
    const int dots = std::clamp(static_cast<int>(area.w / 14.0), 4, 11);
    const Vec2 pivot{0.24, hill(0.24) + 0.06};
    drawShot(r, f, pivot, {towerX + 0.5 * towerW, hill(towerX + towerW) + 3 * 0.085 - 0.01}, dots);
}

const game::cli::Verb& iconVerb() {
    static const game::cli::Verb verb{
        "icon", "the game's icon as a PNG of any size, drawn headless", kIconUsage, {}, runIcon};
    return verb;
}

} // namespace ui
