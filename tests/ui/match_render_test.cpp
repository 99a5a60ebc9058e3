// Headless pictures of a match: a fixed tick of levels/01_earth_basics.json
// drawn by MatchView (the window's drawing code, HUD included) matches the stored
// reference within a tolerance that still catches a missing object, and cannons and
// targets land on the pixels the camera maps them to.
//
// Regenerating the reference, on purpose only (a change to how the game looks, in the
// same commit as that change):
//   ARTILLERY_WRITE_REFERENCE=1 build/tests/ui_tests --gtest_filter='MatchRender.*'
// writes tests/data/earth_basics_tick90.png; look at it before committing it.
#include "game/level.h"
#include "game/session.h"
#include "ui/game/cloth_view.h"
#include "ui/game/match_frame.h"
#include "ui/game/match_view.h"
#include "ui/platform/gl_context.h"
#include "ui/platform/imgui_layer.h"
#include "ui/render/gl.h"
#include "ui/render/renderer2d.h"
#include "ui/render/screenshot.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>

namespace {

using phys::Color;
using phys::Vec2;

constexpr int kW = 640;
constexpr int kH = 360;

std::string sourceDir() {
    return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path().string();
}
std::string referencePath() { return sourceDir() + "/tests/data/earth_basics_tick90.png"; }

/// A headless context with ImGui (for the HUD's text) and the renderer.
struct Headless {
    std::unique_ptr<ui::GLContext> context;
    std::unique_ptr<ui::ImGuiLayer> imgui;
    std::unique_ptr<ui::Renderer2D> renderer;

    int w, h;
    explicit Headless(int width = kW, int height = kH) : w(width), h(height) {
        std::string error;
        context = ui::createHeadlessContext(w, h, ui::HeadlessBackend::Auto, error);
        if (!context) return;
        EXPECT_STREQ(ui::gl::loadGL(context->procAddress()), "");
        imgui = std::make_unique<ui::ImGuiLayer>(*context, nullptr);
        renderer = std::make_unique<ui::Renderer2D>();
    }
    ~Headless() {
        renderer.reset();
        imgui.reset();
    }

    ui::Image draw(const game::Match& match, ui::MatchView& view, const ui::MatchViewOptions& o,
                   ui::Camera* usedCamera = nullptr) {
        const ui::Camera camera = ui::levelCamera(match, w, h);
        if (usedCamera) *usedCamera = camera;
        imgui->newFrame(1.0 / 60.0);
        ui::drawMatchFrame(*renderer, view, match, camera, o);
        imgui->drawLabels(renderer->labels());
        imgui->render();
        context->present();
        return ui::readFramebuffer(context->framebuffer(), w, h);
    }
};

/// Level 01 after a scripted shot: aimed, fired at tick 0, the shell in the air at 90.
std::unique_ptr<game::Session> fixedMatch(game::Level level, ui::MatchView& view) {
    auto session = std::make_unique<game::Session>(level);
    game::Command aim;
    aim.kind = game::CommandKind::Aim;
    aim.number = 38.0;
    game::Command power;
    power.kind = game::CommandKind::Power;
    power.number = 33.0;
    game::Command fire;
    fire.kind = game::CommandKind::Fire;
    for (const auto& c : {aim, power, fire}) EXPECT_EQ(session->submit(c), "");
    for (int i = 0; i < 90; ++i) {
        session->step();
        view.observe(session->match());
    }
    return session;
}

/// Pixels whose largest channel difference exceeds 64: a changed object, not an
/// anti-aliasing or rounding wobble at an edge.
int differingPixels(const ui::Image& a, const ui::Image& b) {
    int n = 0;
    for (std::size_t i = 0; i + 3 < a.rgba.size(); i += 4) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a.rgba[i + c] - b.rgba[i + c]));
        n += worst > 64;
    }
    return n;
}

/// Allowed: a few dozen pixels (a glyph edge, a rounded coordinate). The smallest object
/// in the frame, the 1.2 m target at 210 m, covers about 20 pixels at this size, so it
/// is checked separately below that removing it exceeds the tolerance.
constexpr int kTolerancePixels = 12;

ui::Image loadPng(const std::string& path) {
    ui::Image img;
    int n = 0;
    unsigned char* px = stbi_load(path.c_str(), &img.width, &img.height, &n, 4);
    if (!px) return img;
    img.rgba.assign(px, px + static_cast<std::size_t>(img.width) * img.height * 4);
    stbi_image_free(px);
    return img;
}

bool near(const std::uint8_t* p, Color c, int tol) {
    return std::abs(p[0] - static_cast<int>(std::lround(c.r * 255))) <= tol &&
           std::abs(p[1] - static_cast<int>(std::lround(c.g * 255))) <= tol &&
           std::abs(p[2] - static_cast<int>(std::lround(c.b * 255))) <= tol;
}

