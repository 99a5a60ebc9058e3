// The fixed-step clock: results after N ticks never depend on the frame rate.
#include "physics/clock.h"
#include "physics/world.h"

#include <gtest/gtest.h>

using namespace phys;

namespace {
// A busy scene: drag, wind, springs and a free projectile.
World scene() {
    WorldDef d;
    d.forces.drag = DragModel::Quadratic;
    d.forces.wind = {3.0, 0.0};
    d.integrator = Integrator::RK4;
    World w(d);
    ParticleId prev = kNoParticle;
    for (int i = 0; i < 10; ++i) {
        ParticleDef pd;
        pd.position = {0.3 * i, 5.0};
        pd.velocity = {0.0, 0.1 * i};
        const auto id = w.particles.add(pd);
        Spring s;
        s.a = id;
        s.b = prev;
        s.anchor = {0, 5};
        s.restLength = 0.3;
        s.stiffness = 500;
        s.damping = 0.5;
        w.springs.push_back(s);
        prev = id;
    }
    ParticleDef shell;
    shell.velocity = {30, 40};
    w.particles.add(shell);
    return w;
}

// Plays `ticks` ticks of the scene at a given frame rate through the clock.
std::uint64_t playAt(double fps, std::uint64_t ticks) {
    World w = scene();
    FixedClock clock;
    while (w.tick() < ticks) {
        int n = clock.advance(1.0 / fps);
        while (n-- > 0 && w.tick() < ticks) w.step();
    }
    return w.hash();
}
} // namespace

TEST(FixedClock, SameTicksAtAnyFrameRateAreBitIdentical) {
    const std::uint64_t ticks = 600;
    const auto h30 = playAt(30, ticks), h60 = playAt(60, ticks), h144 = playAt(144, ticks);
    EXPECT_EQ(h30, h60);
    EXPECT_EQ(h60, h144);
    // And equal to stepping without any clock at all.
    World w = scene();
    for (std::uint64_t i = 0; i < ticks; ++i) w.step();
    EXPECT_EQ(w.hash(), h60);
}

TEST(FixedClock, AccumulatesWholeTicksAndReportsTheRemainder) {
    FixedClock c({0.01, 1.0, 32});
    EXPECT_EQ(c.advance(0.025), 2);
    EXPECT_NEAR(c.alpha(), 0.5, 1e-9);
    EXPECT_EQ(c.advance(0.005), 1);
    EXPECT_NEAR(c.alpha(), 0.0, 1e-9);
    EXPECT_EQ(c.ticks(), 3u);
}

TEST(FixedClock, PauseSingleStepAndTimeScale) {
    FixedClock c({0.01, 1.0, 32});
    c.setPaused(true);
    EXPECT_EQ(c.advance(1.0), 0);
    c.requestSingleStep();
    EXPECT_EQ(c.advance(1.0), 1);
    EXPECT_EQ(c.advance(1.0), 0);
    c.setPaused(false);
    c.setTimeScale(0.25); // slow motion: 0.1 s of wall time is 2.5 ticks
    EXPECT_EQ(c.advance(0.1), 2);
    c.setTimeScale(4.0);  // fast forward
    EXPECT_EQ(c.advance(0.1), 40 > 32 ? 32 : 40);
}

TEST(FixedClock, LongStallIsCappedNotReplayed) {
    FixedClock c({0.01, 1.0, 8});
    EXPECT_EQ(c.advance(5.0), 8);
    EXPECT_EQ(c.droppedFrames(), 1u);
    EXPECT_EQ(c.advance(0.0), 0) << "the backlog was dropped";
}

// A frame that runs out of wall time before it has run every tick handed out drops the
// rest: counted as dropped, never owed to the next frame.
TEST(FixedClock, TicksAFrameHadNoTimeForAreDropped) {
    FixedClock c({0.01, 1.0, 32});
    ASSERT_EQ(c.advance(0.1), 10);
    c.dropTicks(9);
    EXPECT_EQ(c.ticks(), 1u);
    EXPECT_EQ(c.droppedFrames(), 1u);
    EXPECT_EQ(c.advance(0.01), 1) << "only the next frame's own time";
    c.dropTicks(0);
    EXPECT_EQ(c.droppedFrames(), 1u) << "nothing dropped, nothing counted";
}
