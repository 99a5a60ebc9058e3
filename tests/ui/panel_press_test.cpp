// A press on a panel is the panel's, also when it comes with the pointer's first move onto
// the panel (a tap on a touch screen, a quick flick and click): ImGui's capture flag then
// still describes where the pointer was when the last frame began. On the sandbox level,
// whose tool spawns a block where the world is pressed, a press on the Stats panel's
// header (folded, over the sky) spawns nothing, and one in the open sky spawns a block.
// A press the match refuses (a spawn outside the world) says why on the HUD for a while.
#include "headless_game.h"
#include "sdl_events.h"
#include "ui/game/game_screen.h"
#include "ui/platform/gl_context.h"
#include "ui/platform/imgui_layer.h"

#include <SDL.h>
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

using test_events::button;
using test_events::motion;

phys::Vec2 pixel(ImVec2 p) { return {p.x, p.y}; }

int spawns(const ui::GameScreen& screen) {
    int n = 0;
    for (const game::Command& c : screen.session()->recording().commands)
        n += c.kind == game::CommandKind::Spawn ? 1 : 0;
    return n;
}

/// The sandbox level on a headless game screen of 1280x720, with a settings folder of
/// this process's own (the panels start where they first open), two frames drawn.
struct Sandbox {
    fs::path settings = freshFolder();
    test_game::HeadlessGame game{"11_sandbox.json", 1280, 720, settings};
    std::unique_ptr<ui::GameScreen>& screen = game.screen;

    static fs::path freshFolder() {
        const fs::path f = fs::temp_directory_path() /
                           ("artillery-panel-press-test-" + std::to_string(::getpid()));
        fs::remove_all(f);
        fs::create_directories(f);
        return f;
    }
    ~Sandbox() {
        screen.reset();
        fs::remove_all(settings);
    }
    void click(ImVec2 at) {
        screen->handleEvent(button(SDL_MOUSEBUTTONDOWN, pixel(at)));
        screen->handleEvent(button(SDL_MOUSEBUTTONUP, pixel(at)));
        screen->frame(1.0 / 60.0);
    }
};

} // namespace

TEST(PanelPress, APressOnAPanelDoesNotReachTheWorldUnderIt) {
    Sandbox s;
    ASSERT_NE(s.screen, nullptr);
    const ImGuiWindow* panel = ImGui::FindWindowByName("Sandbox");
    ASSERT_NE(panel, nullptr);
    ASSERT_TRUE(panel->Active) << "drawn in the last frame";
    s.click(panel->Rect().GetCenter());
    EXPECT_EQ(spawns(*s.screen), 0) << "the press was the panel's";
    // The sky between the wind gauge and the Physics and Stats headers.
    const ImVec2 sky(800.0f, 250.0f);
    for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
        ASSERT_FALSE(w->Active && w->Rect().Contains(sky)) << w->Name;
    s.click(sky);
    EXPECT_EQ(spawns(*s.screen), 1) << "a press in the world spawns a block there";
}

TEST(PanelPress, ARefusedPressSaysWhyOnTheHudForAWhile) {
    Sandbox s;
    ASSERT_NE(s.screen, nullptr);
    EXPECT_EQ(s.screen->notice(), "");
    // Drag the view right with the right button until the left edge of the screen lies
    // left of the world (x = 0), and press there.
    const phys::Vec2 from{700.0, 450.0}, to{1100.0, 450.0};
    s.screen->handleEvent(button(SDL_MOUSEBUTTONDOWN, from, SDL_BUTTON_RIGHT));
    s.screen->handleEvent(motion(to, to - from));
    s.screen->handleEvent(button(SDL_MOUSEBUTTONUP, to, SDL_BUTTON_RIGHT));
    s.screen->frame(1.0 / 60.0);
    s.click(ImVec2(20.0f, 450.0f));
    EXPECT_EQ(spawns(*s.screen), 0) << "refused";
    EXPECT_EQ(s.screen->notice(), "spawn: spawn point is outside the world");
    for (int i = 0; i < 200; ++i) // 3.3 s of frames
        s.screen->frame(1.0 / 60.0);
    EXPECT_EQ(s.screen->notice(), "") << "for a while, not for ever";
}

// What a panel covers is known between frames (events) and inside the next frame before
// the panel is drawn again (the game's drawing, which keeps the target's close-up and the
// charts clear of the panels): the same rectangle both times; nothing for a folded one.
TEST(PanelPress, AnOpenPanelsRectangleIsKnownBetweenAndInsideFrames) {
    Sandbox s;
    ASSERT_NE(s.screen, nullptr);
    const ImGuiWindow* tools = ImGui::FindWindowByName("Sandbox");
    ASSERT_NE(tools, nullptr);
    const auto between = ui::openWindowRect("Sandbox");
    ASSERT_TRUE(between) << "the sandbox's tools open with the sandbox";
    EXPECT_DOUBLE_EQ(between->x0, tools->Pos.x);
    EXPECT_DOUBLE_EQ(between->y1, tools->Pos.y + tools->Size.y);
    EXPECT_FALSE(ui::openWindowRect("Stats")) << "folded";
    EXPECT_FALSE(ui::openWindowRect("no such panel"));
    ImGui::NewFrame(); // the next frame has begun; the panels are not drawn yet
    const auto inside = ui::openWindowRect("Sandbox");
    ImGui::EndFrame();
    ASSERT_TRUE(inside);
    EXPECT_EQ(inside->x0, between->x0);
    EXPECT_EQ(inside->y0, between->y0);
    EXPECT_EQ(inside->x1, between->x1);
    EXPECT_EQ(inside->y1, between->y1);
}
