// The contact solver at the end of the step (contact_solver.h) in piles: resting pairs are
// reported with the impulse that carries their weight, impacts are left to the passes, the
// position sweeps stop where nothing is deep, and the sweeps in wavefronts of four lanes
// give the bits of the sweeps in their own order.
#include "pile_scenes.h"
#include "physics/collision/simd/contact_rows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

using namespace phys;
using namespace phys::piles;

// A resting pair of free particles goes to the solver, and is still a contact of the
// tick: a ball sitting on another reports it, as resting, with the impulse that carries
// its weight over the step (m g h).
TEST(Pile, RestingPairsAreReportedWithTheImpulseThatCarriesTheWeight) {
    WorldDef d;
    d.collision.sleep = false;
    World w(d);
    w.shapes.addSegment({-1.0, 0.0}, {1.0, 0.0}, material::kWooden);
    ParticleDef pd;
    pd.radius = kR;
    pd.mass = 0.2;
    pd.material = material::kWooden;
    pd.position = {0.0, kR};
    const auto low = w.particles.add(pd);
    pd.position = {0.0, 3.0 * kR};
    const auto high = w.particles.add(pd);
    for (int t = 0; t < 60; ++t)
        w.step();
    int pairs = 0;
    for (const ContactEvent& e : w.contacts())
        if (e.b != kNoParticle) {
            ++pairs;
            EXPECT_TRUE(e.resting);
            EXPECT_EQ(e.a, low);
            EXPECT_EQ(e.b, high);
            EXPECT_NEAR(e.impulse, 0.2 * 9.81 / 120.0, 1e-9);
        }
    EXPECT_EQ(pairs, 1);
    EXPECT_NEAR(w.particles.py[high], 3.0 * kR, 1e-12);
}

// The contact solver settles resting contacts; an impact is the passes' to resolve, at
// its time of impact, with the pair's e. A ball that ends a step just short of a wall
// (within the solver's speculative reach) while a column rests elsewhere, so that the
// solver runs in that step, bounces off the wall with its whole speed: e = 1 returns
// v_x exactly. (Held to the speed the gap allows, it used to arrive at 0.6 m/s of 6.)
TEST(Pile, TheSolverLeavesAnImpactToThePasses) {
    World w;
    w.shapes.addSegment({-10.0, 0.0}, {10.0, 0.0}, material::kPerfectlyElastic);
    w.shapes.addSegment({5.0, 0.0}, {5.0, 10.0}, material::kPerfectlyElastic);
    for (int i = 0; i < 3; ++i) { // the column: its resting pairs go to the solver
        ParticleDef pd;
        pd.position = {-5.0, kR + 2.0 * kR * i};
        pd.radius = kR;
        pd.material = material::kWooden;
        w.particles.add(pd);
    }
    // 6 m/s is 0.05 m a tick at 120 Hz: after 10 ticks the ball's edge is 5 mm from the
    // wall (a twentieth of its radius), and it hits the wall in the 11th.
    const double r = 0.1, v = 6.0, gap = 0.005;
    ParticleDef ball;
    ball.radius = r;
    ball.material = material::kPerfectlyElastic;
    ball.position = {5.0 - r - gap - 10.0 * v / 120.0, 5.0};
    ball.velocity = {v, 0.0};
    const ParticleId id = w.particles.add(ball);
    for (int t = 0; t < 10; ++t)
        w.step();
    ASSERT_NEAR(w.particles.px[id] + r, 5.0 - gap, 1e-12);
    ASSERT_EQ(w.particles.vx[id], v);
    w.step();
    EXPECT_EQ(w.particles.vx[id], -v);
    EXPECT_NEAR(w.particles.px[id] + r, 5.0 - (v / 120.0 - gap), 1e-9); // toiTolerance
}

