// The sandbox: spawn, grab, drag and release are commands like any other, refused
// outside a sandbox, checked against the closed form and statics, and replayed
// bit for bit.
#include "game/match.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace game;
using phys::Vec2;

namespace {

// Flat ground at y = 0, no air: a spawned ball falls on the closed form.
Level flatLevel(const char* mode) {
    return parseLevel("flat.json", std::string(R"({"format": 1, "name": "flat", "mode": ")") + mode +
                                       R"(",
      "world": {"min": [-50, -10], "max": [50, 60]},
      "physics": {"planet": "earth", "drag": false, "wind": 0, "water_level": -100},
      "terrain": {"points": [[-50, 0], [50, 0]], "destructible": false},
      "cannons": [{"position": [-40, 1]}],
      "targets": [{"position": [40, 5]}]})");
}

Command at(CommandKind kind, Vec2 p, std::string what = {}, Vec2 to = {}) {
    Command c;
    c.kind = kind;
    c.at = p;
    c.to = to;
    c.text = std::move(what);
    return c;
}

Command plain(CommandKind kind) {
    Command c;
    c.kind = kind;
    return c;
}

void run(Match& m, double seconds) {
    const int ticks = static_cast<int>(std::lround(seconds / m.world().def().tickSeconds));
    for (int i = 0; i < ticks; ++i) m.step();
}

} // namespace

TEST(Sandbox, ToolsAreRefusedOutsideASandboxUntilItBecomesOne) {
    Match m(flatLevel("practice"));
    const std::string why = m.apply(at(CommandKind::Spawn, {0, 10}, "block"));
    EXPECT_NE(why.find("only in the sandbox"), std::string::npos) << why;
    EXPECT_TRUE(m.blocks().empty());
    EXPECT_EQ(m.apply(plain(CommandKind::Sandbox)), "");
    EXPECT_TRUE(m.sandbox());
    EXPECT_EQ(m.apply(at(CommandKind::Spawn, {0, 10}, "block")), "");
    EXPECT_EQ(m.blocks().size(), 1u);
    EXPECT_NE(m.apply(plain(CommandKind::Sandbox)), "") << "already a sandbox";
    EXPECT_NE(m.apply(at(CommandKind::Spawn, {0, 100}, "block")).find("outside"), std::string::npos);
}

TEST(Sandbox, ASpawnedBallFallsOnTheClosedForm) {
    Match m(flatLevel("sandbox"));
    const std::size_t before = m.world().particles.count();
    ASSERT_EQ(m.apply(at(CommandKind::Spawn, {3, 20}, "golf-ball")), "");
    ASSERT_EQ(m.world().particles.count(), before + 1);
    phys::ParticleId ball = phys::kNoParticle;
    const auto& set = m.world().particles;
    for (std::size_t i = 0; i < set.slots(); ++i)
        if ((set.flags[i] & phys::kAlive) && set.px[i] == 3.0) ball = static_cast<phys::ParticleId>(i);
    ASSERT_NE(ball, phys::kNoParticle);
    run(m, 1.0);
    const double t = m.world().def().tickSeconds * std::lround(1.0 / m.world().def().tickSeconds);
    EXPECT_NEAR(set.py[ball], 20.0 - 0.5 * 9.81 * t * t, 1e-9);
    EXPECT_EQ(set.px[ball], 3.0);
}

TEST(Sandbox, ABlockLandsAndRestsOnTheGround) {
    Match m(flatLevel("sandbox"));
    Command c = at(CommandKind::Spawn, {0, 5}, "block");
    c.number = 2.0;
    ASSERT_EQ(m.apply(c), "");
    run(m, 4.0);
    const auto s = m.rigid().state(m.blocks().back().body);
    EXPECT_NEAR(s.position.y, 1.0, 0.02) << "half its 2 m size above the ground";
    EXPECT_LT(std::abs(s.linearVelocity.y), 1e-3);
}

