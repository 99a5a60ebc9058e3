// Sleepers wake when what holds them up moves off (held_sleepers.cpp), against where the
// balls must end: a sleeping column whose bottom ball is removed or knocked away falls by
// one diameter, to rest on the floor as the column did; a sleeper on an awake ball that
// stays put sleeps on, and wakes once that ball slides; what rests on a sleeper never
// wakes it.
#include "physics/world.h"

#include <gtest/gtest.h>

using namespace phys;

namespace {

constexpr double kR = 0.05; // ball radius, m

ParticleDef woodenBall(Vec2 at) {
    ParticleDef pd;
    pd.position = at;
    pd.radius = kR;
    pd.material = material::kWooden;
    return pd;
}

bool asleep(const World& w, ParticleId i) {
    return (w.particles.flags[i] & kSleeping) != 0;
}

// A column of `n` balls standing on a floor, stepped until every ball sleeps.
World sleepingColumn(int n) {
    World w;
    w.shapes.addSegment({-2.0, 0.0}, {2.0, 0.0}, material::kWooden);
    for (int i = 0; i < n; ++i)
        w.particles.add(woodenBall({0.0, kR + 2.0 * kR * i}));
    for (int t = 0; t < 240; ++t)
        w.step();
    for (int i = 0; i < n; ++i)
        EXPECT_TRUE(asleep(w, static_cast<ParticleId>(i))) << "ball " << i;
    return w;
}

// Balls 1..n-1 of a column whose ball 0 went: each one diameter lower, standing on the
// floor, asleep again.
void expectFallenOneDiameter(const World& w, int n) {
    for (int i = 1; i < n; ++i) {
        const auto id = static_cast<ParticleId>(i);
        EXPECT_NEAR(w.particles.px[id], 0.0, 1e-9) << "ball " << i;
        EXPECT_NEAR(w.particles.py[id], kR + 2.0 * kR * (i - 1), 0.02 * kR) << "ball " << i;
        EXPECT_TRUE(asleep(w, id)) << "ball " << i;
    }
}

} // namespace

TEST(HeldSleepers, ASleepingColumnFallsWhenItsBottomBallIsRemoved) {
    World w = sleepingColumn(6);
    w.particles.remove(0);
    for (int t = 0; t < 240; ++t)
        w.step();
    expectFallenOneDiameter(w, 6);
}

TEST(HeldSleepers, ASleepingColumnFallsWhenItsBottomBallIsKnockedAway) {
    // Slid out within the contact's reach in a step, or out of it in one.
    for (const double speed : {2.0, 30.0}) {
        SCOPED_TRACE(speed);
        World w = sleepingColumn(6);
        w.particles.setVelocity(0, {speed, 0.0});
        for (int t = 0; t < 360; ++t)
            w.step();
        EXPECT_GT(w.particles.px[0], 4.0 * kR); // gone from under the column
        expectFallenOneDiameter(w, 6);
    }
}

// The holder is tied to a spring (so it never sleeps) at its rest length (so it pulls
// nothing) and rests on the floor: awake and still. The ball on it falls asleep and stays
// so; when the spring's far end moves, the holder slides and the sleeper wakes.
TEST(HeldSleepers, ASleeperOnAnAwakeBallSleepsUntilThatBallMoves) {
    World w;
    w.shapes.addSegment({-2.0, 0.0}, {2.0, 0.0}, material::kWooden);
    const ParticleId holder = w.particles.add(woodenBall({0.0, kR}));
    const ParticleId held = w.particles.add(woodenBall({0.0, 3.0 * kR}));
    Spring s;
    s.a = holder;
    s.anchor = {-1.0, kR};
    s.restLength = 1.0;
    s.stiffness = 500.0;
    w.springs.push_back(s);
    for (int t = 0; t < 480; ++t) {
        w.step();
        ASSERT_FALSE(asleep(w, holder)) << "tick " << t;
        if (t >= 120) {
            ASSERT_TRUE(asleep(w, held)) << "tick " << t;
        }
    }
    w.springs[0].anchor = {-0.8, kR}; // pulls the holder 0.2 m to the right
    int woke = -1;
    for (int t = 0; t < 120 && woke < 0; ++t) {
        w.step();
        if (!asleep(w, held)) woke = t;
    }
    ASSERT_GE(woke, 0) << "the sleeper stayed up while its holder slid away";
    // It wakes once the holder has slid the stray a sleeper may have (sleepSpeed *
    // sleepTime, 0.5 mm): within a few ticks of the pull.
    EXPECT_LE(woke, 10);
}

// A ball set down on a sleeping column rests on it; the column is not woken (its top ball
// carries the newcomer as the floor would) and the newcomer falls asleep on it.
TEST(HeldSleepers, WhatRestsOnASleeperDoesNotWakeIt) {
    World w = sleepingColumn(4);
    const ParticleId top = w.particles.add(woodenBall({0.0, kR + 2.0 * kR * 4}));
    for (int t = 0; t < 240; ++t) {
        w.step();
        for (ParticleId i = 0; i < 4; ++i)
            ASSERT_TRUE(asleep(w, i)) << "ball " << i << ", tick " << t;
    }
    EXPECT_TRUE(asleep(w, top));
    EXPECT_NEAR(w.particles.py[top], kR + 2.0 * kR * 4, 0.02 * kR);
}
