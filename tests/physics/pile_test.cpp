// Piles, stacks and heaps: the contact solver at the end of the step (particle_collisions.h)
// against exact answers: a column stands exactly still, a heap settles without overlaps,
// with nothing pushed through a wall, and falls asleep; resting pairs are still reported.
#include "physics/collision/simd/contact_rows.h"
#include "physics/diagnostics.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>

using namespace phys;

namespace {

constexpr double kR = 0.05; // ball radius, m

struct Heap {
    World world;
    double width = 0.0;
};

// n wooden balls on a grid 0.12 m apart, staggered (each row offset by half a spacing)
// or in columns (the pile of `artillery bench scaling`), dropped into an open box.
Heap droppedBalls(int n, bool staggered) {
    Heap heap;
    const int columns = static_cast<int>(std::ceil(std::sqrt(2.0 * n)));
    const int rows = (n + columns - 1) / columns;
    heap.width = 0.12 * columns + 0.18;
    const double top = 0.12 * (rows + 4);
    StaticShapes& s = heap.world.shapes;
    s.addSegment({0.0, 0.0}, {heap.width, 0.0}, material::kWooden);
    s.addSegment({0.0, 0.0}, {0.0, top}, material::kWooden);
    s.addSegment({heap.width, 0.0}, {heap.width, top}, material::kWooden);
    std::mt19937_64 rng(777);
    std::uniform_real_distribution<double> jitter(-0.01, 0.01);
    for (int i = 0; i < n; ++i) {
        const int c = i % columns, r = i / columns;
        ParticleDef pd;
        pd.position = {0.12 * (c + 1) + (staggered ? 0.06 * (r % 2) : 0.0) + jitter(rng),
                       0.12 * (r + 1) + jitter(rng)};
        pd.radius = kR;
        pd.mass = 0.1;
        pd.material = material::kWooden;
        heap.world.particles.add(pd);
    }
    return heap;
}

// n wooden balls on a staggered grid 0.12 m apart (each row offset by half a spacing, so
// they settle into a heap, not columns), dropped into an open box.
Heap staggeredHeap(int n) { return droppedBalls(n, true); }

// The deepest overlap between two balls, or of a ball with the floor or a wall, m.
double worstOverlap(const ParticleSet& p, double width) {
    double worst = 0.0;
    for (std::size_t i = 0; i < p.slots(); ++i) {
        worst = std::max({worst, kR - p.py[i], kR - p.px[i], kR - (width - p.px[i])});
        for (std::size_t j = i + 1; j < p.slots(); ++j)
            if (std::abs(p.px[i] - p.px[j]) < 2.0 * kR)
                worst = std::max(worst, 2.0 * kR - length(p.position(static_cast<ParticleId>(i)) -
                                                          p.position(static_cast<ParticleId>(j))));
    }
    return worst;
}

int sleeping(const ParticleSet& p) {
    int n = 0;
    for (const auto f : p.flags)
        n += (f & kSleeping) ? 1 : 0;
    return n;
}

} // namespace

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
namespace {

struct PlayedTick {
    std::uint64_t hash;
    std::vector<ContactEvent> contacts;
    int pairs, changesOnly, sleeping;
};

void dropShots(World& w, int t) {
    if (t >= 120 && t % 8 == 0) {
        ParticleDef shot;
        shot.position = {0.5 + 0.03 * (t % 40), 6.0};
        shot.velocity = {1.5, -12.0};
        shot.radius = 0.03;
        shot.mass = 0.05;
        shot.material = material::kGlassMarble;
        w.particles.add(shot);
    }
    if (t == 150)
        for (int k = 0; k < 40; ++k) {
            ParticleDef golf;
            golf.position = {0.3 + 0.1 * k, 5.0 + 0.05 * (k % 3)};
            golf.radius = 0.02;
            golf.mass = 0.046;
            golf.material = material::kGolf;
            w.particles.add(golf);
        }
}

// n perfectly elastic balls in a closed box without gravity, a third of them at up to
// `speed` m/s in x and y, the rest at rest where the seed puts them.
World rattlingBox(unsigned seed, int n, double side, double speed) {
    WorldDef d;
    d.forces.gravity = {0.0, 0.0};
    World w(d);
    const Vec2 corners[] = {{0.0, 0.0}, {side, 0.0}, {side, side}, {0.0, side}};
    for (int k = 0; k < 4; ++k)
        w.shapes.addSegment(corners[k], corners[(k + 1) % 4], material::kPerfectlyElastic);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < n; ++i) {
        ParticleDef pd;
        pd.position = {0.05 + (side - 0.1) * u(rng), 0.05 + (side - 0.1) * u(rng)};
        if (u(rng) < 0.3)
            pd.velocity = {speed * (2.0 * u(rng) - 1.0), speed * (2.0 * u(rng) - 1.0)};
        pd.radius = 0.02;
        pd.mass = 0.1;
        pd.material = material::kPerfectlyElastic;
        w.particles.add(pd);
    }
    return w;
}

