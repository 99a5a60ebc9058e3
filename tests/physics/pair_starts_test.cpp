// Where the first pass's times of impact need no search: the four-lane classification and
// the one-pair one agree to the bit, and both agree with timeOfImpact itself.
#include "physics/collision/simd/pair_starts.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>

using namespace phys;

namespace {

std::uint64_t bits(double x) {
    return std::bit_cast<std::uint64_t>(x);
}

struct Scene {
    std::vector<PathMotion> paths;
    std::vector<double> radius;
};

// Paths of a resting pile and its neighbours: centres on a lattice of the radius (so pairs
// touch exactly, overlap or stand apart), velocities and accelerations from small sets
// (at rest, rounding-sized, slow, gravity-like; often the same for both, so the pair's
// relative acceleration is exactly zero), and starts at 0, later, or past the step.
Scene latticeScene(std::mt19937_64& rng, int n, double h) {
    std::uniform_int_distribution<int> cell(-4, 4), pick(0, 8), late(0, 9);
    const double speeds[] = {0.0, 1e-17, -1e-17, 1e-5, -3e-4, 0.02, -0.3, 2.0, 1.2e-12};
    const double pulls[] = {0.0, -9.81, -19.62, 1e-10, 4.0, -0.5, 30.0, -60.0, -1.5e-9};
    Scene s;
    for (int i = 0; i < n; ++i) {
        PathMotion m;
        m.p = {0.05 * cell(rng), 0.05 * cell(rng)};
        m.v = {speeds[pick(rng)], speeds[pick(rng)]};
        m.a = {pick(rng) < 4 ? 0.0 : pulls[pick(rng)], pick(rng) < 3 ? -19.62 : pulls[pick(rng)]};
        const int when = late(rng);
        m.t0 = when < 6 ? 0.0 : when < 9 ? 0.25 * h * (when - 5) : 1.5 * h;
        s.paths.push_back(m);
        s.radius.push_back(i % 3 == 0 ? 0.1 : 0.05);
    }
    return s;
}

// Continuous values, where any change to the order of the arithmetic shows in the last
// bits: each particle placed against an earlier one, touching, a hair in or out, or
// inside by a millimetre, with speeds and pulls of every scale and starts anywhere in
// the step.
Scene touchingScene(std::mt19937_64& rng, int n, double h) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0), size(0.03, 0.1), when(0.0, 1.1);
    std::uniform_int_distribution<int> pick(0, 4);
    const double gaps[] = {0.0, 1e-12, -1e-12, -7e-5, 1e-3};
    const double scales[] = {0.0, 1e-17, 1e-9, 1e-2, 3.0};
    Scene s;
    for (int i = 0; i < n; ++i) {
        PathMotion m;
        const double r = size(rng);
        if (i == 0) {
            m.p = {unit(rng), unit(rng)};
        } else {
            const auto j =
                pick(rng) < 2
                    ? static_cast<std::size_t>(i - 1)
                    : static_cast<std::size_t>(std::uniform_int_distribution<int>(0, i - 1)(rng));
            const double angle = 3.14159 * unit(rng);
            const Vec2 dir{std::cos(angle), std::sin(angle)};
            m.p = s.paths[j].p + dir * (r + s.radius[j] + gaps[pick(rng)]);
        }
        m.v = Vec2{unit(rng), unit(rng)} * scales[pick(rng)];
        m.a = Vec2{unit(rng), unit(rng)} * (10.0 * scales[pick(rng)]);
        if (i > 0 && pick(rng) < 2) {
            // Leaving the one below slowly while pulled back onto it: it falls back
            // within the step, a contact at its return.
            const PathMotion& below = s.paths.back();
            const Vec2 up = m.p - below.p;
            const Vec2 n = up * (1.0 / length(up));
            m.v = below.v + n * (1e-3 * std::abs(unit(rng)) + 2e-12);
            m.a = below.a - n * (1.0 + 20.0 * std::abs(unit(rng)));
        }
        m.t0 = pick(rng) < 3 ? 0.0 : when(rng) * h;
        s.paths.push_back(m);
        s.radius.push_back(r);
    }
    return s;
}

} // namespace

TEST(PairStarts, LanesAndOnePairAgreeWithTimeOfImpact) {
    std::mt19937_64 rng(20261127);
    const double h = 1.0 / 120.0;
    std::size_t counts[3] = {}, returning = 0;
    for (int scene = 0; scene < 150; ++scene) {
        // A third on the lattice, a third on it with no tolerance (where touching is a gap
        // of exactly the tolerance), a third continuous; some with a tolerance above a
        // thousandth of a radius (the slop is then the tolerance).
        const double tolerance = scene % 3 == 1 ? 0.0 : scene % 2 == 0 ? 1e-4 : 1e-9;
        const ToiSettings toi{true, 5, tolerance, 64};
        const Scene sc = scene % 3 == 2 ? touchingScene(rng, 8 + scene / 3, h)
                                        : latticeScene(rng, 8 + scene / 3, h);
        const std::vector<PathMotion>& paths = sc.paths;
        const std::vector<double>& radius = sc.radius;
        const auto n = static_cast<std::uint32_t>(paths.size());
        std::vector<ProxyPair> pairs;
        for (std::uint32_t a = 0; a < n; ++a)
            for (std::uint32_t b = a + 1; b < n + 2; ++b) // and two shapes
                pairs.push_back({a, b});
        const PathDiscs discs{paths, radius};
        std::vector<PairStart> fast(pairs.size()), scalar(pairs.size());
        classifyPairStarts(pairs, discs, h, toi, fast.data());
        classifyPairStartsScalar(pairs, discs, h, toi, scalar.data());
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            const auto [a, b] = pairs[k];
            ASSERT_EQ(fast[k].kind, scalar[k].kind) << "scene " << scene << " pair " << k;
            ASSERT_EQ(bits(fast[k].time), bits(scalar[k].time)) << "scene " << scene;
            ++counts[scalar[k].kind];
            if (b >= n) {
                EXPECT_EQ(scalar[k].kind, PairStart::Search); // a shape: the search's
                continue;
            }
            const PathMotion rel = paths[a].relativeTo(paths[b]);
            const std::optional<double> t =
                timeOfImpact(Circle{{0.0, 0.0}, radius[b]}, radius[a], rel, h, toi);
            switch (scalar[k].kind) {
            case PairStart::Contact:
                ASSERT_TRUE(t.has_value()) << "scene " << scene;
                EXPECT_EQ(bits(*t), bits(scalar[k].time));
                returning += scalar[k].time > rel.t0 ? 1 : 0;
                break;
            case PairStart::None:
                EXPECT_FALSE(t.has_value()) << "scene " << scene;
                break;
            case PairStart::Search: // apart at the start: only the search can tell
                EXPECT_GT(length(rel.p) - radius[b] - radius[a], toi.tolerance);
                break;
            }
        }
    }
    // Every outcome is common, a contact when the pair falls back together too, so no way
    // of failing could hide.
    const std::size_t all = counts[0] + counts[1] + counts[2];
    for (const std::size_t c : counts)
        EXPECT_GT(c, all / 20);
    EXPECT_GT(returning, 100u);
}
