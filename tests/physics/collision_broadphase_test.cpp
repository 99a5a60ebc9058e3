// The broad phase returns exactly the pairs the naive all-pairs test returns.
#include "physics/collision/broadphase.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <random>

using namespace phys;

namespace {

struct Scene {
    std::vector<Aabb> boxes;
    std::vector<ProxyKind> kinds;
};

// n boxes scattered over a w x w field, sizes from points to a tenth of the field,
// some degenerate (segments along an axis), kinds mixed.
Scene randomScene(std::mt19937_64& rng, int n, double w) {
    std::uniform_real_distribution<double> pos(0.0, w), size(0.0, 0.1 * w), unit(0.0, 1.0);
    Scene s;
    for (int i = 0; i < n; ++i) {
        const Vec2 lo{pos(rng), pos(rng)};
        Vec2 ext{size(rng), size(rng)};
        if (unit(rng) < 0.1) ext.x = 0.0; // vertical wall
        if (unit(rng) < 0.1) ext.y = 0.0; // horizontal floor
        s.boxes.push_back({lo, lo + ext});
        const double k = unit(rng);
        s.kinds.push_back(k < 0.6    ? ProxyKind::Moving
                          : k < 0.95 ? ProxyKind::Resting
                                     : ProxyKind::None);
    }
    return s;
}

} // namespace

TEST(BroadPhase, GridAndSortAndSweepFindExactlyTheAllPairsPairs) {
    std::mt19937_64 rng(20261121);
    SortAndSweep sweep; // reused across scenes, as the world reuses it across steps
    UniformGrid grid;
    std::vector<ProxyPair> fast, slow, gridded;
    std::size_t total = 0;
    for (int scene = 0; scene < 60; ++scene) {
        const int n = 1 + scene * 7;
        Scene s = randomScene(rng, n, scene % 2 ? 10.0 : 100.0);
        // A few boxes far too big for the grid (floors, walls), and some far away.
        if (scene % 3 == 0)
            s.boxes.push_back({{-1.0, 2.0}, {200.0, 2.5}}), s.kinds.push_back(ProxyKind::Resting);
        if (scene % 5 == 0)
            s.boxes.push_back({{-1e9, -1e9}, {-1e9 + 1.0, -1e9 + 1.0}}),
                s.kinds.push_back(ProxyKind::Moving);
        if (scene % 4 == 0)
            s.boxes.push_back({{3.0, -5.0}, {3.0, 500.0}}), s.kinds.push_back(ProxyKind::Moving);
        sweep.findPairs(s.boxes, s.kinds, fast);
        allPairs(s.boxes, s.kinds, slow);
        ASSERT_EQ(fast, slow) << "scene " << scene;
        for (const double cell : {0.0, 0.37, 5.0}) {
            grid.findPairs(s.boxes, s.kinds, gridded, cell);
            ASSERT_EQ(gridded, slow) << "scene " << scene << " cell " << cell;
        }
        total += slow.size();
        // Move everything a little (the next frame) and check again.
        for (auto& b : s.boxes)
            b.lo.x += 0.5, b.hi.x += 0.5;
        sweep.findPairs(s.boxes, s.kinds, fast);
        allPairs(s.boxes, s.kinds, slow);
        ASSERT_EQ(fast, slow) << "scene " << scene << " moved";
        grid.findPairs(s.boxes, s.kinds, gridded);
        ASSERT_EQ(gridded, slow) << "scene " << scene << " moved";
    }
    EXPECT_GT(total, 1000u); // the scenes do have overlaps to find
}

