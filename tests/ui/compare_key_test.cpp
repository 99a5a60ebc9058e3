// Compare in one key (X): every integrator fires the aim on screen, drawn with a legend
// of each landing error and cost per step, placed where it covers nothing.
#include "headless_game.h"
#include "game/level.h"
#include "ui/game/stats_panel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <unistd.h>

TEST(CompareKey, TheLegendGivesEachPathsErrorAndCost) {
    const game::Match m(game::loadLevel((test_game::kRoot / "levels" / "12_first_shot.json").string()));
    ui::StatsPanel stats;
    stats.toggleCompare(m, ui::PendingAim{45.0, 30.0});
    ASSERT_TRUE(stats.showCompare);
    const std::vector<std::string> lines = stats.legendLines();
    ASSERT_EQ(lines.size(), phys::integrators().size() + 1);
    EXPECT_EQ(lines.front().rfind("explicit-euler", 0), 0u);
    EXPECT_NE(lines.front().find("1 eval/step"), std::string::npos);
    EXPECT_NE(lines[6].find("rk4"), std::string::npos);
    EXPECT_NE(lines[6].find("4 eval/step"), std::string::npos);
    EXPECT_EQ(lines.back(), "closed-form (reference)");
    stats.toggleCompare(m, ui::PendingAim{45.0, 30.0});
    EXPECT_FALSE(stats.showCompare);
}

TEST(CompareKey, XDrawsThePathsWithALegendThatCoversNothing) {
    const test_game::ScratchFolder scratch("compare");
    {
        test_game::HeadlessGame game("12_first_shot.json", 1280, 720, scratch.dir);
        ASSERT_NE(game.screen, nullptr);
        auto hasLegend = [&] {
            const auto& o = game.screen->layout().overlays;
            return std::any_of(o.begin(), o.end(),
                               [](const ui::LayoutOverlay& x) { return x.name == "compare.legend"; });
        };
        EXPECT_FALSE(hasLegend());
        test_game::tap(*game.screen, SDLK_x);
        for (int i = 0; i < 2; ++i) game.screen->frame(1.0 / 60.0);
        EXPECT_TRUE(hasLegend());
        EXPECT_TRUE(ui::coverings(game.screen->layout()).empty());
        test_game::tap(*game.screen, SDLK_x);
        for (int i = 0; i < 2; ++i) game.screen->frame(1.0 / 60.0);
        EXPECT_FALSE(hasLegend());
    }
}
