// "Accurate enough, fastest" and the scaling workloads: the choice is the cheapest
// measured setting within the tolerance, its sub-steps cover its dt; the scaling
// helpers report what they measured.
#include "game/bench/choose.h"
#include "game/bench/scaling.h"
#include "physics/rigid/rigid_world.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace game::bench;
using phys::Integrator;

TEST(Choose, PicksTheCheapestPointOfTheSceneWithinTolerance) {
    const std::vector<WorkPrecisionPoint> pts = {
        {AccuracyScene::Spring, Integrator::RK4, 0.02, 100, 1e-6, 4.0, 0},
        {AccuracyScene::Spring, Integrator::SymplecticEuler, 0.001, 2000, 5e-4, 2.0, 0},
        // Cheaper and accurate, but another scene: never chosen for the spring.
        {AccuracyScene::Orbit, Integrator::Leapfrog, 0.01, 200, 1e-9, 0.1, 0},
    };
    auto c = chooseCheapest(AccuracyScene::Spring, 1e-3, pts);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->integrator, Integrator::SymplecticEuler);
    EXPECT_EQ(c->error, 5e-4);
    EXPECT_EQ(c->cpuSecondsPerSimSecond, 2.0);
    EXPECT_EQ(c->tolerance, 1e-3);
    c = chooseCheapest(AccuracyScene::Spring, 1e-5, pts);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->integrator, Integrator::RK4);
    EXPECT_FALSE(chooseCheapest(AccuracyScene::Spring, 1e-7, pts));
}

TEST(Choose, SubstepsMakeTheStepNoLongerThanTheChosenDt) {
    MethodChoice c;
    c.dt = 1.0 / 480.0;
    EXPECT_EQ(c.substepsPerTick(1.0 / 120.0), 4);
    c.dt = 0.003;
    EXPECT_EQ(c.substepsPerTick(1.0 / 120.0), 3); // 1/360 s <= 0.003 s
    c.dt = 0.05;
    EXPECT_EQ(c.substepsPerTick(1.0 / 120.0), 1);
}

TEST(Choose, MeasuredChoiceMeetsTheToleranceOnTheSpring) {
    // A real (small) sweep: whatever wins, its measured error is within the tolerance,
    // and no point of the sweep within it is cheaper.
    WorkPrecisionDef d = choiceSweep(AccuracyScene::Spring);
    d.halvings = 3;
    d.repeats = 1;
    const auto pts = runWorkPrecision(d);
    const auto c = chooseCheapest(AccuracyScene::Spring, 1e-3, pts);
    ASSERT_TRUE(c);
    EXPECT_LE(c->error, 1e-3);
    for (const auto& p : pts)
        if (p.error <= 1e-3) {
            EXPECT_GE(p.cpuSecondsPerSimSecond, c->cpuSecondsPerSimSecond);
        }
}

TEST(ScalingWorkloads, PileComparisonStepsBothPilesOfTheSameSize) {
    const PileComparison r = comparePiles(100, 20, 3);
    EXPECT_EQ(r.balls, 100);
    EXPECT_GT(r.particleMs, 0.0);
    EXPECT_GT(r.rigidMs, 0.0);
    EXPECT_NEAR(r.speedup(), r.rigidMs / r.particleMs, 1e-12);
    // Three windows of 20 ticks each; the figures are the whole span's cost per step, the
    // windows' mean (they are equally long), not the median of three stages of the drop.
    EXPECT_EQ(r.windowTicks, 20);
    ASSERT_EQ(r.particleWindowMs.size(), 3u);
    ASSERT_EQ(r.rigidWindowMs.size(), 3u);
    ASSERT_EQ(r.asleepAfterWindow.size(), 3u);
    ASSERT_EQ(r.tunedRigidWindowMs.size(), 3u);
    auto mean = [](const std::vector<double>& v) { return (v[0] + v[1] + v[2]) / 3.0; };
    EXPECT_NEAR(r.particleMs, mean(r.particleWindowMs), 1e-12 * r.particleMs);
    EXPECT_NEAR(r.rigidMs, mean(r.rigidWindowMs), 1e-12 * r.rigidMs);
    EXPECT_NEAR(r.tunedRigidMs, mean(r.tunedRigidWindowMs), 1e-12 * r.tunedRigidMs);
    EXPECT_NEAR(r.speedupOverTuned(), r.tunedRigidMs / r.particleMs, 1e-12);
    EXPECT_EQ(r.firstTick(), kPileSettleTicks + 1);
    EXPECT_EQ(r.lastTick(), kPileSettleTicks + 60);
    for (const int asleep : r.asleepAfterWindow) {
        EXPECT_GE(asleep, 0);
        EXPECT_LE(asleep, 100);
    }
    // Each window's awake ball-ticks, counted again from the particles' sleep flags of
    // the same deterministic drop.
    ASSERT_EQ(r.awakeBallTicks.size(), 3u);
    auto pile = particlePile(100);
    for (int i = 0; i < kPileSettleTicks; ++i) pile->step();
    for (std::size_t k = 0; k < 3; ++k) {
        long awake = 0;
        for (int i = 0; i < 20; ++i) {
            pile->step();
            for (const auto flags : pile->particles.flags)
                awake += (flags & phys::kAlive) && !(flags & phys::kSleeping) ? 1 : 0;
        }
        EXPECT_EQ(r.awakeBallTicks[k], awake) << "window " << k;
    }
    // The pile falls asleep within these windows: most of it is awake in the first and
    // asleep in the last.
    EXPECT_GT(r.awakeBallTicks.front(), 20 * 100 / 2);
    EXPECT_LT(r.awakeBallTicks.back(), 20 * 100 / 2);
}

