// The card that follows a finished level: the next level (or why it is locked), another
// go at this one, the level select. A game of First shot played out without a star: its
// Retry button, pressed as a player presses it, starts the level again; the card opens
// where it stays.
#include "headless_game.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <optional>

namespace {

/// Every shot fired at the least power, so each lands at once, until the game is over and
/// the card is drawn; the card's window, or null.
ImGuiWindow* playOut(ui::GameScreen& screen) {
    for (int i = 0; i < 200; ++i) test_game::tap(screen, SDLK_DOWN);
    for (int frame = 0; frame < 60 * 120; ++frame) {
        const game::Match& m = screen.session()->match();
        if (m.over()) {
            ImGuiWindow* card = ImGui::FindWindowByName("Next level");
            if (card && card->Active) return card;
        } else if (!m.shell()) {
            test_game::tap(screen, SDLK_SPACE);
        }
        screen.frame(1.0 / 60.0);
    }
    return nullptr;
}

/// Where in `window` the pointer hovers the button `label`, found by moving over it.
/// Headless, ImGui takes no SDL events: the pointer is set on its IO, as its backend does.
std::optional<ImVec2> buttonIn(ui::GameScreen& screen, ImGuiWindow* window, const char* label) {
    const ImGuiID id = window->GetID(label);
    const ImRect r = window->Rect();
    for (float y = r.Min.y + 4.0f; y < r.Max.y; y += 8.0f)
        for (float x = r.Min.x + 4.0f; x < r.Max.x; x += 12.0f) {
            ImGui::GetIO().MousePos = ImVec2(x, y);
            screen.frame(1.0 / 60.0);
            if (ImGui::GetCurrentContext()->HoveredId == id) return ImVec2(x, y);
        }
    return std::nullopt;
}

} // namespace

TEST(NextCard, RetryPlaysTheLevelAgain) {
    test_game::ScratchFolder scratch("next-card");
    test_game::HeadlessGame game("12_first_shot.json", 1280, 720, scratch.dir);
    ASSERT_NE(game.screen, nullptr);
    ui::GameScreen& screen = *game.screen;
    ImGuiWindow* card = playOut(screen);
    ASSERT_NE(card, nullptr) << "the game ends and its card is drawn";
    EXPECT_EQ(screen.session()->match().stars(), 0);
    // It opens where it stays: only once the camera is home, so it does not hop about
    // as the view glides back (ImGui sizes it over its first two frames).
    for (int i = 0; i < 2; ++i) screen.frame(1.0 / 60.0);
    const ImVec2 opened = card->Pos;
    for (int i = 0; i < 180; ++i) {
        screen.frame(1.0 / 60.0);
        ASSERT_EQ(card->Pos.x, opened.x) << "frame " << i;
        ASSERT_EQ(card->Pos.y, opened.y) << "frame " << i;
    }
    const auto retry = buttonIn(screen, card, "Retry (R)");
    ASSERT_TRUE(retry) << "the card has a Retry button";
    // A press and a release on it, a frame each, as a click reaches ImGui.
    ImGui::GetIO().MouseDown[0] = true;
    screen.frame(1.0 / 60.0);
    ImGui::GetIO().MouseDown[0] = false;
    for (int i = 0; i < 2; ++i) screen.frame(1.0 / 60.0);
    const game::Match& again = screen.session()->match();
    EXPECT_FALSE(again.over());
    EXPECT_EQ(again.cannon().shotsLeft, again.level().shots) << "every shot back";
    EXPECT_EQ(again.score(), 0);
}
