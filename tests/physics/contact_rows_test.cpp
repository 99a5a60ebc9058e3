// The contact solver's lane sweeps (simd/contact_rows.h) against its one-row steps: the same
// rows, swept four at a time and one at a time, end in the same bits, signed zeros and
// rows that do nothing included. Each run of four rows shares no particle, as in a
// wavefront, so the order within a run does not matter and the two must agree exactly.
#include "physics/collision/simd/contact_rows.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdio>
#include <random>
#include <vector>

using namespace phys;

namespace {

constexpr std::uint32_t kParticles = 64, kStill = kParticles, kSink = kParticles + 1;

// A value from a few that make the steps branch (zeros of both signs, ones) or random.
double pick(std::mt19937_64& rng, double scale) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
    case 0:
        return 0.0;
    case 1:
        return -0.0;
    case 2:
        return scale;
    default:
        return scale * u(rng);
    }
}

// The particles of a run of four: eight distinct ones, each row's a and b.
std::vector<std::uint32_t> runParticles(std::mt19937_64& rng) {
    std::vector<std::uint32_t> all(kParticles);
    for (std::uint32_t i = 0; i < kParticles; ++i)
        all[i] = i;
    std::shuffle(all.begin(), all.end(), rng);
    all.resize(8);
    return all;
}

// Sizes `rows` to eight runs of four and calls row(k, a, b) for each row k, where no two
// rows of a run share a particle.
template <class Columns, class Row> void fillRuns(std::mt19937_64& rng, Columns& rows, Row&& row) {
    constexpr std::size_t kRuns = 8;
    rows.resize(4 * kRuns);
    for (std::size_t run = 0; run < kRuns; ++run) {
        const auto p = runParticles(rng);
        for (std::size_t l = 0; l < 4; ++l)
            row(4 * run + l, p[2 * l], p[2 * l + 1]);
    }
}

bool sameBits(double x, double y) {
    return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y);
}

bool sameBits(const std::vector<Vec2>& x, const std::vector<Vec2>& y) {
    for (std::size_t i = 0; i < kParticles + 1; ++i) // the sink's value is never read
        if (!sameBits(x[i].x, y[i].x) || !sameBits(x[i].y, y[i].y)) return false;
    return true;
}

std::vector<Vec2> randomState(std::mt19937_64& rng) {
    std::vector<Vec2> v(kParticles + 2);
    for (std::uint32_t i = 0; i < kParticles; ++i)
        v[i] = {pick(rng, 2.0), pick(rng, 2.0)};
    return v; // still and sink at rest
}

} // namespace

TEST(ContactRows, FourImpulseRowsAtOnceGiveTheBitsOfOneAtATime) {
    if (!contactLanesAvailable()) std::printf("no AVX2 here: both sweeps run one row at a time\n");
    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 300; ++trial) {
        ContactRows rows;
        fillRuns(rng, rows, [&](std::size_t k, std::uint32_t a, std::uint32_t b) {
            const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
            rows.a[k] = a;
            rows.readB[k] = kind == 0 ? kStill : b; // a shape, or a particle
            const double angle = pick(rng, 3.0);
            rows.nx[k] = std::cos(angle), rows.ny[k] = std::sin(angle);
            rows.closing[k] = pick(rng, 0.5), rows.friction[k] = std::abs(pick(rng, 0.6));
            for (ContactRows::Masses* m : {&rows.all, &rows.band}) {
                const bool bMoves = kind >= 2;
                m->wa[k] = kind == 3 ? 0.0 : 10.0, m->wb[k] = bMoves ? 10.0 : 0.0;
                const double sum = m->wa[k] + m->wb[k];
                m->mass[k] = kind == 1 && k % 4 == 3 ? 0.0 : 1.0 / sum; // no step at all
                m->pushB[k] = bMoves ? rows.readB[k] : kSink;
            }
            rows.normalImpulse[k] = std::abs(pick(rng, 0.2));
            rows.tangentImpulse[k] = pick(rng, 0.1);
        });
        ContactRows one = rows;
        std::vector<Vec2> v = randomState(rng), w = v;
        std::vector<std::uint8_t> touchedLanes(kParticles + 2), touchedOne(kParticles + 2);
        for (int sweep = 0; sweep < 3; ++sweep) {
            sweepImpulseRows(rows, rows.all, 0, rows.size(), v.data(), touchedLanes.data(),
                                contactLanesAvailable());
            sweepImpulseRows(one, one.all, 0, one.size(), w.data(), touchedOne.data(), false);
        }
        if (contactLanesAvailable()) markTouched(rows, touchedLanes.data(), rows.all.pushB);
        ASSERT_TRUE(sameBits(v, w)) << trial;
        for (std::size_t k = 0; k < rows.size(); ++k) {
            ASSERT_TRUE(sameBits(rows.normalImpulse[k], one.normalImpulse[k])) << trial << " " << k;
            ASSERT_TRUE(sameBits(rows.tangentImpulse[k], one.tangentImpulse[k]))
                << trial << " " << k;
        }
        for (std::uint32_t i = 0; i < kParticles; ++i)
            ASSERT_EQ(touchedLanes[i], touchedOne[i]) << trial << " " << i;
    }
}