// Runs of the comparison: each side's figure is its fastest run, with that run's windows
// (so the figure is still the mean of the windows it prints), and every run's figure is
// kept for the spread. The sleepers are the drop's, the same in every run.
TEST(ScalingWorkloads, APileComparisonOfRunsKeepsEachSidesFastestRun) {
    const PileComparison one = comparePiles(100, 10, 2);
    EXPECT_EQ(one.runs, 1);
    EXPECT_EQ(one.particleRunMs, std::vector<double>{one.particleMs});
    const PileComparison r = comparePiles(100, 10, 2, 3);
    EXPECT_EQ(r.runs, 3);
    for (const auto* runs : {&r.particleRunMs, &r.rigidRunMs, &r.tunedRigidRunMs})
        ASSERT_EQ(runs->size(), 3u);
    EXPECT_EQ(r.particleMs, *std::min_element(r.particleRunMs.begin(), r.particleRunMs.end()));
    EXPECT_EQ(r.rigidMs, *std::min_element(r.rigidRunMs.begin(), r.rigidRunMs.end()));
    EXPECT_EQ(r.tunedRigidMs,
              *std::min_element(r.tunedRigidRunMs.begin(), r.tunedRigidRunMs.end()));
    auto mean = [](const std::vector<double>& v) { return (v[0] + v[1]) / 2.0; };
    EXPECT_NEAR(r.particleMs, mean(r.particleWindowMs), 1e-12 * r.particleMs);
    EXPECT_NEAR(r.rigidMs, mean(r.rigidWindowMs), 1e-12 * r.rigidMs);
    EXPECT_NEAR(r.tunedRigidMs, mean(r.tunedRigidWindowMs), 1e-12 * r.tunedRigidMs);
    EXPECT_EQ(r.asleepAfterWindow, one.asleepAfterWindow);
    EXPECT_EQ(r.awakeBallTicks, one.awakeBallTicks);
}

// The heap is the pile's balls with every other row half a spacing to the right, in a box
// wider by as much, as particles and as Box2D circles alike, all inside the box (a radius
// from each wall).
TEST(ScalingWorkloads, TheHeapIsThePileWithEveryOtherRowHalfASpacingOver) {
    constexpr long kBalls = 300;
    auto pile = particlePile(kBalls), heap = particlePile(kBalls, PileShape::Staggered);
    auto rigidHeap = rigidPile(kBalls, {}, PileShape::Staggered);
    const phys::ParticleSet &p = pile->particles, &h = heap->particles;
    ASSERT_EQ(h.slots(), static_cast<std::size_t>(kBalls));
    const auto columns = static_cast<std::size_t>(std::ceil(std::sqrt(2.0 * kBalls)));
    const double width = 0.12 * static_cast<double>(columns + 1) + 0.06; // half a spacing more
    std::vector<phys::Vec2> bodies;
    for (const phys::BodyId id : rigidHeap->bodies())
        if (rigidHeap->state(id).type == phys::BodyType::Dynamic)
            bodies.push_back(rigidHeap->state(id).position);
    ASSERT_EQ(bodies.size(), h.slots());
    int shifted = 0;
    for (std::size_t i = 0; i < h.slots(); ++i) {
        const bool oddRow = (i / columns) % 2 == 1;
        EXPECT_NEAR(h.px[i] - p.px[i], oddRow ? 0.06 : 0.0, 1e-12) << "ball " << i;
        EXPECT_EQ(h.py[i], p.py[i]);
        EXPECT_GE(h.px[i], 0.05);
        EXPECT_LE(h.px[i], width - 0.05);
        EXPECT_NEAR(bodies[i].x, h.px[i], 1e-6); // Box2D keeps floats
        EXPECT_NEAR(bodies[i].y, h.py[i], 1e-6);
        shifted += oddRow ? 1 : 0;
    }
    EXPECT_GT(shifted, kBalls / 3);
}

