// The boxes of the particles' paths: four lanes and one path at a time give the same bits,
// each box is the one of the path's control points grown by the reach, a path at rest is
// boxed where it is, and only the listed particles' boxes are written.
#include "physics/collision/simd/path_boxes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <random>

using namespace phys;

namespace {

bool sameBits(const Aabb& x, const Aabb& y) {
    for (int k = 0; k < 4; ++k)
        if (std::bit_cast<std::uint64_t>((&x.lo.x)[k]) !=
            std::bit_cast<std::uint64_t>((&y.lo.x)[k]))
            return false;
    return true;
}

// Paths of every kind a step makes: at rest (all +0), at rest but for a signed zero,
// falling, rising, bounced (started later in the step), on a lattice where control points
// tie, and anywhere.
std::vector<PathMotion> stepPaths(std::mt19937_64& rng, int n, double h) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> kind(0, 5), cell(-3, 3);
    std::vector<PathMotion> paths;
    for (int i = 0; i < n; ++i) {
        PathMotion m;
        switch (kind(rng)) {
        case 0:
            m.p = {unit(rng), unit(rng)};
            break; // at rest
        case 1:
            m.p = {unit(rng), -0.0}, m.v = {-0.0, 0.0};
            break;
        case 2:
            m.p = {0.25 * cell(rng), 0.25 * cell(rng)}, m.v = {0.0, 0.5 * cell(rng)},
            m.a = {0.0, -19.62};
            break;
        default:
            m.p = {unit(rng), unit(rng)}, m.v = Vec2{unit(rng), unit(rng)} * 3.0;
            m.a = Vec2{unit(rng), unit(rng)} * 30.0;
        }
        m.t0 = kind(rng) < 4 ? 0.0 : 0.5 * (1.0 + unit(rng)) * h;
        paths.push_back(m);
    }
    return paths;
}

} // namespace

TEST(PathBoxes, LanesAndOnePathGiveTheControlPointsBoxToTheBit) {
    std::mt19937_64 rng(20261127);
    const double h = 1.0 / 120.0;
    const Aabb untouched{{7.0, 7.0}, {-7.0, -7.0}};
    for (int scene = 0; scene < 40; ++scene) {
        const int n = 5 + scene;
        const std::vector<PathMotion> paths = stepPaths(rng, n, h);
        std::vector<double> radius;
        for (int i = 0; i < n; ++i)
            radius.push_back(0.01 * (1 + i % 7));
        // Every other particle, out of order, as an active list can be.
        std::vector<std::uint32_t> which;
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); i += 1 + scene % 2)
            which.push_back(i);
        std::shuffle(which.begin(), which.end(), rng);
        const PathBoxing boxing{h, scene % 3 == 0 ? 0.1 : 0.0, scene % 4 == 0 ? 0.0 : 1e-9,
                                scene % 5 == 0};
        std::vector<Aabb> fast(n, untouched), scalar(n, untouched);
        pathBoxes(which, paths, radius, boxing, fast.data());
        pathBoxesScalar(which, paths, radius, boxing, scalar.data());
        for (int i = 0; i < n; ++i) {
            ASSERT_TRUE(sameBits(fast[i], scalar[i])) << "scene " << scene << " particle " << i;
            const bool listed = std::find(which.begin(), which.end(), i) != which.end();
            if (!listed) {
                EXPECT_TRUE(sameBits(scalar[i], untouched));
                continue;
            }
            // The box of the control points (start, start + v T/2, end; the end alone
            // when asked), grown by the reach.
            const PathMotion& m = paths[i];
            const double r = radius[i] * (1.0 + boxing.grow) + boxing.tolerance;
            const Vec2 end = m.position(h), mid = m.p + m.v * (0.5 * (h - m.t0));
            std::vector<Vec2> points = {end};
            if (!boxing.atEndOnly) points.insert(points.end(), {m.p, mid});
            double lx = end.x, ly = end.y, hx = end.x, hy = end.y;
            for (const Vec2 q : points) {
                lx = std::min(lx, q.x), ly = std::min(ly, q.y);
                hx = std::max(hx, q.x), hy = std::max(hy, q.y);
            }
            EXPECT_EQ(scalar[i].lo.x, lx - r);
            EXPECT_EQ(scalar[i].lo.y, ly - r);
            EXPECT_EQ(scalar[i].hi.x, hx + r);
            EXPECT_EQ(scalar[i].hi.y, hy + r);
        }
    }
}

TEST(PathBoxes, APathAtRestIsBoxedWhereItIs) {
    PathMotion m;
    m.p = {-0.0, 2.5};
    const Aabb box = pathBox(m, 0.5, {1.0 / 60.0, 0.0, 0.0, false});
    EXPECT_TRUE(sameBits(box, Aabb{{-0.5, 2.0}, {0.5, 3.0}}));
}
