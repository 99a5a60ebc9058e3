// The shortcuts of the collision stages end every tick in the bits of the full work: the
// kept pairs mended rather than rebuilt (pair_cache.h), no broad phase as a heap falls
// asleep, later passes that detect only the changes (toi_passes.h), live pairs filtered as
// kinds fall, settled sleepers skipped (awake_set.h), and a world stepped without its
// profile.
#include "pile_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

using namespace phys;
using namespace phys::piles;

// A ball bouncing out of its fattened box in a falling pile mends the pile's kept pairs
// (a test of its box against the others) instead of rebuilding them all, and the pile
// ends bit for bit as when every escape rebuilds. In the first two seconds of 3,000 balls
// dropped in columns: 18 rebuilds and 84 mends, against 65 rebuilds (one rebuild brings
// the next: every fat box is regrown around where its ball is now).
TEST(Pile, EscapesMendTheKeptPairsWithTheRebuildsBits) {
    auto settle = [](bool patchPairs, int& broadPhases, int& patches) {
        Heap heap = droppedBalls(3000, false);
        WorldDef d = heap.world.def();
        d.collision.patchPairs = patchPairs;
        // Every pass checks the kept pairs (later passes that detect only the changes
        // check only the changed particles, and leave the rest to the next full check).
        d.collision.redetectChangesOnly = false;
        heap.world.setDef(d);
        broadPhases = patches = 0;
        for (int t = 0; t < 240; ++t) {
            heap.world.step();
            broadPhases += heap.world.collisionStats().broadPhases;
            patches += heap.world.collisionStats().cachePatches;
        }
        return heap.world.hash();
    };
    int mendedBroadPhases = 0, patches = 0, rebuiltBroadPhases = 0, none = 0;
    const std::uint64_t mended = settle(true, mendedBroadPhases, patches);
    const std::uint64_t rebuilt = settle(false, rebuiltBroadPhases, none);
    EXPECT_EQ(mended, rebuilt);
    EXPECT_EQ(none, 0);
    EXPECT_GT(patches, 0);
    EXPECT_LE(mendedBroadPhases * 3, rebuiltBroadPhases * 2); // a third of them spared at least
    std::printf("3,000 balls, 240 ticks: %d rebuilds and %d mends, against %d rebuilds\n",
                mendedBroadPhases, patches, rebuiltBroadPhases);
}

// A particle that falls asleep only loses pairs (two resting proxies never pair), so the
// broad phase's kept pairs still hold every pair there is, filtered by the kinds of now:
// a heap falling asleep a few balls a tick runs no broad phase for it. (Before, every
// tick after one in which a ball fell asleep rebuilt the pairs of the whole heap.) The
// pairs are the same either way, so this costs nothing in the result: the golden
// replays and the pile benchmark's world hashes did not change.
TEST(Pile, FallingAsleepCostsNoBroadPhase) {
    Heap heap = staggeredHeap(400);
    World& w = heap.world;
    int before = 0, ticksFallingAsleep = 0, rebuiltAfter = 0, broadPhases = 0;
    bool fellAsleep = false;
    for (int t = 0; t < 600; ++t) {
        w.step();
        const int now = sleeping(w.particles);
        broadPhases += w.collisionStats().broadPhases;
        if (fellAsleep && w.collisionStats().broadPhases > 0) ++rebuiltAfter;
        fellAsleep = now > before;
        ticksFallingAsleep += fellAsleep ? 1 : 0;
        before = now;
    }
    ASSERT_GE(ticksFallingAsleep, 20); // the heap fell asleep over many ticks
    EXPECT_LE(rebuiltAfter, ticksFallingAsleep / 10);
    EXPECT_LE(broadPhases, 60); // in 600 ticks of eight passes and a solve each
}


// A pass after the first detects again only what the pass before it changed (the paths
// it bounced, the resting pairs it left to the solver: toi_passes.h), and every tick
// ends bit for bit as when every pass detects over every particle: the same world hash
// and the same contacts, field for field. The scenes have all that a pass can leave:
//   heap     1,500 balls dropped in columns (impacts, resting pairs, balls falling
//            asleep), then, into the settled heap, a glass marble every few ticks at
//            12 m/s (sleepers woken) and bouncy golf balls above it;
//   rattles  40 perfectly elastic balls in a 0.8 m box without gravity, some at up to
//            40 m/s, 60 seeds: chains of impacts through all eight passes, balls
//            knocked out of their fat boxes (strays) and hit while they are.
TEST(Pile, LaterPassesDetectOnlyWhatChangedWithTheFullDetectionsBits) {
    // (2.6 times fewer pairs; 3.4 before the balls on two sleepers stopped alternating
    // through all the passes, whose later ones test few.)
    expectTheFullDetectionsBits(
        "heap of 1,500 balls, marbles and golf balls", 240, 2.5,
        [] { return std::move(droppedBalls(1500, false).world); }, dropShots);
    // Without the test of a changed particle against the strays (a ball knocked out of
    // its fat box, then hit by a neighbour whose kept pairs never held it), seed 18 parts
    // at its first tick, and 29 later.
    for (unsigned seed = 1; seed <= 60; ++seed)
        expectTheFullDetectionsBits(
            "rattling box, seed " + std::to_string(seed), 40, 1.0,
            [seed] { return rattlingBox(seed, 40, 0.8, 40.0); }, [](World&, int) {}, false);
}