TEST(Sandbox, GrabbedThingsFollowTheHand) {
    Match m(flatLevel("sandbox"));
    ASSERT_EQ(m.apply(at(CommandKind::Spawn, {0, 1}, "tennis-ball")), "");
    ASSERT_EQ(m.apply(at(CommandKind::Spawn, {10, 3}, "block")), "");
    run(m, 2.0);
    // A particle hangs g / w^2 = 6.8 cm below a still hand.
    ASSERT_EQ(m.apply(at(CommandKind::Grab, {0.1, 1.0})), "");
    ASSERT_EQ(m.grab().kind, GrabState::Kind::Particle);
    ASSERT_EQ(m.apply(at(CommandKind::Drag, {-5, 8})), "");
    run(m, 3.0);
    const auto& set = m.world().particles;
    const phys::ParticleId ball = m.grab().particle;
    EXPECT_NEAR(set.px[ball], -5.0, 1e-3);
    EXPECT_NEAR(set.py[ball], 8.0 - 9.81 / (12.0 * 12.0), 1e-3);
    EXPECT_EQ(m.apply(plain(CommandKind::Release)), "");
    EXPECT_EQ(m.grab().kind, GrabState::Kind::None);
    run(m, 3.0);
    EXPECT_LT(set.py[ball], 1.0) << "released, it falls";
    // A block is carried at the grabbed point, its weight included.
    const auto block = m.blocks().back().body;
    const Vec2 c0 = m.rigid().state(block).position;
    ASSERT_EQ(m.apply(at(CommandKind::Grab, c0)), "");
    ASSERT_EQ(m.grab().kind, GrabState::Kind::Body);
    ASSERT_EQ(m.apply(at(CommandKind::Drag, c0 + Vec2{0, 6})), "");
    run(m, 4.0);
    EXPECT_NEAR(m.rigid().state(block).position.y, c0.y + 6.0, 0.02);
    EXPECT_NE(m.apply(plain(CommandKind::Release)), "nothing is grabbed");
    EXPECT_NE(m.apply(plain(CommandKind::Release)), "") << "nothing is grabbed any more";
}

TEST(Sandbox, ASpawnedRopeTiedToABlockHoldsIt) {
    Match m(flatLevel("sandbox"));
    ASSERT_EQ(m.apply(at(CommandKind::Spawn, {0, 10}, "block")), "");
    // A rope from a pinned point 5 m above to just inside the block's top face.
    ASSERT_EQ(m.apply(at(CommandKind::Spawn, {0, 15.45}, "rope", {0, 10.45})), "");
    run(m, 4.0);
    const auto s = m.rigid().state(m.blocks().back().body);
    EXPECT_NEAR(s.position.y, 10.0, 0.02) << "the rope keeps its 5 m";
    EXPECT_LT(m.world().constraintError(), 1e-4);
}

TEST(Sandbox, EveryKindSpawnsAndASessionReplaysBitForBit) {
    auto play = [] {
        Match m(flatLevel("practice"));
        std::vector<Command> cmds{plain(CommandKind::Sandbox)};
        for (const std::string& k : spawnKinds())
            cmds.push_back(at(CommandKind::Spawn, {static_cast<double>(cmds.size()) * 2.0 - 30.0, 12.0},
                              k, {static_cast<double>(cmds.size()) * 2.0 - 30.0, 9.0}));
        for (const Command& c : cmds) EXPECT_EQ(m.apply(c), "") << c.text;
        m.apply(at(CommandKind::Grab, {-26.0, 12.0}));
        for (int i = 0; i < 240; ++i) {
            if (i == 60) m.apply(at(CommandKind::Drag, {-20.0, 20.0}));
            if (i == 180) m.apply(plain(CommandKind::Release));
            m.step();
        }
        return m.hash();
    };
    EXPECT_EQ(play(), play());
}

TEST(Sandbox, NoShotBudget) {
    Match m(flatLevel("sandbox"));
    for (int shot = 0; shot < 8; ++shot) {
        ASSERT_EQ(m.apply(plain(CommandKind::Fire)), "") << "shot " << shot;
        for (int i = 0; i < 120 * 30 && m.shell(); ++i) m.step();
    }
    EXPECT_FALSE(m.over());
}

// A click on the ground puts what it spawns on the ground: the ground is a surface, and
// a block or a ball made under it fell away under the world. Each settles where it was
// put, resting on the flat ground at y = 0.
TEST(Sandbox, WhatIsSpawnedUnderTheGroundStandsOnIt) {
    Match m(flatLevel("sandbox"));
    ASSERT_EQ(m.apply(at(CommandKind::Spawn, {0, -2}, "block")), "");
    ASSERT_EQ(m.apply(at(CommandKind::Spawn, {10, -0.5}, "steel-ball")), "");
    ASSERT_EQ(m.blocks().size(), 1u);
    run(m, 2.0);
    const phys::RigidBodyState block = m.rigid().state(m.blocks()[0].body);
    EXPECT_NEAR(block.position.x, 0.0, 1e-3);
    EXPECT_NEAR(block.position.y, 0.5, 0.02) << "a 1 m block resting on the ground";
    const phys::ParticleSet& ps = m.world().particles;
    bool ballFound = false;
    for (std::size_t i = 0; i < ps.slots(); ++i)
        if (ps.flags[i] & phys::kAlive) {
            ballFound = true;
            EXPECT_NEAR(ps.px[i], 10.0, 1e-3);
            EXPECT_NEAR(ps.py[i], ps.radius[i], 0.01) << "the ball resting on the ground";
        }
    EXPECT_TRUE(ballFound);
}
