// The kept pairs' filter keeps exactly the pairs whose boxes overlap, and the solver's
// exactly the pairs near enough to be contacts with its normal and depth to the bit, in
// their order, with AVX2 lanes or without: edges that touch, signed zeros, NaNs and
// static shapes included.
#include "physics/collision/simd/pair_filter.h"

#include <gtest/gtest.h>

#include <bit>
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

namespace {

// Discs on a coarse lattice, so that many pairs touch exactly, coincide or sit at the
// solver's limit; a few have a NaN coordinate, and zeros come with either sign.
struct DiscScene {
    std::vector<double> x, y, radius;
};

DiscScene latticeDiscs(std::mt19937_64& rng, int n) {
    std::uniform_int_distribution<int> cell(-6, 6), size(1, 4), odd(0, 29);
    DiscScene s;
    for (int i = 0; i < n; ++i) {
        double x = 0.25 * cell(rng), y = 0.25 * cell(rng);
        if (x == 0.0 && odd(rng) < 15) x = -0.0;
        if (odd(rng) == 0) y = std::numeric_limits<double>::quiet_NaN();
        s.x.push_back(x), s.y.push_back(y), s.radius.push_back(0.125 * size(rng));
    }
    return s;
}

} // namespace

TEST(PairFilter, KeepsExactlyTheNearPairsWithTheSolversGeometry) {
    std::mt19937_64 rng(20261127);
    std::size_t nearInAll = 0, particlePairsInAll = 0;
    for (int scene = 0; scene < 40; ++scene) {
        // The solver's limit, and none (where discs that just touch are exactly at it).
        const double tolerance = scene % 2 ? 1e-9 : 0.0, speculative = scene % 2 ? 0.1 : 0.0;
        const DiscScene s = latticeDiscs(rng, 6 + scene);
        const auto n = static_cast<std::uint32_t>(s.x.size());
        const std::uint32_t shapes = 1 + scene % 3;
        std::vector<ProxyPair> pairs;
        std::vector<NearPair> expected;
        for (std::uint32_t a = 0; a < n; ++a) {
            for (std::uint32_t b = a + 1; b < n + shapes; ++b) {
                pairs.push_back({a, b});
                if (b >= n) {
                    expected.push_back({{a, b}, {}, 0.0});
                    continue;
                }
                // The solver's arithmetic, written out.
                const Vec2 d = Vec2{s.x[a], s.y[a]} - Vec2{s.x[b], s.y[b]};
                const double L = std::sqrt(d.x * d.x + d.y * d.y);
                const Vec2 normal = L > 0.0 ? Vec2{d.x / L, d.y / L} : Vec2{0.0, 1.0};
                const double reach = s.radius[a] + s.radius[b], depth = reach - L;
                ++particlePairsInAll;
                if (depth > -tolerance - speculative * reach) {
                    expected.push_back({{a, b}, normal, depth});
                    ++nearInAll;
                }
            }
        }
        const Discs discs{s.x, s.y, s.radius};
        std::vector<NearPair> fast(pairs.size()), scalar(pairs.size());
        fast.resize(keepNear(pairs, discs, tolerance, speculative, fast.data()));
        scalar.resize(keepNearScalar(pairs, discs, tolerance, speculative, scalar.data()));
        for (const std::vector<NearPair>* got : {&fast, &scalar}) {
            ASSERT_EQ(got->size(), expected.size()) << "scene " << scene;
            for (std::size_t k = 0; k < expected.size(); ++k) {
                const NearPair &g = (*got)[k], &e = expected[k];
                ASSERT_EQ(g.pair, e.pair) << "scene " << scene;
                if (e.pair.second >= n) continue; // a shape's geometry is the caller's
                // Bit for bit: the same signed zeros, the same last bits.
                EXPECT_EQ(std::bit_cast<std::uint64_t>(g.normal.x),
                          std::bit_cast<std::uint64_t>(e.normal.x));
                EXPECT_EQ(std::bit_cast<std::uint64_t>(g.normal.y),
                          std::bit_cast<std::uint64_t>(e.normal.y));
                EXPECT_EQ(std::bit_cast<std::uint64_t>(g.depth),
                          std::bit_cast<std::uint64_t>(e.depth));
            }
        }
    }
    // Both outcomes are common, so neither way of failing could hide.
    EXPECT_GT(nearInAll, particlePairsInAll / 10);
    EXPECT_LT(nearInAll, particlePairsInAll * 4 / 5);
}

TEST(PairFilter, NearMeansTheSolversLimitAndCoincidentCentresPointUp) {
    // Radii 0.5 and 0.5: the limit is a gap of 1e-9 + 0.1 m. Centres 1.1 apart are a
    // gap of 0.1 (kept), 1.2 apart one of 0.2 (dropped); two that coincide are kept with
    // the normal {0, 1} and the depth of both radii.
    const std::vector<double> x = {0.0, 1.1, 0.0, 0.0, 2.2}, y = {0.0, 0.0, 0.0, 1.2, 0.0};
    const std::vector<double> radius(5, 0.5);
    const std::vector<ProxyPair> pairs = {{0, 1}, {0, 2}, {0, 3}, {1, 4}, {0, 5}};
    std::vector<NearPair> kept(pairs.size());
    kept.resize(keepNear(pairs, {x, y, radius}, 1e-9, 0.1, kept.data()));
    ASSERT_EQ(kept.size(), 4u);
    EXPECT_EQ(kept[0].pair, (ProxyPair{0, 1}));
    EXPECT_EQ(kept[0].normal, (Vec2{-1.0, 0.0}));
    EXPECT_EQ(kept[1].pair, (ProxyPair{0, 2}));
    EXPECT_EQ(kept[1].normal, (Vec2{0.0, 1.0}));
    EXPECT_EQ(kept[1].depth, 1.0);
    EXPECT_EQ(kept[2].pair, (ProxyPair{1, 4}));
    EXPECT_EQ(kept[3].pair, (ProxyPair{0, 5})); // a shape: the caller's to test
}