TEST(MatchRender, FixedTickOfEarthBasicsMatchesTheReference) {
    Headless h;
    ASSERT_TRUE(h.context) << "no headless GL context (OSMesa or EGL)";
    const game::Level level = game::loadLevel(sourceDir() + "/levels/01_earth_basics.json");
    ui::MatchView view;
    const auto session = fixedMatch(level, view);
    ASSERT_TRUE(session->match().shell().has_value()) << "the shell should be in flight at tick 90";
    const ui::Image frame = h.draw(session->match(), view, {});

    if (std::getenv("ARTILLERY_WRITE_REFERENCE")) {
        ASSERT_EQ(ui::writePng(referencePath(), frame), "");
        // Fails on purpose, so a run that rewrote the reference never passes for a check.
        FAIL() << "wrote " << referencePath() << " (look at it before committing, then rerun "
               << "without ARTILLERY_WRITE_REFERENCE)";
    }
    const ui::Image reference = loadPng(referencePath());
    ASSERT_EQ(reference.width, kW) << "missing or wrong-sized " << referencePath();
    ASSERT_EQ(reference.height, kH);
    const int diff = differingPixels(frame, reference);
    EXPECT_LE(diff, kTolerancePixels) << "the frame differs from the reference in " << diff
                                      << " pixels; if the look changed on purpose, regenerate it "
                                         "(see the top of this file)";

    // The tolerance catches a missing object: the same frame without the farthest,
    // smallest target differs by more than it allows.
    game::Level missing = level;
    missing.targets.pop_back();
    ui::MatchView view2;
    const auto session2 = fixedMatch(missing, view2);
    const ui::Image without = h.draw(session2->match(), view2, {});
    EXPECT_GT(differingPixels(without, reference), kTolerancePixels);
}

TEST(MatchRender, CannonsAndTargetsAreWhereTheCameraMapsThem) {
    Headless h(1280, 720);
    ASSERT_TRUE(h.context) << "no headless GL context (OSMesa or EGL)";
    const game::Match match(game::loadLevel(sourceDir() + "/levels/01_earth_basics.json"));
    ui::MatchView view;
    ui::MatchViewOptions o;
    o.hud = false;
    o.trajectoryPreview = false;
    ui::Camera camera;
    const ui::Image img = h.draw(match, view, o, &camera);
    auto pixel = [&](Vec2 world) {
        const Vec2 p = camera.toPixel(world);
        return img.pixel(static_cast<int>(p.x), static_cast<int>(p.y));
    };
    for (const game::TargetState& t : match.targets()) {
        // Bullseye rings from the centre out: white to 0.2 r, red to 0.45 r, white to
        // 0.72 r, red to r (drawn no smaller than 6 px).
        const double r = std::max(t.def.radius, camera.metres(6.0));
        EXPECT_TRUE(near(pixel(t.position), ui::targetWhite(), 16))
            << "target at " << t.position.x << " m: no white centre";
        EXPECT_TRUE(near(pixel(t.position + Vec2{0.32 * r, 0.0}), ui::targetRed(), 16))
            << "target at " << t.position.x << " m: no inner red ring";
        // The outer ring is a few pixels wide with a darker rim: red-dominant is enough.
        const auto* outer = pixel(t.position + Vec2{0.0, 0.86 * r});
        EXPECT_TRUE(outer[0] > outer[1] + 60 && outer[0] > outer[2] + 60)
            << "target at " << t.position.x << " m: no outer red ring";
    }
    // The cannon's carriage, in its team's colour darkened, right of the wheel and below
    // the barrel (aimed at 45 degrees).
    const double k = ui::cannonDrawScale(camera);
    const Color team = ui::teamColor(0);
    const Color carriage{team.r * 0.8f, team.g * 0.8f, team.b * 0.8f};
    EXPECT_TRUE(near(pixel(match.cannons()[0].def.position + Vec2{0.7 * k, -0.45 * k}), carriage, 16))
        << "no cannon carriage where the camera maps the cannon";
}

// The launch arc ends at half a second or at the least length on screen, whichever
// comes later: a straight path at 12 m/s, 0.1 m a tick of 1/120 s.
TEST(LaunchArc, EndsAtHalfASecondOrTheLeastLengthOnScreenWhicheverComesLater) {
    const double tick = 1.0 / 120.0;
    std::vector<Vec2> path;
    for (int i = 0; i <= 480; ++i)
        path.push_back({0.1 * i, 0.0});
    // 100 px a metre: 160 px is 1.6 m, 0.13 s in; the half second (tick 60) ends it.
    EXPECT_EQ(ui::launchArcPoints(path, tick, 0.01), 61u);
    // 0.049 m a pixel: 160 px is 7.84 m, passed at tick 79 (7.9 m), past the half second.
    EXPECT_EQ(ui::launchArcPoints(path, tick, 0.049), 80u);
    // 0.5 m a pixel: 160 px is 80 m, more than the path's 48 m: all of it.
    EXPECT_EQ(ui::launchArcPoints(path, tick, 0.5), path.size());
}

