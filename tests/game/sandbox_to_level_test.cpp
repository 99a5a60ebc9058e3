// A sandbox scene as a level: what was spawned is in the level where it came to rest
// (to the last bit the file can hold), the level passes the loader, and loose balls are
// left out; a level converted before anything happened is the level it was.
#include "game/editor/sandbox_to_level.h"
#include "game/level_write.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace game;
using phys::Vec2;

namespace {

Level flatSandbox() {
    return parseLevel("flat.json", R"({"format": 1, "name": "flat", "mode": "sandbox",
      "world": {"min": [-50, -10], "max": [50, 60]},
      "physics": {"planet": "earth", "drag": false, "wind": 0},
      "terrain": {"points": [[-50, 0], [0, 0], [50, 0]], "destructible": false},
      "cannons": [{"position": [-40, 1]}]})");
}

Command spawn(const std::string& what, Vec2 at, Vec2 to = {}) {
    Command c;
    c.kind = CommandKind::Spawn;
    c.text = what;
    c.at = at;
    c.to = to;
    return c;
}

/// Steps until every block sleeps (at most `seconds`).
void stepUntilBlocksRest(Match& m, double seconds) {
    const auto ticks = static_cast<int>(seconds / m.world().def().tickSeconds);
    for (int i = 0; i < ticks; ++i) {
        m.step();
        bool awake = false;
        for (const BlockState& b : m.blocks())
            awake = awake || m.rigid().state(b.body).awake;
        if (!awake && i > 120) return;
    }
}

} // namespace

TEST(SandboxToLevel, SpawnedBlockAndRopeAreWhereTheyRested) {
    Match m(flatSandbox());
    ASSERT_EQ(m.apply(spawn("block", {5.0, 4.0})), "");
    ASSERT_EQ(m.apply(spawn("rope", {-10.0, 12.0}, {-4.0, 12.0})), "");
    ASSERT_EQ(m.apply(spawn("tennis-ball", {20.0, 3.0})), "");
    stepUntilBlocksRest(m, 20.0);
    const phys::RigidBodyState rested = m.rigid().state(m.blocks()[0].body);
    ASSERT_FALSE(rested.awake) << "the block came to rest";
    EXPECT_NEAR(rested.position.y, 0.5, 0.02) << "a 1 m block on the ground";

    const Level scene = editor::sandboxToLevel(m);
    const Level loaded = parseLevel("scene.json", levelToJson(scene));
    ASSERT_EQ(loaded.blocks.size(), 1u);
    EXPECT_NEAR(loaded.blocks[0].position.x, rested.position.x, 1e-9);
    EXPECT_NEAR(loaded.blocks[0].position.y, rested.position.y, 1e-9);
    EXPECT_NEAR(loaded.blocks[0].angleDeg * M_PI / 180.0, std::remainder(rested.angle, 2 * M_PI),
                1e-9);
    EXPECT_EQ(loaded.blocks[0].size, (Vec2{1.0, 1.0}));
    EXPECT_EQ(loaded.blocks[0].material, "wood");

    ASSERT_EQ(loaded.ropes.size(), 1u);
    const RopeState& rope = m.ropes()[0];
    const Vec2 freeEnd = m.world().particles.position(rope.last);
    EXPECT_EQ(loaded.ropes[0].from, (Vec2{-10.0, 12.0})) << "pinned where it was spawned";
    EXPECT_NEAR(loaded.ropes[0].to.x, freeEnd.x, 1e-9);
    EXPECT_NEAR(loaded.ropes[0].to.y, freeEnd.y, 1e-9);
    EXPECT_LT(freeEnd.y, 12.0 - 1.0) << "the free end fell";
    EXPECT_EQ(loaded.ropes[0].segments, rope.def.segments);
    EXPECT_FALSE(loaded.ropes[0].pinTo);
    // Same links: (1 + sag) times the new span is the length it was spawned with.
    EXPECT_NEAR((1.0 + loaded.ropes[0].sag) *
                    phys::length(loaded.ropes[0].to - loaded.ropes[0].from),
                6.0, 1e-9);
    EXPECT_EQ(loaded.mode, Mode::Sandbox);
    EXPECT_EQ(loaded.blobs.size(), 0u) << "the tennis ball is left out";

    // Played again, the block starts where it rested.
    Match again(loaded);
    const phys::RigidBodyState start = again.rigid().state(again.blocks()[0].body);
    EXPECT_NEAR(start.position.x, rested.position.x, 1e-6) << "Box2D keeps floats";
    EXPECT_NEAR(start.position.y, rested.position.y, 1e-6);
}

TEST(SandboxToLevel, AnUntouchedLevelIsItself) {
    const Level level = flatSandbox();
    const Match m(level);
    Level scene = editor::sandboxToLevel(m);
    EXPECT_EQ(scene.name, "flat scene");
    EXPECT_EQ(scene.file, "");
    scene.name = level.name;
    scene.file = level.file;
    scene.contentHash = level.contentHash;
    EXPECT_TRUE(scene == level);
}

TEST(SandboxToLevel, SpawnedBlobsAndTheLiveGravityAreKept) {
    Match m(flatSandbox());
    ASSERT_EQ(m.apply(spawn("blob", {0.0, 5.0})), "");
    Command moon;
    moon.kind = CommandKind::Set;
    moon.text = "gravity";
    moon.value = 1.62;
    ASSERT_EQ(m.apply(moon), "");
    for (int i = 0; i < 240; ++i)
        m.step();
    const Level loaded = parseLevel("scene.json", levelToJson(editor::sandboxToLevel(m)));
    ASSERT_EQ(loaded.blobs.size(), 1u);
    const Vec2 centre = m.world().particles.position(m.blobs()[0].center);
    EXPECT_NEAR(loaded.blobs[0].center.x, centre.x, 1e-9);
    EXPECT_NEAR(loaded.blobs[0].center.y, centre.y, 1e-9);
    EXPECT_EQ(loaded.physics.gravity, 1.62);
}
