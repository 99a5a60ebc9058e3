// The panels and the labels scale with the screen as the HUD does (a 1280x720 design
// canvas, ui/render/design_canvas.h): on a 4K screen a panel's text is as large, next to
// the HUD, as on a 720p one. A layout saved in one window size and loaded in another
// keeps each panel at its corner, its margins and size scaled.
#include "headless_game.h"
#include "sdl_events.h"
#include "ui/game/game_screen.h"
#include "ui/platform/gl_context.h"
#include "ui/platform/imgui_layer.h"
#include "ui/render/design_canvas.h"
#include "ui/render/gl.h"
#include "ui/render/renderer2d.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

/// The castle on a headless game screen of w x h, two frames drawn, then the lab's
/// Physics panel (F2) and Stats window (F6) opened and two frames more.
struct Castle : test_game::HeadlessGame {
    Castle(int w, int h, const fs::path& settings)
        : HeadlessGame("05_castle.json", w, h, settings) {
        if (!screen) return;
        for (const SDL_Keycode k : {SDLK_F2, SDLK_F6}) {
            screen->handleEvent(test_events::keyEvent(SDL_KEYDOWN, k));
            screen->handleEvent(test_events::keyEvent(SDL_KEYUP, k));
        }
        for (int i = 0; i < 2; ++i) screen->frame(1.0 / 60.0);
    }
};

struct Rect {
    float x0, y0, x1, y1;
};
Rect rectOf(const char* name) {
    const ImGuiWindow* w = ImGui::FindWindowByName(name);
    EXPECT_NE(w, nullptr) << name;
    if (!w) return {};
    return {w->Pos.x, w->Pos.y, w->Pos.x + w->Size.x, w->Pos.y + w->Size.y};
}

} // namespace

TEST(PanelScale, FollowsTheHudInQuarterStepsAndNeverShrinksTheText) {
    EXPECT_EQ(ui::panelScale(1280, 720), 1.0f);
    EXPECT_EQ(ui::panelScale(1920, 1080), 1.5f);
    EXPECT_EQ(ui::panelScale(2560, 1440), 2.0f);
    EXPECT_EQ(ui::panelScale(3840, 2160), 3.0f);
    EXPECT_EQ(ui::panelScale(1366, 768), 1.0f);  // 1.067: the next quarter is not reached
    EXPECT_EQ(ui::panelScale(3440, 1440), 2.0f); // ultra-wide: the height decides
    EXPECT_EQ(ui::panelScale(800, 600), 1.0f);   // the HUD shrinks to 0.625; the text does not
    EXPECT_EQ(ui::panelScale(7680, 4320), 3.0f); // as far as the HUD goes
}

TEST(PanelScale, APanelKeepsToItsNearestEdges) {
    // 1280 -> 2560 wide at twice the scale: a panel 10 px from the left is 20 px from it;
    // one 10 px from the right edge (at 890, 380 wide) is 20 px from the new right edge.
    EXPECT_FLOAT_EQ(ui::keepToNearestEdge(10, 300, 1280, 2560, 2), 20);
    EXPECT_FLOAT_EQ(ui::keepToNearestEdge(890, 380, 1280, 2560, 2), 2560 - 20 - 760);
    // A window made wider without a change of scale: the right panel follows the edge.
    EXPECT_FLOAT_EQ(ui::keepToNearestEdge(890, 380, 1280, 1600, 1), 1600 - 10 - 380);
    EXPECT_FLOAT_EQ(ui::keepToNearestEdge(12, 250, 1280, 1600, 1), 12);
}

