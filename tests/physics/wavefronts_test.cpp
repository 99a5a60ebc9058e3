// Wavefronts of a sweep (wavefronts.h) against the rule they keep: rows that share a slot
// keep their order, and no two rows of a run of `width` share one, so a run can go through
// vector lanes at once; a barrier puts everything after it after everything before it.
#include "physics/collision/wavefronts.h"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <random>
#include <vector>

using namespace phys;

namespace {

struct Row {
    std::uint32_t kind;
    std::array<std::uint32_t, 3> slots;
};

bool share(const Row& x, const Row& y, std::uint32_t slots) {
    for (const std::uint32_t s : x.slots)
        for (const std::uint32_t t : y.slots)
            if (s == t && s < slots) return true;
    return false;
}

// Random rows over `slots` slots, some touching the two slots past them (still, sink).
std::vector<Row> randomRows(std::mt19937_64& rng, std::size_t n, std::uint32_t slots) {
    std::uniform_int_distribution<std::uint32_t> slot(0, slots + 1), kind(0, 1);
    std::vector<Row> rows(n);
    for (Row& r : rows)
        r = {kind(rng), {slot(rng), slot(rng), slot(rng)}};
    return rows;
}

} // namespace

TEST(Wavefronts, RowsThatShareASlotKeepTheirOrderAndARunSharesNone) {
    std::mt19937_64 rng(5);
    Wavefronts w;
    for (int trial = 0; trial < 200; ++trial) {
        const std::uint32_t slots = 4 + trial % 60;
        const auto rows = randomRows(rng, 1 + trial % 150, slots);
        w.begin(slots);
        for (std::uint32_t k = 0; k < rows.size(); ++k)
            w.add(k, rows[k].kind, rows[k].slots[0], rows[k].slots[1], rows[k].slots[2]);
        const auto& order = w.order(4);
        ASSERT_EQ(order.size() % 4, 0u);
        std::map<std::uint32_t, std::size_t> at;
        for (std::size_t i = 0; i < order.size(); ++i)
            if (order[i] != Wavefronts::kPadding) at[order[i]] = i;
        ASSERT_EQ(at.size(), rows.size()); // each row once
        for (std::uint32_t j = 0; j < rows.size(); ++j)
            for (std::uint32_t k = j + 1; k < rows.size(); ++k)
                if (share(rows[j], rows[k], slots)) {
                    EXPECT_LT(at[j], at[k]) << trial;
                }
        for (std::size_t run = 0; run < order.size(); run += 4)
            for (std::size_t i = run; i < run + 4; ++i)
                for (std::size_t j = i + 1; j < run + 4; ++j) {
                    if (order[i] == Wavefronts::kPadding || order[j] == Wavefronts::kPadding)
                        continue;
                    EXPECT_FALSE(share(rows[order[i]], rows[order[j]], slots)) << trial;
                    EXPECT_EQ(rows[order[i]].kind, rows[order[j]].kind) << trial;
                }
    }
}

// Rows on slots of their own all fall in the first wavefront; a chain through one slot
// takes one wavefront a row.
TEST(Wavefronts, IndependentRowsShareAWavefrontAndAChainTakesOneARow) {
    Wavefronts w;
    w.begin(100);
    for (std::uint32_t k = 0; k < 8; ++k)
        w.add(k, 0, 2 * k, 2 * k + 1, 100); // 100: past the slots, orders nothing
    EXPECT_EQ(w.order(4), (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(w.count(), 1u);
    w.begin(100);
    for (std::uint32_t k = 0; k < 3; ++k)
        w.add(k, 0, 7, 7, 7);
    const auto p = Wavefronts::kPadding;
    EXPECT_EQ(w.order(4), (std::vector<std::uint32_t>{0, p, p, p, 1, p, p, p, 2, p, p, p}));
    EXPECT_EQ(w.count(), 3u);
}

// A barrier: rows after it come after every row before it, even on other slots, and
// barrierStarts() says where each part begins.
TEST(Wavefronts, ABarrierStartsAPartAfterEverythingBeforeIt) {
    Wavefronts w;
    w.begin(10);
    w.barrier();
    w.add(0, 0, 0, 1, 10);
    w.add(1, 0, 2, 3, 10);
    w.barrier();
    w.add(2, 0, 4, 5, 10); // shares nothing with rows 0 and 1, yet comes after them
    w.barrier();
    const auto p = Wavefronts::kPadding;
    EXPECT_EQ(w.order(4), (std::vector<std::uint32_t>{0, 1, p, p, 2, p, p, p}));
    EXPECT_EQ(w.barrierStarts(), (std::vector<std::uint32_t>{0, 4, 8}));
}

// The wavefronts are counted on across sweeps (nothing is cleared between them): a sweep
// after a thousand others orders its rows as the first one did.
TEST(Wavefronts, ASweepAfterManyOrdersAsTheFirst) {
    std::mt19937_64 rng(9);
    const auto rows = randomRows(rng, 120, 40);
    auto orderOnce = [&](Wavefronts& w) {
        w.begin(40);
        for (std::uint32_t k = 0; k < rows.size(); ++k)
            w.add(k, rows[k].kind, rows[k].slots[0], rows[k].slots[1], rows[k].slots[2]);
        return w.order(4);
    };
    Wavefronts fresh, used;
    const auto first = orderOnce(fresh);
    for (int k = 0; k < 1000; ++k)
        orderOnce(used);
    EXPECT_EQ(orderOnce(used), first);
}

// Adding a whole sequence with its parts at once orders as adding it row by row with a
// barrier before each part.
TEST(Wavefronts, ASequenceAddedAtOnceOrdersAsRowByRow) {
    std::mt19937_64 rng(13);
    Wavefronts byRow, atOnce;
    for (int trial = 0; trial < 100; ++trial) {
        const auto rows = randomRows(rng, 80, 30);
        std::vector<std::uint32_t> sequence(rows.size()), parts;
        for (std::uint32_t k = 0; k < rows.size(); ++k)
            sequence[k] = k;
        for (std::uint32_t p = 0; p <= rows.size(); p += 1 + trial % 17)
            parts.push_back(p);
        parts.push_back(static_cast<std::uint32_t>(rows.size()));
        byRow.begin(30);
        std::size_t next = 0;
        for (std::uint32_t k = 0; k < rows.size(); ++k) {
            for (; next < parts.size() && parts[next] == k; ++next)
                byRow.barrier();
            byRow.add(k, rows[k].kind, rows[k].slots[0], rows[k].slots[1], rows[k].slots[2]);
        }
        for (; next < parts.size(); ++next)
            byRow.barrier();
        atOnce.begin(30);
        atOnce.add(sequence, parts, [&](std::uint32_t k) {
            return std::array<std::uint32_t, 4>{rows[k].kind, rows[k].slots[0], rows[k].slots[1],
                                                rows[k].slots[2]};
        });
        ASSERT_EQ(atOnce.order(4), byRow.order(4)) << trial;
        ASSERT_EQ(atOnce.barrierStarts(), byRow.barrierStarts()) << trial;
    }
}
