// Piles, stacks and heaps at rest, against exact answers: a column stands exactly still, a
// heap settles without overlaps, with nothing pushed through a wall, and falls asleep;
// friction holds a ball on a sleeper up to its angle; no sleeper hangs over a hole.
#include "pile_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

using namespace phys;
using namespace phys::piles;

// Ten balls stacked on the floor, touching: every step gravity presses them together, and
// the solver takes it back exactly, from the bottom up. Nothing moves, and they sleep.
TEST(Pile, AColumnStandsExactlyStillAndSleeps) {
    World w;
    w.shapes.addSegment({-1.0, 0.0}, {1.0, 0.0}, material::kWooden);
    for (int i = 0; i < 10; ++i) {
        ParticleDef pd;
        pd.position = {0.0, kR + 2.0 * kR * i};
        pd.radius = kR;
        pd.material = material::kWooden;
        w.particles.add(pd);
    }
    for (int t = 0; t < 240; ++t) {
        w.step();
        for (std::size_t i = 0; i < w.particles.slots(); ++i) {
            ASSERT_NEAR(w.particles.px[i], 0.0, 1e-12) << "tick " << t << " ball " << i;
            ASSERT_NEAR(w.particles.py[i], kR + 2.0 * kR * static_cast<double>(i), 1e-12)
                << "tick " << t << " ball " << i;
        }
    }
    EXPECT_EQ(sleeping(w.particles), 10);
}

// 400 balls fall a few centimetres into a heap: after 5 s nothing is outside the box
// (pressed against a wall, a ball is never pushed through it), balls overlap by less than
// 2 % of a radius, the heap is at rest and nearly all of it asleep. (Before the contact
// solver, the passes settled a pile one layer per pass and projected the rest apart: a
// heap like this one boiled, overlapping by half a radius, and never slept.)
TEST(Pile, AHeapSettlesWithoutOverlapNothingLeaksAndItSleeps) {
    Heap heap = staggeredHeap(400);
    World& w = heap.world;
    const double pe0 = energy(w.particles, w.springs, w.def().forces).potential;
    for (int t = 0; t < 600; ++t)
        w.step();
    const ParticleSet& p = w.particles;
    for (std::size_t i = 0; i < p.slots(); ++i) {
        ASSERT_GT(p.py[i], 0.0) << i;
        ASSERT_GT(p.px[i], 0.0) << i;
        ASSERT_LT(p.px[i], heap.width) << i;
    }
    EXPECT_LT(worstOverlap(p, heap.width), 0.02 * kR);
    const EnergyReport e = energy(p, w.springs, w.def().forces);
    EXPECT_LT(e.kinetic, 1e-4);  // J, for 40 kg of balls
    EXPECT_LT(e.potential, pe0); // it fell; nothing pumped it up
    EXPECT_GE(sleeping(p), 360);
}

// A heap comes to rest, all of it. Sleep asks how far a resting ball went over the rest
// window, not only what its last velocity says: balls wedged between sleepers, or
// clusters the contact solver leaves with a velocity its projection takes back each
// step, report 1-4 cm/s and never move. And a ball resting on a sleeper has friction, as
// on the ground. Without either, 11 of these 1,000 balls were still awake after 5 s (and
// 23 of a 2,000-ball heap for ever); with both, all sleep, their kinetic energy exactly 0.
TEST(Pile, EveryBallOfAHeapSleepsWithinFiveSeconds) {
    Heap heap = staggeredHeap(1000);
    World& w = heap.world;
    for (int t = 0; t < 600; ++t)
        w.step();
    const ParticleSet& p = w.particles;
    EXPECT_EQ(sleeping(p), 1000);
    EXPECT_EQ(energy(p, w.springs, w.def().forces).kinetic, 0.0);
    // Deeper than the 400-ball heap, so more weight on its lowest contacts: 2.6 % of a
    // radius at worst (2.25 % before; sleepers keep the overlap they fell asleep with).
    EXPECT_LT(worstOverlap(p, heap.width), 0.03 * kR);
}

// A ball on top of an immovable one (fixed, as a sleeper is to the others), its contact
// tilted by theta from the vertical, is held by static friction while tan(theta) <= mu_s
// (0.5, wood on wood): it stays exactly where it was, and sleeps. Steeper, it slides off.
TEST(Pile, StaticFrictionHoldsABallOnAnImmovableOneUpToTheFrictionAngle) {
    for (const double degrees : {10.0, 25.0, 30.0, 40.0}) {
        SCOPED_TRACE(degrees);
        World w;
        ParticleDef base;
        base.mass = 0.0; // fixed
        base.radius = kR;
        base.material = material::kWooden;
        w.particles.add(base);
        const double theta = degrees * std::numbers::pi / 180.0;
        ParticleDef top = base;
        top.mass = 0.1;
        top.position = Vec2{std::sin(theta), std::cos(theta)} * (2.0 * kR);
        w.particles.add(top);
        for (int t = 0; t < 120; ++t)
            w.step();
        const double moved = length(w.particles.position(1) - top.position);
        if (std::tan(theta) <= 0.5) {
            EXPECT_LT(moved, 1e-12);
            EXPECT_TRUE(w.particles.flags[1] & kSleeping);
        } else {
            EXPECT_GT(moved, 0.05); // slid off within the second
        }
    }
}