// On a map seen whole, the launch arc is drawn well clear of the cannon: on the crater
// duel (640 m between the cannons), half a second of the opening aim is about 25 px of
// a 1280 px window, hidden under the cannon's ring, so the arc runs on to 160 px of path.
// It stays a launch arc: it ends far short of the other cannon.
TEST(MatchRender, LaunchArcReachesClearOfTheCannonOnAMapSeenWhole) {
    Headless h(1280, 720);
    ASSERT_TRUE(h.context) << "no headless GL context (OSMesa or EGL)";
    const game::Match match(game::loadLevel(sourceDir() + "/levels/34_crater_duel.json"));
    ui::MatchView view;
    ui::MatchViewOptions o;
    o.hud = false;
    o.trajectoryPreview = false;
    ui::Camera camera;
    const ui::Image without = h.draw(match, view, o, &camera);
    o.trajectoryPreview = true;
    const ui::Image with = h.draw(match, view, o);
    const Vec2 muzzle = camera.toPixel(match.muzzle(match.cannon().angleDeg));
    double farthest = 0.0;
    for (int y = 0; y < with.height; ++y)
        for (int x = 0; x < with.width; ++x) {
            const std::uint8_t* a = with.pixel(x, y);
            const std::uint8_t* b = without.pixel(x, y);
            int worst = 0;
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(a[c] - b[c]));
            if (worst > 24) farthest = std::max(farthest, std::hypot(x - muzzle.x, y - muzzle.y));
        }
    const double metresPerPixel = camera.metres(1.0);
    EXPECT_LT(0.5 * match.cannon().speedMps / metresPerPixel, 40.0)
        << "the half second alone should be short on this map, or the test shows nothing";
    EXPECT_GT(farthest, 130.0) << "the arc's dots end " << farthest << " px from the muzzle";
    const Vec2 other = camera.toPixel(match.cannons()[1].def.position);
    EXPECT_LT(farthest, 0.5 * std::hypot(other.x - muzzle.x, other.y - muzzle.y))
        << "the launch arc should not run most of the way to the other cannon";
}

} // namespace

// A cloth is drawn as fabric: the middle of every cell between four of its particles is
// the cell's fill (the fabric shaded by the cell's stretch), where the sky was before
// the cloth was spawned, and no particle of it is drawn as a dot over it.
TEST(MatchRender, ClothIsDrawnAsFabricBetweenItsParticles) {
    Headless h(1280, 720);
    ASSERT_TRUE(h.context) << "no headless GL context (OSMesa or EGL)";
    game::Session session(game::loadLevel(sourceDir() + "/levels/11_sandbox.json"));
    ui::MatchView view;
    ui::MatchViewOptions o;
    o.hud = false;
    o.trajectoryPreview = false;
    ui::Camera camera;
    const ui::Image before = h.draw(session.match(), view, o, &camera);
    game::Command spawn;
    spawn.kind = game::CommandKind::Spawn;
    spawn.text = "cloth";
    spawn.at = {20.0, 14.0};
    spawn.number = 6.0;
    ASSERT_EQ(session.submit(spawn), "");
    for (int i = 0; i < 30; ++i) session.step();
    const ui::Image with = h.draw(session.match(), view, o);
    ASSERT_EQ(session.match().cloths().size(), 1u);
    const game::ClothState& cloth = session.match().cloths().front();
    const phys::ParticleSet& ps = session.match().world().particles;
    const int n = cloth.columns, rows = static_cast<int>(cloth.particles.size()) / n;
    ASSERT_GT(rows, 1);
    auto at = [&](int r, int c) { return ps.position(cloth.particles[static_cast<std::size_t>(r * n + c)]); };
    int cells = 0;
    for (int r = 0; r + 1 < rows; ++r)
        for (int c = 0; c + 1 < n; ++c) {
            const Vec2 q[] = {at(r, c), at(r, c + 1), at(r + 1, c + 1), at(r + 1, c)};
            double sides = 0.0;
            for (int k = 0; k < 4; ++k) sides += phys::length(q[(k + 1) % 4] - q[k]);
            const Vec2 mid = camera.toPixel((q[0] + q[1] + q[2] + q[3]) * 0.25);
            const int x = static_cast<int>(mid.x), y = static_cast<int>(mid.y);
            const Color fill = ui::clothFill(sides / (4.0 * cloth.spacing) - 1.0);
            EXPECT_TRUE(near(with.pixel(x, y), fill, 12)) << "cell " << r << ", " << c << " at " << x << ", " << y;
            EXPECT_FALSE(near(before.pixel(x, y), fill, 40)) << "the sky there was the fabric's colour already";
            ++cells;
        }
    EXPECT_EQ(cells, (rows - 1) * (n - 1));
}
