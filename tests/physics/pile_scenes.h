// The scenes of the pile tests (pile_test.cpp, pile_solver_test.cpp,
// pile_same_bits_test.cpp): balls dropped into a box in columns or staggered rows, shots
// into a settled heap, elastic balls rattling in a box, and the way to play a world two
// ways and hold the ticks against each other.
#pragma once

#include "physics/diagnostics.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace phys::piles {

inline constexpr double kR = 0.05; // ball radius, m

struct Heap {
    World world;
    double width = 0.0;
};

// n wooden balls on a grid 0.12 m apart, staggered (each row offset by half a spacing)
// or in columns (the pile of `artillery bench scaling`), dropped into an open box.
inline Heap droppedBalls(int n, bool staggered) {
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
inline Heap staggeredHeap(int n) {
    return droppedBalls(n, true);
}

// The deepest overlap between two balls, or of a ball with the floor or a wall, m.
inline double worstOverlap(const ParticleSet& p, double width) {
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

inline int sleeping(const ParticleSet& p) {
    int n = 0;
    for (const auto f : p.flags)
        n += (f & kSleeping) ? 1 : 0;
    return n;
}

struct PlayedTick {
    std::uint64_t hash;
    std::vector<ContactEvent> contacts;
    int pairs, changesOnly, sleeping;
};

inline void dropShots(World& w, int t) {
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
inline World rattlingBox(unsigned seed, int n, double side, double speed) {
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
inline std::vector<PlayedTick> playWith(Set set, int ticks, Build build, Act act) {
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
inline std::vector<PlayedTick> playBothWays(bool changesOnly, int ticks, Build build, Act act) {
    return playWith([=](CollisionDef& c) { c.redetectChangesOnly = changesOnly; }, ticks, build,
                    act);
}

inline bool sameContact(const ContactEvent& x, const ContactEvent& y) {
    return x.a == y.a && x.b == y.b && x.shape.kind == y.shape.kind &&
           x.shape.index == y.shape.index && x.time == y.time && x.normal.x == y.normal.x &&
           x.normal.y == y.normal.y && x.closingSpeed == y.closingSpeed && x.impulse == y.impulse &&
           x.resting == y.resting && x.position.x == y.position.x && x.position.y == y.position.y &&
           x.velocity.x == y.velocity.x && x.velocity.y == y.velocity.y;
}

// Also: a later pass tests fewer than 1 / `fewerPairs` of the pairs full detection tests.
template <class Build, class Act>
inline void expectTheFullDetectionsBits(const std::string& scene, int ticks, double fewerPairs,
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

} // namespace phys::piles
