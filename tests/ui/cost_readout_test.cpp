// The cost in a corner (F3): its lines from the match's figures, and its window on the
// game screen, recorded in the screen layout and covering none of the objects.
#include "headless_game.h"
#include "ui/game/cost_readout.h"
#include "ui/game/screen_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <optional>
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
    const test_game::ScratchFolder scratch("cost");
    for (const char* level : {"05_castle.json", "07_soft_blob.json"}) {
        fs::remove_all(scratch.dir);
        test_game::HeadlessGame game(level, 1280, 720, scratch.dir);
        ASSERT_NE(game.screen, nullptr);
        auto rectOf = [&](const std::string& name) -> std::optional<ui::PixelRect> {
            for (const ui::LayoutOverlay& o : game.screen->layout().overlays)
                if (o.name == name) return o.rect;
            return std::nullopt;
        };
        EXPECT_FALSE(rectOf("panel.Cost")) << level;
        test_game::tap(*game.screen, SDLK_F3);
        for (int i = 0; i < 3; ++i) game.screen->frame(1.0 / 60.0);
        const auto cost = rectOf("panel.Cost"), controls = rectOf("panel.Controls");
        ASSERT_TRUE(cost) << level;
        EXPECT_TRUE(ui::coverings(game.screen->layout()).empty()) << level;
        // Nor over the turn's controls (the fire button).
        ASSERT_TRUE(controls) << level;
        EXPECT_FALSE(cost->overlaps(*controls)) << level;
        test_game::tap(*game.screen, SDLK_F3);
        for (int i = 0; i < 2; ++i) game.screen->frame(1.0 / 60.0);
        EXPECT_FALSE(rectOf("panel.Cost")) << level;
    }
}
