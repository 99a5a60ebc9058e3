// Compare in one key (X): every integrator fires the aim on screen, drawn with a legend
// of each landing error and cost per step, placed where it covers nothing.
#include "headless_game.h"
#include "game/level.h"
#include "ui/game/compare_chart.h"
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

// The work-precision chart of the compared shot stands beside the legend, drawn with a
// line per integrator in its path's colour, and covers no target, cannon, shell or impact;
// on a small screen too (where it is drawn at the HUD's scale).
TEST(CompareKey, XDrawsTheShotsWorkPrecisionChartCoveringNothing) {
    const test_game::ScratchFolder scratch("compare-chart");
    struct Case {
        const char* level;
        int width, height;
    };
    for (const auto [level, width, height] :
         {Case{"12_first_shot.json", 1280, 720}, Case{"03_windy_valley.json", 1280, 720},
          Case{"05_castle.json", 1280, 720}, Case{"03_windy_valley.json", 960, 540}}) {
        test_game::HeadlessGame game(level, width, height, scratch.dir);
        ASSERT_NE(game.screen, nullptr);
        test_game::tap(*game.screen, SDLK_x);
        for (int i = 0; i < 2; ++i) game.screen->frame(1.0 / 60.0);
        const ui::ScreenLayout& layout = game.screen->layout();
        const auto named = [&](const char* name) {
            return std::find_if(layout.overlays.begin(), layout.overlays.end(),
                                [&](const ui::LayoutOverlay& o) { return o.name == name; });
        };
        const auto chart = named("compare.chart"), legend = named("compare.legend");
        ASSERT_NE(legend, layout.overlays.end()) << level;
        ASSERT_NE(chart, layout.overlays.end()) << level;
        EXPECT_FALSE(chart->rect.overlaps(legend->rect)) << level;
        for (const ui::Covering& c : ui::coverings(layout))
            ADD_FAILURE() << level << ": " << ui::describe(layout, c);
    }
}

TEST(CompareKey, TheChartHasALinePerIntegratorInItsPathsColour) {
    const game::Match m(
        game::loadLevel((test_game::kRoot / "levels" / "12_first_shot.json").string()));
    ui::StatsPanel stats;
    stats.toggleCompare(m, ui::PendingAim{45.0, 30.0});
    const ui::charts::Chart chart = ui::shotWorkChart(stats.work());
    ASSERT_EQ(chart.series.size(), phys::integrators().size());
    for (std::size_t i = 0; i < chart.series.size(); ++i) {
        const phys::Integrator id = phys::integrators()[i].id;
        EXPECT_EQ(chart.series[i].name, phys::info(id).name);
        const ui::Color c = ui::compareColor(id);
        EXPECT_EQ(chart.series[i].color.r, c.r);
        EXPECT_EQ(chart.series[i].color.g, c.g);
        ASSERT_EQ(chart.series[i].points.size(), 5u);
        // Cost rises as the tick halves; an exact landing sits on the floor.
        for (std::size_t k = 1; k < 5; ++k)
            EXPECT_GT(chart.series[i].points[k].x, chart.series[i].points[k - 1].x);
    }
    for (const phys::Vec2 p : chart.series[static_cast<std::size_t>(phys::Integrator::RK4)].points)
        EXPECT_EQ(p.y, ui::kShotWorkFloor);
}
