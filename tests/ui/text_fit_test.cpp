// No text is cut: every ImGui window drawn on the play screens (the lab's panels too), a
// replay, the pause menu, the help, the lesson and the editor lies inside the display and
// holds what it draws (nothing reaches past its right edge, which would be clipped: its
// horizontal scroll range is 0), at 1280 x 720 and on a smaller 1024 x 600 window; and
// every line of the HUD lies inside the box drawn for it, measured in the font it is
// drawn in, whatever the projectile's description, on a duel and on the end card.
#include "headless_game.h"
#include "game/session.h"
#include "ui/game/match_frame.h"
#include "ui/game/match_view.h"
#include "ui/game/screen_layout.h"
#include "ui/platform/imgui_layer.h"
#include "ui/render/gl.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <functional>
#include <memory>
#include <string>

namespace {

namespace fs = std::filesystem;

/// Every window drawn in the last frame (child windows too) lies inside the display and
/// has nothing past its right edge; one the game sizes (not a child, not one the player
/// resizes, whose height is the player's and scrolls) also has nothing past its bottom
/// unless it reached the display's height (then it scrolls).
void expectWindowsFit(const std::string& where, int width, int height) {
    int seen = 0;
    for (const ImGuiWindow* w : GImGui->Windows) {
        if (!w->Active || w->Hidden || std::string(w->Name).starts_with("Debug##")) continue;
        ++seen;
        const std::string what = where + ", window \"" + w->Name + "\"";
        EXPECT_EQ(w->ScrollMax.x, 0.0f) << what << ": " << w->ScrollMax.x << " px of it cut at the right";
        EXPECT_GE(w->Pos.x, 0.0f) << what;
        EXPECT_GE(w->Pos.y, 0.0f) << what;
        EXPECT_LE(w->Pos.x + w->Size.x, static_cast<float>(width)) << what;
        EXPECT_LE(w->Pos.y + w->Size.y, static_cast<float>(height)) << what;
        const bool child = (w->Flags & ImGuiWindowFlags_ChildWindow) != 0;
        const bool sized = (w->Flags & (ImGuiWindowFlags_NoResize | ImGuiWindowFlags_AlwaysAutoResize)) != 0;
        if (!child && sized && w->Size.y < 0.9f * static_cast<float>(height)) {
            EXPECT_EQ(w->ScrollMax.y, 0.0f) << what << ": " << w->ScrollMax.y << " px of it cut at the bottom";
        }
    }
    EXPECT_GT(seen, 0) << where << ": no window drawn";
}

void frames(ui::GameScreen& screen, int n) {
    for (int i = 0; i < n; ++i) screen.frame(1.0 / 60.0);
}

struct Size {
    int w, h;
};
constexpr Size kSizes[] = {{1280, 720}, {1024, 600}};

std::string at(const char* what, Size s) {
    return std::string(what) + " at " + std::to_string(s.w) + "x" + std::to_string(s.h);
}

} // namespace

TEST(TextFits, ThePlayScreensPanelsHoldWhatTheyDraw) {
    for (const Size s : kSizes)
        for (const char* level : {"01_earth_basics.json", "10_duel.json", "40_scatter.json", "11_sandbox.json"}) {
            test_game::ScratchFolder scratch("text-fit-play");
            test_game::HeadlessGame game(level, s.w, s.h, scratch.dir);
            ASSERT_NE(game.screen, nullptr);
            frames(*game.screen, 3);
            expectWindowsFit(at(level, s), s.w, s.h);
        }
}

TEST(TextFits, TheLabsPanelsHoldWhatTheyDraw) {
    for (const Size s : kSizes) {
        test_game::ScratchFolder scratch("text-fit-lab");
        test_game::HeadlessGame game("05_castle.json", s.w, s.h, scratch.dir);
        ASSERT_NE(game.screen, nullptr);
        for (const SDL_Keycode key : {SDLK_F2, SDLK_F3, SDLK_F6}) test_game::tap(*game.screen, key);
        frames(*game.screen, 4);
        for (const char* name : {"Physics", "Stats", "Cost"}) {
            const ImGuiWindow* w = ImGui::FindWindowByName(name);
            ASSERT_NE(w, nullptr) << name;
            EXPECT_TRUE(w->Active) << at(name, s);
        }
        expectWindowsFit(at("the lab's panels", s), s.w, s.h);
    }
}

TEST(TextFits, TheReplaysPanelHoldsWhatItDraws) {
    for (const Size s : kSizes) {
        ui::GameScreenDef def;
        def.replayFile = (test_game::kRoot / "tests" / "replays" / "39_crows_nests.replay.json").string();
        test_game::HeadlessGame game(def, s.w, s.h);
        ASSERT_NE(game.screen, nullptr);
        ui::GameScreen& screen = *game.screen;
        screen.warmUp(4.0);
        frames(screen, 3);
        ASSERT_NE(screen.replayViewer(), nullptr);
        expectWindowsFit(at("a replay", s), s.w, s.h);
    }
}

TEST(TextFits, ThePauseMenuAndTheHelpHoldWhatTheyDraw) {
    for (const Size s : kSizes) {
        test_game::ScratchFolder scratch("text-fit-pause");
        test_game::HeadlessGame game("01_earth_basics.json", s.w, s.h, scratch.dir);
        ASSERT_NE(game.screen, nullptr);
        test_game::tap(*game.screen, SDLK_ESCAPE);
        frames(*game.screen, 3);
        ASSERT_NE(ImGui::FindWindowByName("Paused"), nullptr);
        EXPECT_TRUE(ImGui::FindWindowByName("Paused")->Active) << at("the pause menu", s);
        expectWindowsFit(at("the pause menu", s), s.w, s.h);
        test_game::tap(*game.screen, SDLK_F1);
        frames(*game.screen, 3);
        ASSERT_NE(ImGui::FindWindowByName("Help"), nullptr);
        EXPECT_TRUE(ImGui::FindWindowByName("Help")->Active) << at("the help", s);
        expectWindowsFit(at("the help", s), s.w, s.h);
    }
}

