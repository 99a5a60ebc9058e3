// The cost in a corner (F3): its lines from the match's figures, and its window on the
// game screen, recorded in the screen layout and covering none of the objects.
#include "headless_game.h"
#include "ui/game/cost_readout.h"
#include "ui/game/screen_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <unistd.h>

namespace fs = std::filesystem;

TEST(CostReadout, SaysWhatEachModelMoves) {
    ui::CostFigures f;
    f.frameMs = 16.4;
    f.particlesUs = 35.0;
    f.rigidUs = 6.0;
    f.tickHz = 120.0;
    f.substeps = 2;
    f.integrator = "velocity-verlet";
    f.closedForm = 1;
    f.integrated = 12;
    f.springs = 20;
    f.bodiesAwake = 3;
    f.bodiesAsleep = 4;
    const std::vector<std::string> lines = ui::costLines(f);
    const std::vector<std::string> expected = {
        "frame 16.40 ms   tick 120 Hz x 2",
        "physics 41 us/tick  (particles 35, Box2D 6)",
        "closed form  1 particle",
        "velocity-verlet  12 particles, 20 springs",
        "Box2D  3 bodies awake, 4 asleep",
    };
    EXPECT_EQ(lines, expected);
}

TEST(CostReadout, F3ShowsItInACornerThatCoversNothing) {
    const fs::path dir = fs::temp_directory_path() / ("artillery-cost-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    {
        test_game::HeadlessGame game("05_castle.json", 1280, 720, dir);
        ASSERT_NE(game.screen, nullptr);
        auto hasCost = [&] {
            const auto& o = game.screen->layout().overlays;
            return std::any_of(o.begin(), o.end(), [](const ui::LayoutOverlay& x) { return x.name == "panel.Cost"; });
        };
        EXPECT_FALSE(hasCost());
        test_game::tap(*game.screen, SDLK_F3);
        for (int i = 0; i < 3; ++i) game.screen->frame(1.0 / 60.0);
        EXPECT_TRUE(hasCost());
        EXPECT_TRUE(ui::coverings(game.screen->layout()).empty());
        test_game::tap(*game.screen, SDLK_F3);
        for (int i = 0; i < 2; ++i) game.screen->frame(1.0 / 60.0);
        EXPECT_FALSE(hasCost());
    }
    fs::remove_all(dir);
}
