// The measuring tools as a mode (ui/game/measure_tools.h): M cycles them, a press
// measures instead of aiming, the tape follows a drag.
#include "headless_game.h"
#include "ui/game/measure_tools.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <unistd.h>

TEST(MeasureTools, CycleProbeTapeStopwatchOff) {
    ui::MeasureTools t;
    EXPECT_FALSE(t.on());
    EXPECT_FALSE(t.press({0.0, 0.0}, 1.0)) << "off: the mouse aims";
    t.next();
    EXPECT_EQ(t.tool(), ui::MeasureTool::Probe);
    t.next();
    EXPECT_EQ(t.tool(), ui::MeasureTool::Tape);
    EXPECT_TRUE(t.press({1.0, 1.0}, 1.0));
    EXPECT_TRUE(t.move({4.0, 5.0}));
    EXPECT_TRUE(t.lift({4.0, 5.0}));
    ASSERT_TRUE(t.tapeReading());
    EXPECT_DOUBLE_EQ(t.tapeReading()->distance, 5.0);
    t.next();
    EXPECT_EQ(t.tool(), ui::MeasureTool::Stopwatch);
    t.next();
    EXPECT_FALSE(t.on());
}

TEST(MeasureTools, MOnTheGameScreenTurnsTheMouseIntoAProbe) {
    const test_game::ScratchFolder scratch("measure");
    {
        test_game::HeadlessGame game("12_first_shot.json", 1280, 720, scratch.dir);
        ASSERT_NE(game.screen, nullptr);
        ASSERT_NE(game.screen->session(), nullptr);
        auto drag = [&](int x0, int y0, int x1, int y1) {
            SDL_Event e{};
            e.type = SDL_MOUSEBUTTONDOWN;
            e.button.button = SDL_BUTTON_LEFT;
            e.button.x = x0;
            e.button.y = y0;
            game.screen->handleEvent(e);
            e = SDL_Event{};
            e.type = SDL_MOUSEMOTION;
            e.motion.x = x1;
            e.motion.y = y1;
            game.screen->handleEvent(e);
            e = SDL_Event{};
            e.type = SDL_MOUSEBUTTONUP;
            e.button.button = SDL_BUTTON_LEFT;
            e.button.x = x1;
            e.button.y = y1;
            game.screen->handleEvent(e);
            for (int i = 0; i < 3; ++i) game.screen->frame(1.0 / 60.0);
            return game.screen->session()->match().cannon().angleDeg;
        };
        const double before = game.screen->session()->match().cannon().angleDeg;
        const double aimed = drag(300, 300, 500, 250);
        EXPECT_NE(aimed, before) << "without a tool, the drag aims";
        test_game::tap(*game.screen, SDLK_m);
        EXPECT_EQ(drag(300, 300, 400, 150), aimed) << "with one, it measures";
    }
}