// The query grid lists every box that overlaps a query box (those of the build, and those
// changed since, as moved), each once; or it refuses a box too big for it.
TEST(BroadPhase, QueryGridListsEveryOverlappingBoxOnce) {
    std::mt19937_64 rng(20261126);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    BoxQueryGrid grid; // reused across scenes, as the collisions reuse it
    std::vector<std::uint32_t> listed;
    std::size_t overlaps = 0;
    for (int scene = 0; scene < 40; ++scene) {
        const double w = scene % 2 ? 10.0 : 100.0;
        Scene s = randomScene(rng, 1 + scene * 11, w);
        if (scene % 3 == 0) // a floor too big for the grid's cells
            s.boxes.push_back({{-1.0, 2.0}, {200.0, 2.5}}), s.kinds.push_back(ProxyKind::Resting);
        grid.build(s.boxes, s.kinds);
        // Some boxes move (or change kind) after the build; the grid is told.
        const Scene built = s;
        for (std::uint32_t i = 0; i < s.boxes.size(); ++i)
            if (unit(rng) < 0.1) {
                const Vec2 shift{20.0 * unit(rng) - 10.0, 20.0 * unit(rng) - 10.0};
                s.boxes[i] = {s.boxes[i].lo + shift, s.boxes[i].hi + shift};
                s.kinds[i] = unit(rng) < 0.5 ? ProxyKind::Moving : built.kinds[i];
                grid.moved(i);
            }
        for (int q = 0; q < 30; ++q) {
            const Aabb& box = s.boxes[static_cast<std::size_t>(q) % s.boxes.size()];
            listed.clear();
            if (!grid.query(box, listed)) continue; // (the floor)
            std::vector<std::uint32_t> sorted = listed;
            std::sort(sorted.begin(), sorted.end());
            ASSERT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end())
                << "scene " << scene << ": a box listed twice";
            for (std::uint32_t i = 0; i < s.boxes.size(); ++i) {
                if (s.kinds[i] == ProxyKind::None || !box.overlaps(s.boxes[i])) continue;
                ++overlaps;
                EXPECT_TRUE(std::binary_search(sorted.begin(), sorted.end(), i))
                    << "scene " << scene << " query " << q << ": box " << i << " missed";
            }
        }
        // A box over the whole field of a hundred boxes or more covers too many cells to
        // look up.
        if (scene < 10) continue;
        listed.clear();
        EXPECT_FALSE(grid.query({{-w, -w}, {2.0 * w, 2.0 * w}}, listed)) << "scene " << scene;
        EXPECT_TRUE(listed.empty());
    }
    EXPECT_GT(overlaps, 2000u); // the queries do have boxes to find
}

// A box that reached far out (a particle an unstable integrator threw away) can span
// 2^32 cells a side, or, clamped, 2e15: counted in 64-bit integers its cells wrap round
// to 0. It is too big for either grid, not a loop over the cells it covers.
TEST(BroadPhase, BoxesFarOutAreTooBigForTheGridsNotAHang) {
    const double wrap = 4294967295.5; // unit cells 0 .. 2^32 - 1 a side: 2^64 in all
    for (const Aabb far :
         {Aabb{{0.0, 0.0}, {wrap, wrap}}, Aabb{{-1e300, -1e300}, {1e300, 1e300}}}) {
        const std::vector<Aabb> boxes{{{0.0, 0.0}, {1.0, 1.0}}, {{0.5, 0.5}, {1.5, 1.5}}, far};
        const std::vector<ProxyKind> kinds(boxes.size(), ProxyKind::Moving);
        std::vector<ProxyPair> pairs;
        UniformGrid().findPairs(boxes, kinds, pairs, 1.0);
        EXPECT_EQ(pairs, (std::vector<ProxyPair>{{0, 1}, {0, 2}, {1, 2}}));
        // The query grid's cells are about the mean box (here 1 m), so it is built without
        // the far box, which would make one cell of everything, and then asked about it.
        BoxQueryGrid grid;
        grid.build(std::span(boxes).first(2), std::span(kinds).first(2));
        std::vector<std::uint32_t> listed;
        EXPECT_FALSE(grid.query(far, listed));
        EXPECT_TRUE(listed.empty());
    }
}

