// The candidates' order: by time, ties by index, whichever sort gives it. The radix sort
// of a long list gives exactly what the comparison sort gives, ties, zeros of both signs,
// negative times and times that share most of their bits included.
#include "physics/collision/narrowphase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace phys;

namespace {

std::vector<TimeKey> byComparison(std::vector<TimeKey> keys) {
    std::sort(keys.begin(), keys.end(), [](const TimeKey& x, const TimeKey& y) {
        return x.time < y.time || (x.time == y.time && x.index < y.index);
    });
    return keys;
}

bool sameOrder(const std::vector<TimeKey>& a, const std::vector<TimeKey>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const TimeKey& x, const TimeKey& y) { return x.index == y.index; });
}

} // namespace

TEST(TimeOrder, TheRadixSortGivesTheComparisonSortsOrder) {
    std::mt19937_64 rng(20261126);
    const double h = 1.0 / 120.0;
    std::uniform_real_distribution<double> within(0.0, h), unit(0.0, 1.0);
    std::vector<TimeKey> keys, scratch;
    for (const std::size_t n : {kRadixSortFrom - 1, kRadixSortFrom, std::size_t{5000}}) {
        for (int kind = 0; kind < 4; ++kind) {
            keys.clear();
            for (std::uint32_t i = 0; i < n; ++i) {
                double t = within(rng);
                const double u = unit(rng);
                if (kind >= 1 && u < 0.3) t = 0.0; // resting pairs touch at 0
                if (kind >= 1 && u >= 0.3 && u < 0.35) t = -0.0;
                if (kind >= 2 && u >= 0.35 && u < 0.6) t = h;         // and at the step's end
                if (kind == 3 && u >= 0.6 && u < 0.7) t = -1e-12 * u; // rounding below 0
                if (kind == 3 && u >= 0.7) t = 0.5 * h + 1e-15 * std::floor(10 * u);
                keys.push_back({t, i});
            }
            const auto expected = byComparison(keys);
            orderByTime(keys, scratch);
            EXPECT_TRUE(sameOrder(keys, expected)) << n << " keys, kind " << kind;
        }
    }
}