// The world of build() with `set` applied to its collision settings, played for `ticks`.
template <class Set, class Build, class Act>
std::vector<PlayedTick> playWith(Set set, int ticks, Build build, Act act) {
    World w = build();
    WorldDef d = w.def();
    set(d.collision);
    w.setDef(d);
    std::vector<PlayedTick> played;
    for (int t = 0; t < ticks; ++t) {
        act(w, t);
        w.step();
        const CollisionStats& s = w.collisionStats();
        played.push_back({w.hash(), w.contacts(), s.pairs, s.changesOnly, s.sleeping});
    }
    return played;
}

template <class Build, class Act>
std::vector<PlayedTick> playBothWays(bool changesOnly, int ticks, Build build, Act act) {
    return playWith([=](CollisionDef& c) { c.redetectChangesOnly = changesOnly; }, ticks, build,
                    act);
}

bool sameContact(const ContactEvent& x, const ContactEvent& y) {
    return x.a == y.a && x.b == y.b && x.shape.kind == y.shape.kind &&
           x.shape.index == y.shape.index && x.time == y.time && x.normal.x == y.normal.x &&
           x.normal.y == y.normal.y && x.closingSpeed == y.closingSpeed && x.impulse == y.impulse &&
           x.resting == y.resting && x.position.x == y.position.x && x.position.y == y.position.y &&
           x.velocity.x == y.velocity.x && x.velocity.y == y.velocity.y;
}

// Also: a later pass tests fewer than 1 / `fewerPairs` of the pairs full detection tests.
template <class Build, class Act>
void expectTheFullDetectionsBits(const std::string& scene, int ticks, double fewerPairs,
                                 Build build, Act act, bool print = true) {
    const auto later = playBothWays(true, ticks, build, act);
    const auto full = playBothWays(false, ticks, build, act);
    long laterPairs = 0, fullPairs = 0, changesOnly = 0, fullChangesOnly = 0;
    for (std::size_t t = 0; t < later.size(); ++t) {
        ASSERT_EQ(later[t].hash, full[t].hash) << scene << ", tick " << t;
        ASSERT_EQ(later[t].contacts.size(), full[t].contacts.size()) << scene << ", tick " << t;
        for (std::size_t k = 0; k < later[t].contacts.size(); ++k)
            ASSERT_TRUE(sameContact(later[t].contacts[k], full[t].contacts[k]))
                << scene << ", tick " << t << ", contact " << k;
        laterPairs += later[t].pairs, fullPairs += full[t].pairs;
        changesOnly += later[t].changesOnly, fullChangesOnly += full[t].changesOnly;
    }
    EXPECT_EQ(fullChangesOnly, 0);
    EXPECT_GT(changesOnly, 0) << scene;
    EXPECT_LE(static_cast<double>(laterPairs) * fewerPairs, static_cast<double>(fullPairs))
        << scene;
    if (print)
        std::printf("%s, %d ticks: %ld passes detected only the changes; %ld pairs tested, "
                    "against %ld\n",
                    scene.c_str(), ticks, changesOnly, laterPairs, fullPairs);
}

} // namespace

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