// Two resting proxies never pair, and None is skipped; touching boxes do pair.
TEST(BroadPhase, PairingRules) {
    const std::vector<Aabb> boxes{
        {{0, 0}, {1, 1}}, {{1, 0}, {2, 1}}, {{0.5, 0.5}, {1.5, 1.5}}, {{0, 0}, {3, 3}}};
    const std::vector<ProxyKind> kinds{ProxyKind::Resting, ProxyKind::Resting, ProxyKind::Moving,
                                       ProxyKind::None};
    std::vector<ProxyPair> out;
    SortAndSweep().findPairs(boxes, kinds, out);
    EXPECT_EQ(out, (std::vector<ProxyPair>{{0, 2}, {1, 2}}));
    UniformGrid().findPairs(boxes, kinds, out, 0.5);
    EXPECT_EQ(out, (std::vector<ProxyPair>{{0, 2}, {1, 2}}));
}

// In a world: 200 particles raining into a box onto a circle and a platform and piling
// up behave identically in two runs (determinism, with collisions), and no contact is
// lost to the broad phase: nothing ends up through a wall or the floor, and overlaps
// in the pile stay below 5 % of a radius (the passes and the projection are iterative;
// a pile is their hardest case).
TEST(BroadPhase, WorldWithManyParticlesIsDeterministicAndLeavesNoOverlaps) {
    auto run = [](BroadPhase bp, bool patchPairs = true) {
        WorldDef d;
        d.collision.broadPhase = bp;
        d.collision.patchPairs = patchPairs;
        World w(d);
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> x(-4.5, 4.5), y(0.5, 8.0), v(-3.0, 3.0);
        w.shapes.addSegment({-5.0, 0.0}, {5.0, 0.0}, material::kFloor);
        w.shapes.addSegment({-5.0, 0.0}, {-5.0, 10.0}, material::kFloor);
        w.shapes.addSegment({5.0, 0.0}, {5.0, 10.0}, material::kFloor);
        w.shapes.addCircle({0.0, 2.0}, 0.7);
        w.shapes.addBox({2.0, 1.0}, {3.0, 1.5});
        for (int i = 0; i < 200; ++i) {
            ParticleDef pd;
            pd.position = {x(rng), y(rng)};
            pd.velocity = {v(rng), v(rng)};
            pd.radius = 0.05;
            pd.material = static_cast<MaterialId>(material::kGolf + i % 9);
            w.particles.add(pd);
        }
        for (int i = 0; i < 400; ++i)
            w.step();
        return w;
    };
    const World a = run(BroadPhase::Grid), b = run(BroadPhase::Grid);
    EXPECT_EQ(a.hash(), b.hash());
    // The broad phase only proposes pairs: every kind gives the same world, bit for bit.
    EXPECT_EQ(run(BroadPhase::SortAndSweep).hash(), a.hash());
    EXPECT_EQ(run(BroadPhase::AllPairs).hash(), a.hash());
    // Mending the kept pairs where a few particles left their fat boxes, or rebuilding
    // them each time, proposes the same pairs too.
    EXPECT_EQ(run(BroadPhase::Grid, false).hash(), a.hash());
    // Nothing is left inside the floor, the walls or each other (beyond the tolerance
    // and the projection of one step's fall).
    double worst = 0.0;
    const auto& p = a.particles;
    for (std::size_t i = 0; i < p.slots(); ++i) {
        worst = std::max(worst, 0.05 - p.py[i]);
        worst = std::max(worst, 0.05 - (p.px[i] + 5.0));
        worst = std::max(worst, 0.05 - (5.0 - p.px[i]));
        for (std::size_t j = i + 1; j < p.slots(); ++j)
            worst = std::max(worst, 0.1 - length(p.position(static_cast<ParticleId>(i)) -
                                                 p.position(static_cast<ParticleId>(j))));
    }
    EXPECT_LT(worst, 0.05 * 0.05);
}
