// Each weapon is drawn distinctly: a shell of each, drawn by the window's code at the
// same place in the same headless frame, shows a centre colour of its own, different
// from every other weapon's and from the plain cannonball's.
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

#include <array>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

using phys::Vec2;

const char* kNames[] = {"cannonball", "cluster",  "bouncer", "roller", "grenade",
                        "mortar",     "airburst", "digger",  "sticky"};

game::Level arena(const std::string& weapon) {
    return game::parseLevel("arena.json", R"({"format": 1, "name": "arena",
      "world": {"min": [0, -10], "max": [100, 60]}, "physics": {"drag": false},
      "terrain": {"points": [[0, 0], [100, 0]]},
      "cannons": [{"position": [10, 2], "projectiles": [")" +
                                              weapon + R"("]}],
      "targets": [{"position": [95, 50], "radius": 1}]})");
}

TEST(WeaponLook, EveryWeaponHasACentreColourOfItsOwn) {
    std::string error;
    auto context = ui::createHeadlessContext(640, 360, ui::HeadlessBackend::Auto, error);
    ASSERT_TRUE(context) << "no headless GL context (OSMesa or EGL): " << error;
    ASSERT_STREQ(ui::gl::loadGL(context->procAddress()), "");
    ui::ImGuiLayer imgui(*context, nullptr);
    ui::Renderer2D renderer;
    std::vector<std::array<int, 3>> centres;
    for (const char* name : kNames) {
        game::Match m(arena(name));
        game::Command c;
        c.kind = game::CommandKind::Aim;
        c.number = 45.0;
        ASSERT_EQ(m.apply(c), "");
        c.kind = game::CommandKind::Power;
        c.number = 20.0;
        ASSERT_EQ(m.apply(c), "");
        c.kind = game::CommandKind::Fire;
        ASSERT_EQ(m.apply(c), "");
        for (int i = 0; i < 40; ++i)
            m.step(); // rising, 1/3 s in: before any apex or contact
        ASSERT_TRUE(m.shell()) << name;
        ui::MatchView view;
        ui::MatchViewOptions o;
        o.hud = false;
        o.trajectoryPreview = false;
        o.trails = false;
        o.effects = false;
        const ui::Camera camera = ui::levelCamera(m, 640, 360);
        imgui.newFrame(1.0 / 60.0);
        ui::drawMatchFrame(renderer, view, m, camera, o);
        imgui.drawLabels(renderer.labels());
        imgui.render();
        context->present();
        const ui::Image img = ui::readFramebuffer(context->framebuffer(), 640, 360);
        const Vec2 p = camera.toPixel(m.world().particles.position(*m.shell()));
        const std::uint8_t* px = img.pixel(static_cast<int>(p.x), static_cast<int>(p.y));
        centres.push_back({px[0], px[1], px[2]});
    }
    for (std::size_t i = 0; i < centres.size(); ++i)
        for (std::size_t j = i + 1; j < centres.size(); ++j) {
            int d = 0;
            for (int k = 0; k < 3; ++k)
                d = std::max(d, std::abs(centres[i][k] - centres[j][k]));
            EXPECT_GT(d, 24) << kNames[i] << " and " << kNames[j] << " look alike at their centre";
        }
}

} // namespace