// The tuned Box2D pile is the game's pile with every length (and gravity) ten times:
// the same motion in Box2D's units. Before anything lands, every ball has fallen exactly
// ten times as far, to float rounding; and without time of impact nothing leaves the box.
TEST(ScalingWorkloads, TheTunedBox2DPileIsTheSamePileScaled) {
    constexpr long kBalls = 300;
    auto game = rigidPile(kBalls);
    auto tuned = rigidPile(kBalls, kTunedBox2D);
    const double tick = phys::WorldDef{}.tickSeconds, s = kTunedBox2D.scale;
    const std::vector<phys::BodyId> a = game->bodies(), b = tuned->bodies();
    ASSERT_EQ(a.size(), b.size());
    // 5 ticks: 0.4 cm of fall, less than the 2 cm gaps between the rows.
    for (int t = 0; t < 5; ++t)
        game->step(tick), tuned->step(tick);
    for (std::size_t k = 0; k < a.size(); ++k) {
        const phys::RigidBodyState x = game->state(a[k]), y = tuned->state(b[k]);
        if (x.type != phys::BodyType::Dynamic) continue;
        ASSERT_NEAR(y.position.x, s * x.position.x, 1e-5 * s * std::abs(x.position.x) + 1e-9);
        ASSERT_NEAR(y.position.y, s * x.position.y, 1e-5 * s * std::abs(x.position.y) + 1e-9);
        ASSERT_NEAR(y.linearVelocity.y, s * x.linearVelocity.y,
                    1e-4 * s * std::abs(x.linearVelocity.y));
    }
    for (int t = 5; t < 600; ++t)
        tuned->step(tick); // 5 s: landed and settled
    double left = 1e9, right = -1e9, lowest = 1e9;
    for (const phys::BodyId id : b) {
        const phys::RigidBodyState y = tuned->state(id);
        if (y.type != phys::BodyType::Dynamic) continue;
        left = std::min(left, y.position.x), right = std::max(right, y.position.x);
        lowest = std::min(lowest, y.position.y);
    }
    const double radius = 0.05 * s;
    EXPECT_GT(left, 0.99 * radius);
    EXPECT_GT(lowest, 0.95 * radius) << "a ball sank into or through the floor";
    EXPECT_LT(right, s * 0.12 * (std::ceil(std::sqrt(2.0 * kBalls)) + 1.0) - 0.99 * radius);
}

TEST(ScalingWorkloads, TheLeadGrowsOnlyIfEveryLargerPileLeadsByMore) {
    auto pile = [](long balls, double particleMs, double rigidMs) {
        PileComparison p;
        p.balls = balls, p.particleMs = particleMs, p.rigidMs = rigidMs;
        return p;
    };
    EXPECT_EQ(firstLeadThatDoesNotGrow({}), nullptr);
    EXPECT_EQ(firstLeadThatDoesNotGrow({pile(1000, 1, 14)}), nullptr);
    const std::vector<PileComparison> growing{pile(1000, 1, 4), pile(2000, 1, 6),
                                              pile(4000, 1, 17)};
    EXPECT_EQ(firstLeadThatDoesNotGrow(growing), nullptr);
    // 14.0x, 11.7x, 19.6x: the 2,000 balls are where it stops growing.
    const std::vector<PileComparison> dips{pile(1000, 0.108, 1.51), pile(2000, 0.319, 3.72),
                                           pile(4000, 1.34, 26.3)};
    EXPECT_EQ(firstLeadThatDoesNotGrow(dips), &dips[1]);
    // Equal leads do not grow.
    const std::vector<PileComparison> flat{pile(1000, 1, 5), pile(2000, 2, 10)};
    EXPECT_EQ(firstLeadThatDoesNotGrow(flat), &flat[1]);
    // Over the tuned Box2D: 5.6x, 5.7x, 4.9x stop growing at 4,000 balls, while the lead
    // over the game's Box2D grows.
    std::vector<PileComparison> both{pile(1000, 0.181, 1.84), pile(2000, 0.43, 10.8),
                                     pile(4000, 1.52, 44.4)};
    const double tunedMs[] = {1.01, 2.45, 7.5};
    for (std::size_t k = 0; k < both.size(); ++k)
        both[k].tunedRigidMs = tunedMs[k];
    EXPECT_EQ(firstLeadThatDoesNotGrow(both), nullptr);
    EXPECT_EQ(firstLeadThatDoesNotGrow(both, &PileComparison::speedupOverTuned), &both[2]);
}

TEST(ScalingWorkloads, ExponentOfExactlyLinearCostIsOne) {
    std::vector<ScalingPoint> pts;
    for (long n : {1000L, 10000L, 100000L}) pts.push_back({"x", n, 0.02 * n, 20.0});
    EXPECT_NEAR(scalingExponent(pts), 1.0, 1e-12);
    pts.back().usPerStep *= 10.0; // quadratic at the end
    EXPECT_GT(scalingExponent(pts), 1.3);
}
