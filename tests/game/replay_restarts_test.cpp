// Restart points: a seek back that starts from a parked match gives the very state that
// straight play had (every stored checkpoint's hash, and the final hash), and it
// re-simulates at most one spacing of ticks.
#include "game/replay_player.h"
#include "game/replay_restarts.h"

#include <gtest/gtest.h>

#include <string>

using namespace game;

namespace {

struct Golden {
    Replay replay;
    Level level;
};

Golden golden(const std::string& name) {
    const std::string file = std::string(ARTILLERY_SOURCE_DIR) + "/tests/replays/" + name;
    Replay r = loadReplay(file);
    Level l = levelForReplay(file, r);
    return {std::move(r), std::move(l)};
}

} // namespace

TEST(RestartPoints, ParkMatchesEverySpacingUpToTheEnd) {
    const Golden g = golden("06_rope_bridge.replay.json");
    RestartPoints points(g.level, g.replay, {600, 32});
    EXPECT_EQ(points.spacing(), 600u);
    EXPECT_EQ(points.points(), (g.replay.ticks - 1) / 600);
    EXPECT_EQ(points.parked(), 0u);
    EXPECT_FALSE(points.build(599)); // the first point is 600 ticks away
    EXPECT_EQ(points.parked(), 0u);
    EXPECT_FALSE(points.build(1)); // it is parked; the next one starts from the start
    EXPECT_EQ(points.parked(), 1u);
    EXPECT_TRUE(points.build(UINT64_MAX));
    EXPECT_EQ(points.parked(), points.points());
    // A long replay spaces its points wider rather than keeping more than maxPoints.
    RestartPoints few(g.level, g.replay, {10, 4});
    EXPECT_EQ(few.spacing(), (g.replay.ticks + 3) / 4);
    EXPECT_LE(few.points(), 4u);
}

TEST(RestartPoints, ASeekBackFromAPointGivesStraightPlaysHashes) {
    for (const char* name : {"06_rope_bridge.replay.json", "05_castle.replay.json",
                             "11_sandbox.replay.json", "10_duel.replay.json"}) {
        SCOPED_TRACE(name);
        const Golden g = golden(name);
        ReplayPlayer player(g.level, g.replay);
        EXPECT_TRUE(player.prepareRestartPoints(UINT64_MAX));
        const std::uint64_t spacing = player.restartPoints().spacing();
        ASSERT_GT(player.restartPoints().points(), 0u);
        player.seek(player.lastTick());
        ASSERT_FALSE(player.divergence().has_value());
        // The stored checkpoints a window of restart points at a time, latest window
        // first, so each seek back finds its point still parked (one handed out is
        // rebuilt from the start). The window's first checkpoint is reached by a seek
        // back from the parked match at or before it (tick % spacing re-simulated); the
        // rest by playing on from there. Every hash is the recorded one.
        const auto& checkpoints = g.replay.checkpoints;
        std::size_t end = checkpoints.size();
        while (end > 0) {
            const std::uint64_t window = checkpoints[end - 1].tick / spacing;
            std::size_t first = end - 1;
            while (first > 0 && checkpoints[first - 1].tick / spacing == window)
                --first;
            for (std::size_t k = first; k < end; ++k) {
                const std::uint64_t tick = checkpoints[k].tick;
                player.seek(tick);
                ASSERT_EQ(player.tick(), tick);
                EXPECT_EQ(checkpointOf(player.match()).hash, checkpoints[k].hash) << "tick " << tick;
                if (k == first) {
                    EXPECT_EQ(player.lastSeekResimulated(), tick % spacing) << "tick " << tick;
                }
            }
            end = first;
        }
        // Played on from the earliest of them, the match ends in the recorded hash; and
        // the points handed out, made again, serve the next seek back.
        player.seek(player.lastTick());
        EXPECT_EQ(player.match().hash(), g.replay.finalHash);
        EXPECT_TRUE(player.prepareRestartPoints(UINT64_MAX));
        player.seek(player.restartPoints().points() * spacing);
        EXPECT_EQ(player.lastSeekResimulated(), 0u);
        player.seek(player.lastTick());
        EXPECT_EQ(player.match().hash(), g.replay.finalHash);
        EXPECT_FALSE(player.divergence().has_value());
    }
}

TEST(RestartPoints, ASeekWithoutPointsStartsOver) {
    const Golden g = golden("05_castle.replay.json");
    ReplayPlayer player(g.level, g.replay);
    player.seek(player.lastTick());
    player.seek(1000);
    EXPECT_EQ(player.lastSeekResimulated(), 1000u);
    ASSERT_TRUE(player.prepareRestartPoints(UINT64_MAX));
    player.seek(player.lastTick());
    player.seek(1000);
    EXPECT_EQ(player.lastSeekResimulated(), 1000u % player.restartPoints().spacing());
    // The point handed out is gone until rebuilt; the one before it serves meanwhile.
    player.seek(player.lastTick());
    player.seek(1000);
    EXPECT_EQ(player.lastSeekResimulated(),
              1000u % player.restartPoints().spacing() + player.restartPoints().spacing());
}
