// The physics panel's material and contact edits become `set` commands by the names of
// game/settings.h; applied to the match they came from, they give the edited settings.
// The panel of a match draws those controls (headless, through ImGui).
#include "game/level.h"
#include "game/match.h"
#include "ui/game/settings_commands.h"
#include "ui/platform/gl_context.h"
#include "ui/platform/imgui_layer.h"
#include "ui/play/physics_panel.h"
#include "ui/render/gl.h"
#include "ui/render/screenshot.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cstdlib>
#include <filesystem>
#include <memory>

namespace {
std::string levelFile(const char* name) {
    return (std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "levels" / name)
        .string();
}
} // namespace

TEST(SettingCommands, MaterialAndContactEditsBecomeSetCommandsThatReproduceThem) {
    game::Match m(game::loadLevel(levelFile("01_earth_basics.json")));
    const game::LiveSettings before = m.liveSettings();
    game::LiveSettings after = before;
    ASSERT_EQ(game::applySetting(after, "restitution.golf-ball", std::string("tennis")), "");
    ASSERT_EQ(game::applySetting(after, "restitution.tennis-ball", 0.4), "");
    ASSERT_EQ(game::applySetting(after, "pair.golf-ball.earth", 0.5), "");
    ASSERT_EQ(game::applySetting(after, "contact_model", std::string("penalty")), "");
    ASSERT_EQ(game::applySetting(after, "continuous", false), "");

    const auto cmds = ui::settingCommands(before, after);
    ASSERT_EQ(cmds.size(), 5u);
    EXPECT_EQ(cmds[0].text, "contact_model");
    EXPECT_EQ(cmds[1].text, "continuous");
    EXPECT_EQ(cmds[2].text, "restitution.golf-ball");
    EXPECT_EQ(std::get<std::string>(cmds[2].value), "tennis");
    EXPECT_EQ(cmds[3].text, "restitution.tennis-ball");
    EXPECT_EQ(std::get<double>(cmds[3].value), 0.4);
    EXPECT_EQ(cmds[4].text, "pair.golf-ball.earth");
    for (const game::Command& c : cmds) EXPECT_EQ(m.apply(c), "") << c.text;
    for (const std::string& name : game::settingNames(after))
        EXPECT_EQ(game::readSetting(m.liveSettings(), name), game::readSetting(after, name)) << name;

    // Giving the pair back to the rule is one command, "combine".
    game::LiveSettings rule = after;
    ASSERT_EQ(game::applySetting(rule, "pair.golf-ball.earth", std::string("combine")), "");
    const auto back = ui::settingCommands(after, rule);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].text, "pair.golf-ball.earth");
    EXPECT_EQ(std::get<std::string>(back[0].value), "combine");
    EXPECT_TRUE(ui::settingCommands(after, after).empty());
}

TEST(PhysicsPanel, DrawsAMatchsContactAndMaterialControlsWithoutEditingThem) {
    constexpr int w = 480, h = 900;
    std::string error;
    auto context = ui::createHeadlessContext(w, h, ui::HeadlessBackend::Auto, error);
    ASSERT_TRUE(context) << "no headless GL context (OSMesa or EGL): " << error;
    ASSERT_STREQ(ui::gl::loadGL(context->procAddress()), "");
    auto imgui = std::make_unique<ui::ImGuiLayer>(*context, nullptr);
    game::Match m(game::loadLevel(levelFile("04_bank_shots.json")));
    game::LiveSettings s = m.liveSettings();
    ASSERT_EQ(game::applySetting(s, "pair.golf-ball.floor", 0.95), ""); // a row with "rule"
    const game::LiveSettings before = s;
    ui::TimeControls time;
    ui::ViewControls view;
    ui::SceneRequests scene;
    ui::FrameStats stats;
    bool edited = false;
    for (int frame = 0; frame < 3; ++frame) { // the first frames lay the window out
        imgui->newFrame(1.0 / 60.0);
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(static_cast<float>(w), static_cast<float>(h)));
        ImGui::SetNextWindowCollapsed(false);
        edited |= ui::physicsPanel(s, m.materialsInPlay(), time, view, scene, stats);
        imgui->render();
        context->present();
    }
    EXPECT_FALSE(edited);
    EXPECT_TRUE(ui::settingCommands(before, s).empty());
    const ui::Image img = ui::readFramebuffer(context->framebuffer(), w, h);
    int lit = 0;
    for (std::size_t i = 0; i + 3 < img.rgba.size(); i += 4) lit += img.rgba[i] > 200;
    EXPECT_GT(lit, 1000) << "the panel's text";
    if (const char* out = std::getenv("ARTILLERY_PANEL_PNG")) {
        EXPECT_EQ(ui::writePng(out, img), ""); // to look at the panel
    }
}