// The live pairs (the kept pairs the kinds of now can make) are filtered from the last
// live pairs while kinds only fall (balls falling asleep), and from the whole cache when
// one rises (a ball woken or added). Either way they are the pairs a fresh broad phase
// gives: the heap, shot at as it falls asleep, ends every tick in the same bits when each
// tick's first detection builds the cache again (the grid's cell size, for which the
// cache is kept, alternates; the grid finds the same pairs at any cell size).
TEST(Pile, LivePairsKeptAsKindsFallAreThoseOfAFreshBroadPhase) {
    auto build = [] { return std::move(droppedBalls(1500, false).world); };
    const auto kept = playWith([](CollisionDef&) {}, 240, build, dropShots);
    const auto fresh = playWith([](CollisionDef&) {}, 240, build, [](World& w, int t) {
        dropShots(w, t);
        WorldDef d = w.def();
        d.collision.gridCellSize = t % 2 == 0 ? 0.0 : 0.25;
        w.setDef(d);
    });
    int mostAsleep = 0;
    for (std::size_t t = 0; t < kept.size(); ++t) {
        ASSERT_EQ(kept[t].hash, fresh[t].hash) << "tick " << t;
        mostAsleep = std::max(mostAsleep, kept[t].sleeping);
    }
    EXPECT_GT(mostAsleep, 500); // the kinds fell: a third of the heap asleep at once
}