// The position sweeps over all contacts after the first run only while one pushed a pair
// apart by more than a tenth of a radius: a heap resting awake (sleep off) gets the bits
// of one sweep whatever the most is, and one that a heavy ball lands in does not.
TEST(Pile, ARestingHeapGetsOneSweepOverAllContactsALandingMore) {
    auto play = [](int positionSweeps, bool landing) {
        Heap heap = staggeredHeap(400);
        WorldDef d = heap.world.def();
        d.collision.sleep = false;
        heap.world.setDef(d);
        for (int t = 0; t < 360; ++t)
            heap.world.step();
        d.collision.relaxPositionSweeps = positionSweeps;
        heap.world.setDef(d);
        if (landing) {
            ParticleDef shot;
            shot.position = {heap.width / 2.0, 3.0};
            shot.velocity = {0.0, -8.0};
            shot.radius = 2.0 * kR;
            shot.mass = 5.0;
            shot.material = material::kWooden;
            heap.world.particles.add(shot);
        }
        for (int t = 0; t < 120; ++t)
            heap.world.step();
        return heap.world.hash();
    };
    EXPECT_EQ(play(1, false), play(4, false)) << "resting";
    EXPECT_NE(play(1, true), play(4, true)) << "landing";
}


// The contact solver's sweeps laid out in wavefronts (contacts that share no particle),
// four at a time in AVX2 lanes where the processor has them, end every tick in the bits
// of the sweeps one contact at a time in their own order, contacts and impulses included:
// a heap of like balls that marbles and golf balls land on (three masses, sleepers, the
// walls, shock propagation in the bands), and boxes of elastic balls without gravity.
TEST(Pile, TheSweepsInWavefrontsGiveTheBitsOfTheSweepsInOrder) {
    auto expectSameBits = [](const std::string& scene, int ticks, auto build, auto act) {
        const auto lanes =
            playWith([](CollisionDef& c) { c.contactLanes = true; }, ticks, build, act);
        const auto inOrder =
            playWith([](CollisionDef& c) { c.contactLanes = false; }, ticks, build, act);
        for (std::size_t t = 0; t < lanes.size(); ++t) {
            ASSERT_EQ(lanes[t].hash, inOrder[t].hash) << scene << ", tick " << t;
            ASSERT_EQ(lanes[t].contacts.size(), inOrder[t].contacts.size())
                << scene << ", tick " << t;
            for (std::size_t k = 0; k < lanes[t].contacts.size(); ++k)
                ASSERT_TRUE(sameContact(lanes[t].contacts[k], inOrder[t].contacts[k]))
                    << scene << ", tick " << t << ", contact " << k;
        }
    };
    std::printf("the sweeps run in AVX2 lanes here: %s\n", contactLanesAvailable() ? "yes" : "no");
    expectSameBits(
        "heap of 1,500 balls, marbles and golf balls", 300,
        [] { return std::move(droppedBalls(1500, false).world); }, dropShots);
    for (unsigned seed = 1; seed <= 10; ++seed)
        expectSameBits(
            "rattling box, seed " + std::to_string(seed), 60,
            [seed] { return rattlingBox(seed, 60, 0.8, 10.0); }, [](World&, int) {});
}

// In a heap whose balls touch side by side, a row of balls listed pair by pair is a
// chain of contacts, one wavefront each: in lanes, nearly three rows a contact. Such a
// band is swept one row at a time instead (a band keeps its lanes up to two rows a
// contact), in the bits of the sweeps in order: the staggered heap lands and settles
// in the same bits with lanes as without, in at most two rows a contact, and some bands
// keep their lanes (where the processor has AVX2; elsewhere every row is a contact).
TEST(Pile, AHeapTouchingSideBySideSweepsItsChainsOneRowAtATimeInTheSameBits) {
    Heap lanes = staggeredHeap(1000), inOrder = staggeredHeap(1000);
    WorldDef d = inOrder.world.def();
    d.collision.contactLanes = false;
    inOrder.world.setDef(d);
    long contacts = 0, rows = 0;
    for (int t = 0; t < 150; ++t) {
        lanes.world.step();
        inOrder.world.step();
        ASSERT_EQ(lanes.world.hash(), inOrder.world.hash()) << "tick " << t;
        const CollisionStats &l = lanes.world.collisionStats(), &o = inOrder.world.collisionStats();
        EXPECT_EQ(o.solverRows, o.solverContacts);
        contacts += l.solverContacts;
        rows += l.solverRows;
    }
    std::printf("staggered heap of 1,000 balls, ticks 1-150: %ld contacts in %ld rows "
                "(lanes here: %s)\n",
                contacts, rows, contactLanesAvailable() ? "yes" : "no");
    EXPECT_GT(contacts, 150L * 1000); // most balls are in the solver's contacts
    EXPECT_LE(rows, 2 * contacts);
    if (contactLanesAvailable()) {
        EXPECT_GT(rows, contacts); // some bands keep their lanes
    }
}