TEST(PanelScale, PanelTextAndWorldLabelsAreTwiceAsLargeOnATwiceAsLargeScreen) {
    const fs::path settings =
        fs::temp_directory_path() / ("artillery-panel-scale-" + std::to_string(::getpid()));
    fs::remove_all(settings);
    float small = 0.0f, large = 0.0f;
    {
        Castle c(1280, 720, settings);
        ASSERT_NE(c.screen, nullptr);
        small = ImGui::GetFontSize();
    }
    fs::remove_all(settings); // no layout carried over: each starts where panels first open
    {
        Castle c(2560, 1440, settings);
        ASSERT_NE(c.screen, nullptr);
        large = ImGui::GetFontSize();
        const Rect controls = rectOf("Controls");
        // The turn's controls sit beside the aim readout at the bottom left, as at 720p,
        // and their text is twice as large, so their row is about twice as tall.
        EXPECT_NEAR(controls.x0, 2 * 336.0, 1.0);
        EXPECT_NEAR(controls.y1, 1440 - 2 * 12.0, 1.0);
        EXPECT_GT(controls.y1 - controls.y0, 2 * 30.0);

        // A world label's size and nudge scale too; a label the caller laid out in
        // pixels (the HUD, the charts) is drawn at the size it asks for.
        // (the game screen loaded the GL functions for this context)
        ui::Renderer2D r;
        r.begin(ui::Camera::framing({0, 0}, {100, 50}, 2560, 1440));
        r.label({50, 25}, "range", ui::Color::hex(0xffffff), {4.0, -8.0}, 0.85f);
        r.screenLabel({12, 12}, "HUD", ui::Color::hex(0xffffff), 1.1f);
        ASSERT_EQ(r.labels().size(), 2u);
        EXPECT_FLOAT_EQ(r.labels()[0].scale, 2 * 0.85f);
        EXPECT_NEAR(r.labels()[0].pixel.x - r.camera().toPixel({50, 25}).x, 8.0, 1e-9);
        EXPECT_FLOAT_EQ(r.labels()[1].scale, 1.1f);
    }
    fs::remove_all(settings);
    EXPECT_FLOAT_EQ(large, 2 * small);
}

TEST(PanelScale, ALayoutSavedInASmallWindowIsMovedToFitALargeOne) {
    const fs::path settings =
        fs::temp_directory_path() / ("artillery-panel-layout-" + std::to_string(::getpid()));
    fs::remove_all(settings);
    Rect physics{}, stats{};
    {
        Castle c(1280, 720, settings);
        ASSERT_NE(c.screen, nullptr);
        physics = rectOf("Physics");
        stats = rectOf("Stats");
    } // the screen saves its layout as it closes
    {
        Castle c(2560, 1440, settings);
        ASSERT_NE(c.screen, nullptr);
        // The panels at the top right stay there, their margins and widths doubled.
        const Rect p = rectOf("Physics"), s = rectOf("Stats");
        EXPECT_NEAR(2560 - p.x1, 2 * (1280 - physics.x1), 2.0);
        EXPECT_NEAR(p.x1 - p.x0, 2 * (physics.x1 - physics.x0), 2.0);
        EXPECT_NEAR(p.y0, 2 * physics.y0, 2.0);
        EXPECT_NEAR(2560 - s.x1, 2 * (1280 - stats.x1), 2.0);
        EXPECT_NEAR(s.y0, 2 * stats.y0, 2.0);
    }
    fs::remove_all(settings);
}

// A damaged layout: a display size that is none (inf, 1e30) leaves the panels where the
// file put them; one that is a size, with a panel far off at its edge, moves it within
// what the layout can hold (ImGui keeps positions in shorts), not past it.
TEST(PanelScale, ADamagedLayoutIsTakenAsItIsOrMovedWithinBounds) {
    const fs::path settings =
        fs::temp_directory_path() / ("artillery-panel-damaged-" + std::to_string(::getpid()));
    auto layout = [&](const std::string& display) {
        fs::remove_all(settings);
        fs::create_directories(settings);
        std::ofstream(settings / "imgui.ini")
            << "[Window][Stats]\nPos=900,44\nSize=330,600\n\n"
               "[Window][Physics]\nPos=32000,32000\nSize=380,20\n\n"
               "[ArtilleryDisplay][Display]\nSize="
            << display << "\n";
    };
    layout("inf,1e30");
    {
        Castle c(2560, 1440, settings);
        ASSERT_NE(c.screen, nullptr);
        EXPECT_EQ(rectOf("Stats").x0, 900.0f) << "not a display: the layout as it is";
    }
    layout("640,360");
    {
        Castle c(2560, 1440, settings);
        ASSERT_NE(c.screen, nullptr);
        const Rect p = rectOf("Physics");
        EXPECT_TRUE(std::isfinite(p.x0) && std::isfinite(p.y0));
        EXPECT_LE(p.x0, 32767.0f);
    }
    fs::remove_all(settings);
}
