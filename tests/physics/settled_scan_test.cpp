// skipSettled (simd/settled_scan.h) passes exactly the slots AwakeSet::select's one-slot test
// passes: on slots that fail it each way it can (flags not as recorded, awake, a -0 or a
// tiny velocity, a place or radius one bit off, -0 against +0), it stops at the first
// such slot, clears the marks of the slots it passed and counts the alive among them.
#include "physics/collision/simd/settled_scan.h"
#include "physics/particles.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

using namespace phys;

namespace {

struct Slots {
    std::vector<std::uint32_t> flags, settledFlags;
    std::vector<double> vx, vy, px, py, radius, settledX, settledY, settledRadius;
    SettledRecords records() const {
        return {flags.data(),    vx.data(),           vy.data(),           px.data(),
                py.data(),       radius.data(),       settledFlags.data(), settledX.data(),
                settledY.data(), settledRadius.data()};
    }
};

// The one-slot test, written out as AwakeSet::select has it.
bool settled(const Slots& s, std::size_t i) {
    auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
    const std::uint32_t f = s.flags[i];
    const bool rests = !(f & kAlive) || ((f & kSleeping) && (bits(s.vx[i]) | bits(s.vy[i])) == 0);
    return rests && f == s.settledFlags[i] && bits(s.px[i]) == bits(s.settledX[i]) &&
           bits(s.py[i]) == bits(s.settledY[i]) && bits(s.radius[i]) == bits(s.settledRadius[i]);
}

// n slots, each settled (a sleeper or an empty slot as recorded) unless it draws one of
// the ways to fail, with probability `odd`.
Slots draw(std::size_t n, double odd, std::mt19937_64& rng) {
    Slots s;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::uniform_int_distribution<int> way(0, 8);
    for (std::size_t i = 0; i < n; ++i) {
        const bool empty = u(rng) < 0.2;
        const std::uint32_t f = empty ? 0u : kAlive | kSleeping | (u(rng) < 0.3 ? kProjectile : 0u);
        const double x = empty ? 0.0 : u(rng), y = empty ? 0.0 : u(rng), r = empty ? 0.0 : 0.05;
        s.flags.push_back(f), s.settledFlags.push_back(f);
        s.vx.push_back(0.0), s.vy.push_back(0.0);
        s.px.push_back(x), s.py.push_back(y), s.radius.push_back(r);
        s.settledX.push_back(x), s.settledY.push_back(y), s.settledRadius.push_back(r);
        if (u(rng) >= odd) continue;
        switch (way(rng)) {
        case 0:
            s.settledFlags[i] ^= kProjectile;
            break; // flags not as recorded
        case 1:
            s.flags[i] = s.settledFlags[i] = kAlive;
            break; // awake
        case 2:
            s.vx[i] = -0.0;
            break; // -0 does not rest
        case 3:
            s.vy[i] = 1e-300;
            break; // a tiny velocity
        case 4:
            s.px[i] = std::nextafter(s.px[i], 2.0);
            break; // a bit off
        case 5:
            s.settledY[i] = std::nextafter(s.settledY[i], -1.0);
            break;
        case 6:
            s.radius[i] = 0.051;
            break;
        case 7:
            s.settledX[i] = s.px[i] == 0.0 ? -0.0 : s.px[i];
            break; // -0 against +0
        case 8:
            s.flags[i] = s.settledFlags[i] = 0u, s.vx[i] = 1.0;
            break; // empty, moving: rests
        }
    }
    return s;
}

} // namespace

TEST(SettledScan, PassesExactlyTheSlotsTheOneSlotTestPasses) {
    std::mt19937_64 rng(41);
    int stopped = 0, passedGroups = 0;
    for (int scene = 0; scene < 400; ++scene) {
        const std::size_t n = 1 + scene % 37;
        const Slots s = draw(n, scene % 4 == 0 ? 0.0 : 0.08, rng);
        for (std::size_t from = 0; from < n; from += 1 + scene % 3) {
            std::vector<std::uint8_t> mark(n, 1);
            std::size_t asleep = 0;
            const std::size_t at =
                skipSettled(s.records(), from, n, kAlive, kSleeping, mark.data(), asleep);
            // Where the lanes run: every settled slot up to the first that is not, in
            // groups of four (so not into the tail shorter than four); without them, none.
            std::size_t expected = from, expectedAsleep = 0;
            std::size_t groupEnd = from;
            while (skipSettledInLanes() && expected < n) {
                if (expected == groupEnd) {
                    if (groupEnd + 4 > n) break;
                    groupEnd += 4;
                }
                if (!settled(s, expected)) break;
                expectedAsleep += (s.flags[expected] & kAlive) ? 1 : 0;
                ++expected;
            }
            ASSERT_EQ(at, expected) << "scene " << scene << " from " << from;
            EXPECT_EQ(asleep, expectedAsleep) << "scene " << scene << " from " << from;
            for (std::size_t k = 0; k < n; ++k)
                EXPECT_EQ(mark[k], k >= from && k < at ? 0 : 1) << "slot " << k;
            stopped += at < n && !settled(s, at) ? 1 : 0; // at a slot that fails
            passedGroups += static_cast<int>((at - from) / 4);
        }
    }
    if (skipSettledInLanes()) { // both outcomes are common
        EXPECT_GT(stopped, 200);
        EXPECT_GT(passedGroups, 500);
    }
}