TEST(TextFits, TheEditorHoldsWhatItDraws) {
    for (const Size s : kSizes) {
        test_game::ScratchFolder scratch("text-fit-editor");
        ui::GameScreenDef def = test_game::HeadlessGame::levelDef("05_castle.json", scratch.dir);
        def.edit = true;
        test_game::HeadlessGame game(def, s.w, s.h);
        ASSERT_NE(game.screen, nullptr);
        ui::GameScreen& screen = *game.screen;
        frames(screen, 2);
        ASSERT_NE(screen.levelEditor(), nullptr);
        ASSERT_NE(ImGui::FindWindowByName("##editorhint"), nullptr);
        expectWindowsFit(at("the editor", s), s.w, s.h);
        // The rope tool's hint is the longest.
        test_game::tap(screen, SDLK_6);
        frames(screen, 3);
        expectWindowsFit(at("the editor's rope tool", s), s.w, s.h);
    }
}

TEST(TextFits, TheLessonHoldsWhatItDraws) {
    for (const Size s : kSizes) {
        test_game::ScratchFolder scratch("text-fit-lesson");
        ui::GameScreenDef def;
        def.settingsFolder = scratch.dir.string();
        test_game::HeadlessGame game(def, s.w, s.h);
        ASSERT_NE(game.screen, nullptr);
        ui::GameScreen& screen = *game.screen;
        ImGuiIO& io = ImGui::GetIO();
        io.KeyMap[ImGuiKey_Enter] = SDL_SCANCODE_RETURN;
        frames(screen, 3);
        io.KeysDown[SDL_SCANCODE_RETURN] = true;
        frames(screen, 1);
        io.KeysDown[SDL_SCANCODE_RETURN] = false;
        frames(screen, 3);
        const ImGuiWindow* lesson = ImGui::FindWindowByName("Lesson");
        ASSERT_NE(lesson, nullptr);
        EXPECT_TRUE(lesson->Active) << at("the lesson", s);
        expectWindowsFit(at("the lesson", s), s.w, s.h);
    }
}

namespace {

/// A match drawn by MatchView with its HUD and layout, through ImGui (the labels' font).
struct HudFrame {
    std::unique_ptr<ui::GLContext> context;
    std::unique_ptr<ui::ImGuiLayer> imgui;
    std::unique_ptr<ui::Renderer2D> renderer;
    ui::MatchView view;
    ui::ScreenLayout layout;

    HudFrame() {
        std::string error;
        context = ui::createHeadlessContext(1280, 720, ui::HeadlessBackend::Auto, error);
        EXPECT_NE(context, nullptr) << error;
        if (!context) return;
        EXPECT_STREQ(ui::gl::loadGL(context->procAddress()), "");
        imgui = std::make_unique<ui::ImGuiLayer>(*context, nullptr);
        renderer = std::make_unique<ui::Renderer2D>();
    }
    ~HudFrame() {
        renderer.reset();
        imgui.reset();
    }

    /// Draws `m` and checks that every line the HUD wrote lies inside one of its boxes.
    void expectLinesInBoxes(const game::Match& m, const std::string& what) {
        imgui->newFrame(1.0 / 60.0);
        layout.clear(1280, 720);
        ui::MatchViewOptions o;
        o.layout = &layout;
        ui::drawMatchFrame(*renderer, view, m, ui::levelCamera(m, 1280, 720), o);
        int lines = 0;
        for (const ui::Label& l : renderer->labels()) {
            if (l.world) continue;
            ++lines;
            const ui::PixelRect r = ui::labelRect(l);
            bool held = false;
            for (const ui::LayoutOverlay& box : layout.overlays)
                held = held || ((box.name.starts_with("hud.") || box.name == "card") && ui::inside(r, box.rect));
            EXPECT_TRUE(held) << what << ": \"" << l.text << "\" [" << r.x0 << ", " << r.x1
                              << "] lies in no box of the HUD";
        }
        EXPECT_GT(lines, 0) << what;
        imgui->drawLabels(renderer->labels());
        imgui->render();
    }
};

game::Command command(game::CommandKind kind, double number = 0.0, std::string text = "") {
    game::Command c;
    c.kind = kind;
    c.number = number;
    c.text = std::move(text);
    return c;
}

} // namespace

TEST(TextFits, EveryLineOfTheHudLiesInItsBox) {
    HudFrame frame;
    ASSERT_NE(frame.context, nullptr);
    for (const char* name : {"40_scatter.json", "39_crows_nests.json", "10_duel.json"}) {
        game::Session session(game::loadLevel((test_game::kRoot / "levels" / name).string()));
        for (const std::string& projectile : session.match().cannon().def.projectiles) {
            EXPECT_EQ(session.submit(command(game::CommandKind::Select, 0.0, projectile)), "") << projectile;
            session.step();
            frame.expectLinesInBoxes(session.match(), std::string(name) + " with " + projectile);
        }
    }
    // The end card: every shot of Earth basics fired into the ground before it.
    game::Session session(game::loadLevel((test_game::kRoot / "levels" / "01_earth_basics.json").string()));
    EXPECT_EQ(session.submit(command(game::CommandKind::Aim, 80.0)), "");
    for (int tick = 0; tick < 120 * 120 && !session.match().over(); ++tick) {
        if (!session.match().shell()) session.submit(command(game::CommandKind::Fire));
        session.step();
    }
    ASSERT_TRUE(session.match().over());
    frame.expectLinesInBoxes(session.match(), "the end card of Earth basics");
}