// A ball awake between a sleeper under it and a sleeper resting on it (as a shot leaves
// one in a sleeping pile) was put to rest on each in turn, each pushing it into the
// other, so the passes alternated between the two for all eight of every step. The
// sleeper on it is weight it carries, which the contact solver holds: the passes settle
// in two, and the ball stays in the column and sleeps.
TEST(Pile, ABallSqueezedBetweenSleepersLetsThePassesSettle) {
    World w;
    w.shapes.addSegment({-1.0, 0.0}, {1.0, 0.0}, material::kWooden);
    const double squeeze = 0.01 * kR; // each contact overlaps by half a millimetre
    for (int i = 0; i < 3; ++i) {
        ParticleDef pd;
        pd.position = {0.0, kR + (2.0 * kR - squeeze) * i};
        pd.radius = kR;
        pd.material = material::kWooden;
        w.particles.add(pd);
    }
    w.particles.flags[0] |= kSleeping;
    w.particles.flags[2] |= kSleeping;
    int mostPasses = 0;
    for (int t = 0; t < 120; ++t) {
        w.step();
        mostPasses = std::max(mostPasses, w.collisionStats().passes);
    }
    EXPECT_LE(mostPasses, 2);
    EXPECT_NEAR(w.particles.px[1], 0.0, 1e-12); // not squeezed out sideways
    EXPECT_EQ(sleeping(w.particles), 3);
}

// The other side of sleeping on motion: a steady slide is motion. A ball sliding on a
// frictionless floor at twice the sleep speed keeps sliding, at its speed exactly, and
// never sleeps; at half the sleep speed it sleeps after sleepTime, where it got to.
TEST(Pile, ASteadySlideSleepsOnlyBelowTheSleepSpeed) {
    for (const double factor : {2.0, 0.5}) {
        World w;
        const double speed = factor * w.def().collision.sleepSpeed;
        w.shapes.addSegment({-1.0, 0.0}, {1.0, 0.0}, material::kPerfectlyElastic);
        ParticleDef pd;
        pd.position = {0.0, kR};
        pd.velocity = {speed, 0.0};
        pd.radius = kR;
        pd.material = material::kPerfectlyElastic;
        w.particles.add(pd);
        const int ticks = 360; // 3 s
        int sleptAt = -1;
        for (int t = 1; t <= ticks && sleptAt < 0; ++t) {
            w.step();
            if (w.particles.flags[0] & kSleeping) sleptAt = t;
        }
        const double seconds = w.def().tickSeconds;
        if (factor > 1.0) {
            EXPECT_EQ(sleptAt, -1);
            EXPECT_NEAR(w.particles.vx[0], speed, 1e-15);
            EXPECT_NEAR(w.particles.px[0], speed * ticks * seconds, 1e-12);
        } else {
            // sleepTime of rest after the first tick's contact
            EXPECT_NEAR(sleptAt * seconds, w.def().collision.sleepTime, 2.0 * seconds);
            EXPECT_EQ(w.particles.vx[0], 0.0);
            EXPECT_NEAR(w.particles.px[0], speed * sleptAt * seconds, 1e-12);
        }
        EXPECT_NEAR(w.particles.py[0], kR, 1e-12);
    }
}


// A free ball resting on two sleepers at once (in the notch between them, or against a
// sleeper and a wall) is held by both in the same pass. The passes used to alternate
// between the two, each support bending its motion into the other and each push out of a
// few 1e-7 m of overlap pushing it into the other, for all eight passes of a step, every
// step, for the last awake balls of a heap: in this heap of 1,500 balls in columns, 58
// of the 240 steps after the first second ran all eight passes, 3.7 passes a step on
// average (now 4 and 2.1). A sphere inside another by less than kOverlapSlop radii that
// is not heading in is touching, not in contact (the solver mends that much); either
// change alone leaves the alternation.
TEST(Pile, ABallOnTwoSleepersIsHeldByBothAtOnce) {
    World w = std::move(droppedBalls(1500, false).world);
    const int most = w.def().collision.maxPasses;
    long passes = 0, allPasses = 0, steps = 0;
    for (int t = 0; t < 300; ++t) {
        w.step();
        if (t < 60) continue;
        const int p = w.collisionStats().passes;
        passes += p, allPasses += p == most ? 1 : 0, ++steps;
    }
    std::printf("heap of 1,500 balls in columns, steps 61-300: %.2f passes a step, %ld of %ld "
                "ran all %d\n",
                static_cast<double>(passes) / static_cast<double>(steps), allPasses, steps, most);
    EXPECT_LE(allPasses, 12);
    EXPECT_LT(passes, 3 * steps);
}

// The bench's pile of balls in columns slides and topples for seconds after it lands, and
// part of it sleeps meanwhile. Every sleeper rests on something below it: the floor or a
// ball under its centre, within the solver's reach (a sleeper is immovable, so one whose
// support slid away would hang in the air; it wakes and follows instead).
TEST(Pile, NoSleeperHangsOverAHole) {
    World w = std::move(droppedBalls(1500, false).world);
    const ParticleSet& p = w.particles;
    const double reach = 2.0 * kR * 1.1 + w.def().collision.toiTolerance; // kSpeculative
    int checked = 0;
    for (int t = 1; t <= 480; ++t) {
        w.step();
        if (t % 60 != 0) continue;
        for (std::size_t i = 0; i < p.slots(); ++i) {
            if (!(p.flags[i] & kSleeping)) continue;
            bool held = p.py[i] <= kR * 1.1 + w.def().collision.toiTolerance; // the floor
            for (std::size_t j = 0; j < p.slots() && !held; ++j) {
                const Vec2 d =
                    p.position(static_cast<ParticleId>(i)) - p.position(static_cast<ParticleId>(j));
                held = j != i && d.y > 0.0 && length(d) <= reach;
            }
            ASSERT_TRUE(held) << "ball " << i << " sleeps at (" << p.px[i] << ", " << p.py[i]
                              << ") over nothing, tick " << t;
            ++checked;
        }
    }
    EXPECT_GT(checked, 4 * 1000); // most of the pile sleeps at each check
}

