// A blast drawn headlessly: the frame just after a cannonball bursts shows the flash, and
// a frame a quarter second later shows debris in the air above the ground, in the
// effects' colours (ui/game/effects_view.cpp); the same frames drawn with the effects
// off show neither, so the check proves something.
#include "game/level.h"
#include "game/match.h"
#include "ui/game/match_frame.h"
#include "ui/game/match_view.h"
#include "ui/platform/gl_context.h"
#include "ui/platform/imgui_layer.h"
#include "ui/render/gl.h"
#include "ui/render/renderer2d.h"
#include "ui/render/screenshot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>

namespace {

using phys::Vec2;

std::string sourceDir() {
    return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path().string();
}

constexpr int kW = 1280, kH = 720;

/// Pixels within `tol` of the colour (per channel); with `near` set, only those above the
/// ground line and within 12 m of it (the blast's neighbourhood, not the cannon's wheel).
int countColour(const ui::Image& img, int r, int g, int b, int tol, const ui::Camera& cam,
                const game::Match& m, const Vec2* near = nullptr) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.pixel(x, y);
            if (std::abs(p[0] - r) > tol || std::abs(p[1] - g) > tol || std::abs(p[2] - b) > tol)
                continue;
            if (near) {
                const Vec2 w = cam.toWorld({x + 0.5, y + 0.5});
                if (w.y < m.terrain().heightAt(w.x) + cam.metres(4.0) || length(w - *near) > 12.0)
                    continue;
            }
            ++n;
        }
    return n;
}

struct Frames {
    std::unique_ptr<ui::GLContext> context;
    std::unique_ptr<ui::ImGuiLayer> imgui;
    std::unique_ptr<ui::Renderer2D> renderer;
    Frames() {
        std::string error;
        context = ui::createHeadlessContext(kW, kH, ui::HeadlessBackend::Auto, error);
        if (!context) return;
        EXPECT_STREQ(ui::gl::loadGL(context->procAddress()), "");
        imgui = std::make_unique<ui::ImGuiLayer>(*context, nullptr);
        renderer = std::make_unique<ui::Renderer2D>();
    }
    ~Frames() {
        renderer.reset();
        imgui.reset();
    }
    ui::Image draw(const game::Match& m, ui::MatchView& view, bool effects, const ui::Camera& cam) {
        ui::MatchViewOptions o;
        o.hud = false;
        o.effects = effects;
        imgui->newFrame(1.0 / 60.0);
        ui::drawMatchFrame(*renderer, view, m, cam, o);
        imgui->drawLabels(renderer->labels());
        imgui->render();
        context->present();
        return ui::readFramebuffer(context->framebuffer(), kW, kH);
    }
};

TEST(EffectsPng, ABlastFrameShowsTheFlashThenDebris) {
    Frames f;
    ASSERT_TRUE(f.context) << "no headless GL context (OSMesa or EGL)";
    game::Level level = game::loadLevel(sourceDir() + "/levels/01_earth_basics.json");
    level.physics.windMin = level.physics.windMax = 0.0;
    game::Match m(level);
    ui::MatchView view;
    for (auto [kind, number] : {std::pair{game::CommandKind::Aim, 45.0},
                                {game::CommandKind::Power, 18.0},
                                {game::CommandKind::Fire, 0.0}}) {
        game::Command c;
        c.kind = kind;
        c.number = number;
        ASSERT_EQ(m.apply(c), "");
    }
    // Until the cannonball bursts on the open ground before the first target.
    const game::GameEvent* burst = nullptr;
    for (int k = 0; k < 1200 && !burst; ++k) {
        m.step();
        view.observe(m);
        for (const game::GameEvent& e : m.events())
            if (e.kind == game::EventKind::Burst) burst = &e;
    }
    ASSERT_NE(burst, nullptr);
    // Framed as the camera frames an impact: 2.2 times the level's zoom, on the burst.
    ui::Camera cam = ui::levelCamera(m, kW, kH);
    cam.pixelsPerMetre *= 2.2;
    cam.center = burst->where + Vec2{0.0, cam.metres(0.15 * kH)};

    // The flash's core (#fff6d8) the tick after the burst.
    const ui::Image flashOn = f.draw(m, view, true, cam);
    const ui::Image flashOff = f.draw(m, view, false, cam);
    const int flash = countColour(flashOn, 0xff, 0xf6, 0xd8, 24, cam, m);
    const int flashWithout = countColour(flashOff, 0xff, 0xf6, 0xd8, 24, cam, m);
    EXPECT_GE(flash - flashWithout, 200)
        << "flash pixels: " << flash << " with effects, " << flashWithout << " without";
    // The glow (#ffa630) around it.
    EXPECT_GE(countColour(flashOn, 0xff, 0xa6, 0x30, 60, cam, m) -
                  countColour(flashOff, 0xff, 0xa6, 0x30, 60, cam, m),
              100);

    // A quarter second on: soil (#5a3e26) and dust (#a08c70 over the sky) in the air.
    for (int k = 0; k < 30; ++k) {
        m.step();
        view.observe(m);
    }
    const ui::Image debrisOn = f.draw(m, view, true, cam);
    const ui::Image debrisOff = f.draw(m, view, false, cam);
    const Vec2 at = burst->where;
    const int soil = countColour(debrisOn, 0x5a, 0x3e, 0x26, 20, cam, m, &at);
    EXPECT_GE(soil, 40) << "soil pieces above the ground";
    EXPECT_LE(countColour(debrisOff, 0x5a, 0x3e, 0x26, 20, cam, m, &at), 2);
    EXPECT_GT(view.effects().pieces().count(), 20u);

    if (std::getenv("ARTILLERY_WRITE_EFFECTS_PNG")) {
        EXPECT_EQ(ui::writePng("effects_flash.png", flashOn), "");
        EXPECT_EQ(ui::writePng("effects_debris.png", debrisOn), "");
    }
}

} // namespace