TEST(ContactRows, FourProjectionRowsAtOnceGiveTheBitsOfOneAtATime) {
    std::mt19937_64 rng(12);
    int deepSweeps[2] = {0, 0}; // sweeps that did not push deep, and that did
    for (int trial = 0; trial < 300; ++trial) {
        ContactRows rows;
        fillRuns(rng, rows, [&](std::size_t k, std::uint32_t a, std::uint32_t b) {
            const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
            const bool bMoves = kind > 0, still = kind == 3 && k % 4 == 1; // no mass: no step
            rows.a[k] = a, rows.readB[k] = b;
            rows.reach[k] = std::abs(pick(rng, 1.5)), rows.cap[k] = std::abs(pick(rng, 0.3));
            ContactRows::Masses& m = rows.all;
            m.pushB[k] = bMoves ? b : kSink;
            m.mass[k] = still ? 0.0 : bMoves ? 0.05 : 0.1;
            m.fa[k] = still ? 0.0 : bMoves ? 0.5 : 1.0, m.fb[k] = still || !bMoves ? 0.0 : 0.5;
        });
        ContactRows one = rows;
        std::vector<Vec2> p = randomState(rng), q = p;
        // Some pairs on top of each other: the normal is then straight up.
        for (std::size_t k = 0; k < rows.size(); k += 5)
            p[rows.readB[k]] = p[rows.a[k]], q[rows.readB[k]] = q[rows.a[k]];
        std::vector<std::uint8_t> touchedLanes(kParticles + 2), touchedOne(kParticles + 2);
        auto noShapes = [](std::size_t) {
            ADD_FAILURE() << "no shape rows here";
            return 0.0;
        };
        // 0: every push is deep; 1: only a push of more than the cap, which none is.
        const double deepShare = std::array{0.0, 0.5, 0.99, 1.0}[trial % 4];
        for (int sweep = 0; sweep < 3; ++sweep) {
            const bool deepLanes =
                sweepProjectRows(rows, rows.all, 0, rows.size(), p.data(), touchedLanes.data(),
                                    contactLanesAvailable(), deepShare, noShapes);
            const bool deepOne = sweepProjectRows(one, one.all, 0, one.size(), q.data(),
                                                     touchedOne.data(), false, deepShare, noShapes);
            ASSERT_EQ(deepLanes, deepOne) << trial << ", sweep " << sweep;
            ++deepSweeps[deepOne];
        }
        if (contactLanesAvailable()) markTouched(rows, touchedLanes.data(), rows.all.pushB);
        ASSERT_TRUE(sameBits(p, q)) << trial;
        for (std::uint32_t i = 0; i < kParticles; ++i)
            ASSERT_EQ(touchedLanes[i], touchedOne[i]) << trial << " " << i;
    }
    EXPECT_GT(deepSweeps[0], 100);
    EXPECT_GT(deepSweeps[1], 100);
}

// A sweep says whether it pushed deep: a pair 0.375 inside each other, with a cap of
// 0.25, moves 0.25 apart in the first sweep (deeper than half the cap) and the last 0.125
// in the second (not deeper), and the third pushes nothing. (Binary fractions: exact.)
TEST(ContactRows, ASweepSaysWhetherItPushedDeeperThanItsShareOfTheCap) {
    for (const bool lanes : {false, true}) {
        if (lanes && !contactLanesAvailable()) continue;
        // The pair's row, then (for the lanes) three padding rows: at the sink against
        // still, with no mass.
        ContactRows rows;
        rows.resize(4);
        for (std::size_t k = 0; k < 4; ++k)
            rows.a[k] = kSink, rows.readB[k] = kStill, rows.all.pushB[k] = kSink;
        rows.a[0] = 0, rows.readB[0] = 1, rows.reach[0] = 1.0, rows.cap[0] = 0.25;
        ContactRows::Masses& m = rows.all;
        m.wa[0] = m.wb[0] = 1.0, m.mass[0] = 0.5, m.fa[0] = m.fb[0] = 0.5, m.pushB[0] = 1;
        std::vector<Vec2> p(kParticles + 2);
        p[0] = {0.0, 0.625}, p[1] = {0.0, 0.0};
        std::vector<std::uint8_t> touched(kParticles + 2);
        auto noShapes = [](std::size_t) { return 0.0; };
        auto sweep = [&](double deepShare) {
            return sweepProjectRows(rows, rows.all, 0, lanes ? 4 : 1, p.data(), touched.data(),
                                       lanes, deepShare, noShapes);
        };
        EXPECT_TRUE(sweep(0.5)) << lanes;
        EXPECT_EQ(p[0].y - p[1].y, 0.875);
        EXPECT_FALSE(sweep(0.5)) << lanes;
        EXPECT_EQ(p[0].y - p[1].y, 1.0);
        EXPECT_FALSE(sweep(0.0)) << lanes; // nothing left to push
    }
}
