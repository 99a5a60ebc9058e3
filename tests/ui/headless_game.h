// A level on a headless game screen, as the window would show it, for the tests that
// press on it or look at its panels.
#pragma once

#include "ui/game/game_screen.h"
#include "ui/platform/gl_context.h"

#include <SDL.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>

namespace test_game {

/// The source tree (levels/ is in it).
inline const std::filesystem::path kRoot =
    std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();

/// `level` (a file in levels/) on a headless game screen of w x h with the settings
/// folder `settings` (kept: the caller decides when it goes), two frames drawn. `screen`
/// is null when no headless context could be made (the test says why).
struct HeadlessGame {
    std::unique_ptr<ui::GLContext> context;
    std::unique_ptr<ui::GameScreen> screen;

    HeadlessGame(const std::string& level, int w, int h, const std::filesystem::path& settings)
        : HeadlessGame(levelDef(level, settings), w, h) {}

    /// Any screen the game opens on (a replay, the editor, the level select): `def`, its
    /// levels folder the source tree's.
    HeadlessGame(ui::GameScreenDef def, int w, int h) {
        std::string error;
        context = ui::createHeadlessContext(w, h, ui::HeadlessBackend::Auto, error);
        EXPECT_NE(context, nullptr) << error;
        if (!context) return;
        def.levelsFolder = (kRoot / "levels").string();
        screen = std::make_unique<ui::GameScreen>(*context, nullptr, def);
        for (int i = 0; i < 2; ++i)
            screen->frame(1.0 / 60.0);
    }

    static ui::GameScreenDef levelDef(const std::string& level, const std::filesystem::path& settings) {
        ui::GameScreenDef def;
        def.levelFile = (kRoot / "levels" / level).string();
        def.settingsFolder = settings.string();
        return def;
    }
};

/// A scratch settings folder named for the test and the process, gone with the scope.
struct ScratchFolder {
    std::filesystem::path dir;
    explicit ScratchFolder(const std::string& name)
        : dir(std::filesystem::temp_directory_path() /
              ("artillery-" + name + "-" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(dir);
    }
    ~ScratchFolder() { std::filesystem::remove_all(dir); }
};

/// A key pressed and let go on the screen, as the window sends it.
inline void tap(ui::GameScreen& screen, SDL_Keycode key) {
    SDL_Event e{};
    e.type = SDL_KEYDOWN;
    e.key.keysym.sym = key;
    screen.handleEvent(e);
    e.type = SDL_KEYUP;
    screen.handleEvent(e);
}

} // namespace test_game
