// The kept pairs' filter keeps exactly the pairs whose boxes overlap, in their order, with
// AVX2 lanes or without: edges that touch, signed zeros, NaNs and static shapes included.
#include "physics/collision/pair_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace phys;

namespace {

// Boxes on a coarse lattice, so that many share an edge or a corner exactly; a few are
// points, a few have a NaN corner, and zeros come with either sign.
std::vector<Aabb> latticeBoxes(std::mt19937_64& rng, int n) {
    std::uniform_int_distribution<int> cell(-4, 4), extent(0, 3), odd(0, 19);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<Aabb> boxes;
    for (int i = 0; i < n; ++i) {
        Vec2 lo{0.5 * cell(rng), 0.5 * cell(rng)};
        if (lo.x == 0.0 && odd(rng) < 10) lo.x = -0.0;
        Vec2 hi = lo + Vec2{0.5 * extent(rng), 0.5 * extent(rng)};
        if (hi.y == 0.0 && odd(rng) < 10) hi.y = -0.0;
        if (odd(rng) == 0) hi.x = nan;
        if (odd(rng) == 0) lo.y = nan;
        boxes.push_back({lo, hi});
    }
    return boxes;
}

} // namespace

TEST(PairFilter, KeepsExactlyTheOverlappingPairsInOrder) {
    std::mt19937_64 rng(20261127);
    std::size_t keptInAll = 0, testedInAll = 0;
    for (int scene = 0; scene < 40; ++scene) {
        const std::vector<Aabb> particles = latticeBoxes(rng, 5 + scene);
        const std::vector<Aabb> statics = latticeBoxes(rng, 1 + scene % 4);
        const auto n = static_cast<std::uint32_t>(particles.size());
        std::vector<ProxyPair> pairs, expected;
        for (std::uint32_t a = 0; a < n; ++a) {
            for (std::uint32_t b = a + 1; b < n + statics.size(); ++b) {
                pairs.push_back({a, b});
                const Aabb& other = b < n ? particles[b] : statics[b - n];
                if (particles[a].overlaps(other)) expected.push_back({a, b});
            }
        }
        std::vector<ProxyPair> fast(pairs.size()), scalar(pairs.size());
        fast.resize(keepOverlapping(pairs, particles, statics, fast.data()));
        scalar.resize(keepOverlappingScalar(pairs, particles, statics, scalar.data()));
        EXPECT_EQ(fast, expected) << "scene " << scene;
        EXPECT_EQ(scalar, expected) << "scene " << scene;
        keptInAll += expected.size();
        testedInAll += pairs.size();
    }
    // Both outcomes are common, so neither way of failing could hide.
    EXPECT_GT(keptInAll, testedInAll / 10);
    EXPECT_LT(keptInAll, testedInAll * 4 / 5);
}

TEST(PairFilter, EdgesThatTouchOverlapAndNaNsNever) {
    const std::vector<Aabb> particles = {{{0.0, 0.0}, {1.0, 1.0}},
                                         {{1.0, 1.0}, {2.0, 2.0}},    // a corner in common
                                         {{-1.0, -0.0}, {-0.0, 0.0}}, // -0 against +0
                                         {{0.0, std::nan("")}, {1.0, 1.0}}};
    const std::vector<Aabb> statics = {{{1.0 + 1e-12, 0.0}, {3.0, 3.0}}};
    const std::vector<ProxyPair> pairs = {{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 4}, {2, 3}};
    std::vector<ProxyPair> kept(pairs.size());
    kept.resize(keepOverlapping(pairs, particles, statics, kept.data()));
    const std::vector<ProxyPair> expected = {{0, 1}, {0, 2}, {1, 4}};
    EXPECT_EQ(kept, expected);
}
