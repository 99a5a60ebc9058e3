// A press on a panel is the panel's, also when it comes with the pointer's first move onto
// the panel (a tap on a touch screen, a quick flick and click): ImGui's capture flag then
// still describes where the pointer was when the last frame began. On the sandbox level,
// whose tool spawns a block where the world is pressed, a press on the Stats panel's
// header (folded, over the sky) spawns nothing, and one in the open sky spawns a block.
#include "ui/game/game_screen.h"
#include "ui/platform/gl_context.h"

#include <SDL.h>
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

const fs::path kRoot = fs::path(__FILE__).parent_path().parent_path().parent_path();

SDL_Event button(Uint32 type, ImVec2 pixel) {
    SDL_Event e{};
    e.type = type;
    e.button.button = SDL_BUTTON_LEFT;
    e.button.x = static_cast<int>(pixel.x);
    e.button.y = static_cast<int>(pixel.y);
    return e;
}

int spawns(const ui::GameScreen& screen) {
    int n = 0;
    for (const game::Command& c : screen.session()->recording().commands)
        n += c.kind == game::CommandKind::Spawn ? 1 : 0;
    return n;
}

} // namespace

TEST(PanelPress, APressOnAPanelDoesNotReachTheWorldUnderIt) {
    // A settings folder of this process's own: the panels start where they first open.
    const fs::path settings =
        fs::temp_directory_path() / ("artillery-panel-press-test-" + std::to_string(::getpid()));
    fs::remove_all(settings);
    fs::create_directories(settings);
    std::string error;
    auto context = ui::createHeadlessContext(1280, 720, ui::HeadlessBackend::Auto, error);
    ASSERT_NE(context, nullptr) << error;
    {
        ui::GameScreenDef def;
        def.levelFile = (kRoot / "levels/11_sandbox.json").string();
        def.levelsFolder = (kRoot / "levels").string();
        def.settingsFolder = settings.string();
        ui::GameScreen screen(*context, nullptr, def);
        for (int i = 0; i < 2; ++i)
            screen.frame(1.0 / 60.0);
        const ImGuiWindow* panel = ImGui::FindWindowByName("Stats");
        ASSERT_NE(panel, nullptr);
        ASSERT_TRUE(panel->Active) << "drawn in the last frame";

        auto click = [&](ImVec2 at) {
            screen.handleEvent(button(SDL_MOUSEBUTTONDOWN, at));
            screen.handleEvent(button(SDL_MOUSEBUTTONUP, at));
            screen.frame(1.0 / 60.0);
        };
        click(panel->Rect().GetCenter());
        EXPECT_EQ(spawns(screen), 0) << "the press was the panel's";
        // The sky between the wind gauge and the Physics and Stats headers.
        const ImVec2 sky(800.0f, 250.0f);
        for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows)
            ASSERT_FALSE(w->Active && w->Rect().Contains(sky)) << w->Name;
        click(sky);
        EXPECT_EQ(spawns(screen), 1) << "a press in the world spawns a block there";
    }
    fs::remove_all(settings);
}
