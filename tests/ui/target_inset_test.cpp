// The target close-up: it frames what the player aims at, only while the main view shows
// it too small to read. Camera arithmetic only; no GL is needed.
#include "game/level.h"
#include "game/match.h"
#include "ui/game/match_view.h"
#include "ui/game/target_inset.h"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <string>

namespace {

using phys::Vec2;

std::string sourceDir() {
    return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path().string();
}

bool inside(const ui::Camera& c, Vec2 p) {
    const Vec2 lo = c.visibleMin(), hi = c.visibleMax();
    return p.x >= lo.x - 1e-9 && p.x <= hi.x + 1e-9 && p.y >= lo.y - 1e-9 && p.y <= hi.y + 1e-9;
}

TEST(TargetInset, FramesTheCastleWhenTheLevelViewShowsItSmall) {
    const game::Match m(game::loadLevel(sourceDir() + "/levels/05_castle.json"));
    const ui::Camera home = ui::levelCamera(m, 1280, 720);
    const auto box = ui::aimedAtBox(m);
    ASSERT_TRUE(box);
    // The three marked blocks stand at x = 150, 165 and 176 m; the towers and the hall
    // they stand on are taken in with them.
    EXPECT_LE(box->first.x, 149.5);
    EXPECT_GE(box->second.x, 176.5);
    EXPECT_NEAR(box->first.y, 0.0, 1e-2); // the castle stands on the ground at y = 0
    const double shownPx = (box->second.y - box->first.y) * home.pixelsPerMetre;
    ASSERT_LT(shownPx, ui::TargetInsetDef{}.readablePx);

    const auto inset = ui::targetInset(m, home);
    ASSERT_TRUE(inset);
    EXPECT_TRUE(inside(inset->camera, box->first));
    EXPECT_TRUE(inside(inset->camera, box->second));
    EXPECT_GT(inset->camera.pixelsPerMetre, 1.5 * home.pixelsPerMetre);
    // In the top right corner, on the screen.
    EXPECT_GE(inset->cornerPx.x, 0.5 * home.width);
    EXPECT_LE(inset->cornerPx.x + inset->camera.width, home.width);
    EXPECT_LE(inset->cornerPx.y + inset->camera.height, 0.5 * home.height);
}

TEST(TargetInset, HidesOnceTheMainViewShowsTheTargetsReadable) {
    const game::Match m(game::loadLevel(sourceDir() + "/levels/05_castle.json"));
    ui::Camera close = ui::levelCamera(m, 1280, 720);
    const auto box = ui::aimedAtBox(m);
    ASSERT_TRUE(box);
    close.pixelsPerMetre = ui::TargetInsetDef{}.readablePx / (box->second.y - box->first.y);
    EXPECT_FALSE(ui::targetInset(m, close));
    close.pixelsPerMetre *= 0.99;
    EXPECT_TRUE(ui::targetInset(m, close));
}

// First shot's discs, drawn at least as large as they read, stand in the main view for
// themselves: no close-up covers the sky for them; the castle's blocks at the same framing
// want it.
TEST(TargetInset, DiscsAloneReadInTheMainView) {
    const game::Match discs(game::loadLevel(sourceDir() + "/levels/12_first_shot.json"));
    EXPECT_FALSE(ui::targetInset(discs, ui::levelCamera(discs, 1280, 720)));
    const game::Match castle(game::loadLevel(sourceDir() + "/levels/05_castle.json"));
    EXPECT_TRUE(ui::targetInset(castle, ui::levelCamera(castle, 1280, 720)));
}

// The Stats window open over the close-up's corner (as it first opens at 1280x720) moves
// the close-up to its left, clear of it and on the screen; a window elsewhere, or one
// that leaves no room left of it, leaves the close-up where it is.
TEST(TargetInset, MovesLeftOfAPanelOpenOverIt) {
    const game::Match m(game::loadLevel(sourceDir() + "/levels/05_castle.json"));
    const ui::Camera home = ui::levelCamera(m, 1280, 720);
    auto rect = [&](const ui::TargetInsetDef& d) {
        const auto inset = ui::targetInset(m, home, d);
        EXPECT_TRUE(inset);
        const Vec2 c = inset ? inset->cornerPx : Vec2{};
        const double w = inset ? inset->camera.width : 0.0, h = inset ? inset->camera.height : 0.0;
        return std::array<double, 4>{c.x, c.y, c.x + w, c.y + h};
    };
    const ui::TargetInsetDef plain;
    const auto before = rect(plain);
    const ui::PixelRect stats{938.0, 44.0, 1268.0, 644.0};
    ASSERT_LT(stats.x0, before[2]) << "the window covers the close-up's place";
    const auto after = rect(ui::clearOf(plain, home, stats));
    EXPECT_DOUBLE_EQ(after[2], stats.x0 - plain.rightPx) << "left of the window, a gap apart";
    EXPECT_GE(after[0], 0.0);
    EXPECT_DOUBLE_EQ(after[1], before[1]);
    EXPECT_DOUBLE_EQ(after[2] - after[0], before[2] - before[0]) << "the same size";

    const ui::PixelRect elsewhere{12.0, 300.0, 300.0, 600.0};
    EXPECT_EQ(rect(ui::clearOf(plain, home, elsewhere)), before);
    const ui::PixelRect wide{300.0, 44.0, 1268.0, 644.0};
    EXPECT_EQ(rect(ui::clearOf(plain, home, wide)), before) << "no room left of it";
}

TEST(TargetInset, InADuelFramesTheOtherCannon) {
    const game::Match m(game::loadLevel(sourceDir() + "/levels/10_duel.json"));
    const auto box = ui::aimedAtBox(m);
    ASSERT_TRUE(box);
    const Vec2 mine = m.cannon().def.position;
    for (const game::CannonState& c : m.cannons()) {
        const Vec2 p = c.def.position;
        const bool framed = p.x >= box->first.x && p.x <= box->second.x && p.y >= box->first.y &&
                            p.y <= box->second.y;
        EXPECT_EQ(framed, c.def.player != m.cannon().def.player) << "cannon at x = " << p.x;
    }
    EXPECT_FALSE(mine.x >= box->first.x && mine.x <= box->second.x);
}

// The other cannon is framed standing on its ground: on a pedestal 6 m above it (as the
// castle duel's cannons once stood), a box of the cannon alone (and its margin) left out
// the ground, so the close-up showed a cannon on a column in the sky.
TEST(TargetInset, InADuelFramesTheGroundTheOtherCannonStandsOn) {
    const game::Match m(game::parseLevel("pedestals.json", R"({"format": 1, "name": "pedestals",
        "mode": "duel", "world": {"min": [0, -10], "max": [300, 150]},
        "terrain": {"points": [[0, 5], [300, 5]]},
        "cannons": [{"position": [25, 12], "player": "1"},
                    {"position": [275, 12], "angle_deg": 135, "player": "cpu"}]})"));
    const auto box = ui::aimedAtBox(m);
    ASSERT_TRUE(box);
    const Vec2 other = m.cannons()[1].def.position;
    ASSERT_NE(m.cannons()[1].def.player, m.cannon().def.player);
    const double ground = m.terrain().heightAt(other.x);
    ASSERT_GT(other.y - ground, 2.0 * game::kCannonRadius) << "the cannon stands on a pedestal";
    EXPECT_LE(box->first.y, ground);
    const auto inset = ui::targetInset(m, ui::levelCamera(m, 1280, 720));
    ASSERT_TRUE(inset);
    EXPECT_TRUE(inside(inset->camera, {other.x, ground}));
    EXPECT_TRUE(inside(inset->camera, other));
}

} // namespace