// A sleeper that a sub-step left as it was (asleep, at rest, untouched by any contact) is
// settled: the sub-steps after it skip it, until something changes it. The world ends
// every tick in the bits of one that works on every particle, contacts, impulses and
// sleepers included, through a heap falling asleep, shots landing on it, and all that
// changes a sleeper from outside: moved, pushed, its slot emptied and filled by another
// sleeper elsewhere (with the same flags) that a ball then lands on, a sleeper added with
// a velocity, all woken at once, a new tolerance (which the boxes grow by).
TEST(Pile, SettledSleepersAreSkippedWithTheBitsOfWorkingOnEveryParticle) {
    auto firstSleeper = [](const ParticleSet& p, std::size_t from) {
        for (std::size_t i = from; i < p.slots(); ++i)
            if ((p.flags[i] & kAlive) && (p.flags[i] & kSleeping))
                return static_cast<ParticleId>(i);
        return kNoParticle;
    };
    auto ball = [](Vec2 at) {
        ParticleDef d;
        d.position = at;
        d.radius = kR;
        d.mass = 0.3;
        d.material = material::kWooden;
        return d;
    };
    auto act = [&](World& w, int t) {
        ParticleSet& p = w.particles;
        double top = 0.0;
        for (std::size_t i = 0; i < p.slots(); ++i)
            if (p.flags[i] & kAlive) top = std::max(top, p.py[i]);
        if (t == 280) {
            const ParticleId s = firstSleeper(p, 50);
            ASSERT_NE(s, kNoParticle);
            p.setPosition(s, p.position(s) + Vec2{0.0, 0.3});
        }
        if (t == 300) p.setVelocity(firstSleeper(p, 100), {0.5, 0.0});
        if (t == 320) { // the slot of a sleeper, refilled asleep with the same flags, above
            const ParticleId s = firstSleeper(p, 150);
            ASSERT_NE(s, kNoParticle);
            const std::uint32_t flags = p.flags[s];
            const Vec2 at = {p.px[s], top + 0.5};
            p.remove(s);
            ParticleDef d = ball(at);
            d.flags = flags & ~kAlive;
            ASSERT_EQ(p.add(d), s);
            ASSERT_EQ(p.flags[s], flags);
        }
        if (t == 322) { // a ball dropped onto the sleeper of the refilled slot
            const ParticleId s = firstSleeper(p, 150);
            p.add(ball(p.position(s) + Vec2{0.0, 0.3}));
        }
        if (t == 360) {
            ParticleDef d = ball({0.4, top + 0.3});
            d.flags = kSleeping;
            d.velocity = {0.2, 0.0};
            p.add(d);
        }
        if (t == 380) w.wakeAll();
        if (t == 420) {
            WorldDef d = w.def();
            d.collision.toiTolerance *= 2.0;
            w.setDef(d);
        }
    };
    std::vector<int> sleeping[2], active[2];
    std::vector<PlayedTick> played[2];
    for (const bool skip : {true, false}) {
        const auto build = [] { return std::move(staggeredHeap(400).world); };
        played[skip] = playWith([&](CollisionDef& c) { c.skipSettled = skip; }, 450, build,
                                [&](World& w, int t) {
                                    if (t > 0) {
                                        sleeping[skip].push_back(w.collisionStats().sleeping);
                                        active[skip].push_back(w.collisionStats().active);
                                    }
                                    act(w, t);
                                });
    }
    long skipped = 0, every = 0;
    for (std::size_t t = 0; t < played[0].size(); ++t) {
        ASSERT_EQ(played[1][t].hash, played[0][t].hash) << "tick " << t;
        ASSERT_EQ(played[1][t].contacts.size(), played[0][t].contacts.size()) << "tick " << t;
        for (std::size_t k = 0; k < played[1][t].contacts.size(); ++k)
            ASSERT_TRUE(sameContact(played[1][t].contacts[k], played[0][t].contacts[k]))
                << "tick " << t << ", contact " << k;
    }
    for (std::size_t t = 0; t < active[0].size(); ++t) {
        ASSERT_EQ(sleeping[1][t], sleeping[0][t]) << "tick " << t;
        skipped += active[1][t], every += active[0][t];
    }
    // The heap sleeps whole before the first change: from then on only what changes and
    // what it wakes is worked on, with the sleepers that what moved held up: 50 % of the
    // work of every particle.
    EXPECT_EQ(sleeping[1][278], 400);
    EXPECT_LT(skipped * 5, every * 3);
    std::printf("heap of 400 balls, 450 ticks: %ld particles worked on, against %ld\n", skipped,
                every);

    // A ball that falls asleep on the floor, where no contact solver runs (the passes hold
    // it up), and a stack of two sliding towards it later, which the solver settles: it
    // slows the stack's lower ball, a few hundredths of a radius from the sleeper at the
    // end of a step, to what the gap allows (a contact that only the boxes the solver has
    // for the sleeper find).
    auto lone = [&] {
        World w;
        w.shapes.addSegment({-1.0, 0.0}, {1.0, 0.0}, material::kWooden);
        w.particles.add(ball({0.0, kR}));
        return w;
    };
    auto slideStack = [&](World& w, int t) {
        if (t != 90) return;
        ASSERT_TRUE(w.particles.flags[0] & kSleeping);
        for (const double y : {kR, 3.0 * kR + 1e-6}) {
            ParticleDef d = ball({2.0 * kR + 0.001, y});
            d.velocity = {-0.1, 0.0};
            w.particles.add(d);
        }
    };
    const auto skipping =
        playWith([](CollisionDef& c) { c.skipSettled = true; }, 130, lone, slideStack);
    const auto working =
        playWith([](CollisionDef& c) { c.skipSettled = false; }, 130, lone, slideStack);
    for (std::size_t t = 0; t < skipping.size(); ++t)
        ASSERT_EQ(skipping[t].hash, working[t].hash) << "lone ball, tick " << t;
}


// The profile's clock is only read around the step's phases, never inside them: a world
// stepped with profiling off (as the aim preview and the computer's trial shots are) ends
// bit for bit where the profiled one does, with no time on its profile.
TEST(Pile, AWorldSteppedWithoutItsProfileEndsInTheSameBits) {
    Heap profiled = staggeredHeap(200), quiet = staggeredHeap(200);
    quiet.world.setProfiling(false);
    double timed = 0.0;
    for (int t = 0; t < 240; ++t) {
        profiled.world.step();
        quiet.world.step();
        timed += profiled.world.profile().totalUs;
        const StepProfile& p = quiet.world.profile();
        ASSERT_EQ(p.totalUs + p.integrateUs + p.collideUs + p.resolveUs + p.constraintsUs +
                      p.springsUs,
                  0.0)
            << "tick " << t;
        EXPECT_EQ(p.sleeping, profiled.world.profile().sleeping); // the counts stay
    }
    EXPECT_GT(timed, 0.0);
    EXPECT_EQ(quiet.world.hash(), profiled.world.hash());
}
