// Rods and cables (Millington's contact-style constraints) against their definitions.
#include "physics/constraints/rods_and_cables.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace phys;

namespace {

// A rope of n rods of length L hanging from an anchor at (0, 10), released horizontal
// so that it swings and whips, not just hangs.
std::vector<ParticleId> rope(World& w, int n, double L, ConstraintKind kind = ConstraintKind::Rod) {
    std::vector<ParticleId> ids;
    ParticleId prev = kNoParticle;
    for (int i = 0; i < n; ++i) {
        ParticleDef pd;
        pd.position = {L * (i + 1), 10.0};
        pd.mass = 0.05;
        pd.radius = 0.02;
        const auto id = w.particles.add(pd);
        DistanceConstraint c;
        c.kind = kind;
        c.a = id;
        c.b = prev;
        c.anchor = {0.0, 10.0};
        c.length = L;
        EXPECT_EQ(validate(c, w.particles), "");
        w.constraints.push_back(c);
        ids.push_back(id);
        prev = id;
    }
    return ids;
}

double ropeLength(const World& w) {
    double total = 0.0;
    for (const auto& c : w.constraints) {
        const Vec2 b = c.b == kNoParticle ? c.anchor : w.particles.position(c.b);
        total += length(w.particles.position(c.a) - b);
    }
    return total;
}

} // namespace

// A rope of 20 rods, 2 m long, swinging down from horizontal under gravity for 10 s:
// every link, and so the whole rope, keeps its length within 0.1 %.
TEST(Rods, RopeKeepsItsLengthWithinATenthOfAPercent) {
    for (const Integrator m :
         {Integrator::VelocityVerlet, Integrator::RK4, Integrator::SymplecticEuler}) {
        WorldDef d;
        d.integrator = m;
        World w(d);
        const auto ids = rope(w, 20, 0.1);
        double worstLink = 0.0, worstRope = 0.0, lowest = 10.0;
        for (int i = 0; i < 1200; ++i) {
            w.step();
            for (const auto& c : w.constraints)
                worstLink = std::max(worstLink, lengthError(c, w.particles));
            worstRope = std::max(worstRope, std::abs(ropeLength(w) - 2.0) / 2.0);
            lowest = std::min(lowest, w.particles.py[ids.back()]);
        }
        std::printf("%s: 20-rod rope, worst link error %.2e, worst rope-length error %.2e\n",
                    info(m).name, worstLink, worstRope);
        EXPECT_LE(worstLink, 1e-3) << info(m).name; // 0.1 % of the link length
        EXPECT_LE(worstLink, 2.0 * d.collision.constraintTolerance)
            << info(m).name; // what CG gives
        EXPECT_LE(worstRope, 1e-3) << info(m).name;
        EXPECT_DOUBLE_EQ(w.constraintError(), [&] {
            double e = 0.0;
            for (const auto& c : w.constraints)
                e = std::max(e, lengthError(c, w.particles));
            return e;
        }()) << info(m).name;
        EXPECT_LT(lowest, 8.5) << info(m).name; // it really swung down (the end can reach 8 m)
        EXPECT_GE(lowest, 8.0 - 2e-3) << info(m).name; // and never further than the rope allows
    }
}

// A rod holds a pendulum at its length; its period for small swings is 2 pi sqrt(L/g).
TEST(Rods, PendulumOnARodHasTheSmallAnglePeriod) {
    WorldDef d;
    d.tickSeconds = 1.0 / 1000.0;
    World w(d);
    ParticleDef pd;
    const double L = 1.0, th0 = 0.05;
    pd.position = {L * std::sin(th0), 10.0 - L * std::cos(th0)};
    pd.radius = 0.01;
    const auto id = w.particles.add(pd);
    w.constraints.push_back({ConstraintKind::Rod, id, kNoParticle, {0.0, 10.0}, L});
    // Time of the first crossing from + to - x is a quarter period.
    double prevX = w.particles.px[id], t = 0.0;
    for (int i = 0; i < 2000; ++i) {
        w.step();
        const double x = w.particles.px[id];
        if (prevX > 0.0 && x <= 0.0) {
            t = (i + prevX / (prevX - x)) * d.tickSeconds;
            break;
        }
        prevX = x;
    }
    const double quarter = 0.5 * std::acos(-1.0) * std::sqrt(L / 9.81);
    // Finite amplitude lengthens the period by th0^2/16 (0.016 %); the rest is the step.
    EXPECT_NEAR(t, quarter * (1.0 + th0 * th0 / 16.0), 2e-3 * quarter);
}

// A cable is slack until taut: a particle below its anchor inside the cable's length
// falls freely (y = y0 - g t^2 / 2), then hangs at exactly the cable length.
TEST(Cables, SlackThenTaut) {
    WorldDef d;
    World w(d);
    ParticleDef pd;
    pd.position = {0.0, 9.5};
    pd.radius = 0.01;
    const auto id = w.particles.add(pd);
    w.constraints.push_back({ConstraintKind::Cable, id, kNoParticle, {0.0, 10.0}, 1.0});
    for (int i = 0; i < 24; ++i)
        w.step(); // 0.2 s: falls 0.196 m, still slack
    EXPECT_NEAR(w.particles.py[id], 9.5 - 0.5 * 9.81 * 0.04, 1e-12);
    for (int i = 0; i < 240; ++i)
        w.step();
    EXPECT_NEAR(w.particles.py[id], 9.0, 1e-9);
    EXPECT_NEAR(w.particles.vy[id], 0.0, 1e-9);
    EXPECT_EQ(lengthError(w.constraints[0], w.particles),
              0.0 * lengthError(w.constraints[0], w.particles));
    EXPECT_NE(validate(DistanceConstraint{ConstraintKind::Rod, id, id, {}, 1.0}, w.particles), "");
}

namespace {

// A 30-link chain from the anchor at (0, 0), its particles displaced off their rest
// lengths (a whipped rope mid-step); `order` lists the links in chain order or shuffled.
struct Chain {
    ParticleSet set;
    std::vector<DistanceConstraint> links;
};

enum class Order { Chain, Pairs, Shuffled };

Chain displacedChain(Order order) {
    Chain c;
    ParticleId prev = kNoParticle;
    for (int i = 0; i < 30; ++i) {
        ParticleDef pd;
        pd.position = {0.1 * (i + 1) + 0.004 * std::sin(1.7 * i), 0.006 * std::cos(2.3 * i)};
        pd.velocity = {0.3 * std::sin(0.9 * i), 0.5 * std::cos(1.1 * i)};
        pd.mass = 0.05 + 0.01 * (i % 3);
        const ParticleId id = c.set.add(pd);
        DistanceConstraint d;
        d.a = id;
        d.b = prev;
        d.length = 0.1;
        c.links.push_back(d);
        prev = id;
    }
    if (order == Order::Shuffled) // every 7th link first: links sharing a particle far apart
        std::stable_partition(c.links.begin(), c.links.end(),
                              [&](const DistanceConstraint& d) { return d.a % 7 == 0; });
    if (order == Order::Pairs) // 1, 0, 3, 2, ...: neighbours up to 3 apart in the list
        for (std::size_t k = 0; k + 1 < c.links.size(); k += 2)
            std::swap(c.links[k], c.links[k + 1]);
    return c;
}

} // namespace

// A chain listed in order has a band of 1 and is factored directly (tridiagonal); in
// pairs swapped, a band of 3 (the general banded factorization); shuffled (a band far
// above kDirectBandwidth), it goes to conjugate gradients. All solve the same
// equations, so they agree to rounding, and all keep every link's length.
TEST(Rods, TheBandedDirectSolveAgreesWithConjugateGradients) {
    Chain direct = displacedChain(Order::Chain), banded = displacedChain(Order::Pairs),
          iterative = displacedChain(Order::Shuffled);
    ConstraintScratch wd, wb, wi;
    const double ed = solveConstraints(direct.links, direct.set, wd, 4, 1e-9);
    const double eb = solveConstraints(banded.links, banded.set, wb, 4, 1e-9);
    const double ei = solveConstraints(iterative.links, iterative.set, wi, 4, 1e-9);
    EXPECT_GT(wd.lastDirectSolves, 0);
    EXPECT_EQ(wd.lastIterations, 0);
    EXPECT_GT(wb.lastDirectSolves, 0);
    EXPECT_EQ(wb.lastIterations, 0);
    EXPECT_EQ(wi.lastDirectSolves, 0);
    EXPECT_GT(wi.lastIterations, 0);
    EXPECT_LT(ed, 1e-9);
    EXPECT_LT(eb, 1e-9);
    EXPECT_LT(ei, 1e-9);
    for (std::size_t i = 0; i < direct.set.slots(); ++i) {
        EXPECT_NEAR(direct.set.px[i], iterative.set.px[i], 1e-12) << i;
        EXPECT_NEAR(direct.set.py[i], iterative.set.py[i], 1e-12) << i;
        EXPECT_NEAR(direct.set.vx[i], iterative.set.vx[i], 1e-9) << i;
        EXPECT_NEAR(direct.set.vy[i], iterative.set.vy[i], 1e-9) << i;
        EXPECT_NEAR(banded.set.px[i], direct.set.px[i], 1e-12) << i;
        EXPECT_NEAR(banded.set.py[i], direct.set.py[i], 1e-12) << i;
        EXPECT_NEAR(banded.set.vx[i], direct.set.vx[i], 1e-9) << i;
        EXPECT_NEAR(banded.set.vy[i], direct.set.vy[i], 1e-9) << i;
    }
    // No velocity along any rod is left (J v = 0).
    for (const DistanceConstraint& d : direct.links) {
        const Vec2 n =
            direct.set.position(d.a) - (d.b == kNoParticle ? d.anchor : direct.set.position(d.b));
        const Vec2 u =
            direct.set.velocity(d.a) - (d.b == kNoParticle ? Vec2{} : direct.set.velocity(d.b));
        EXPECT_NEAR(dot(u, n / length(n)), 0.0, 1e-12);
    }
}

// A straight rope pinned at both ends, each link stretched along the line: its rows are
// dependent (the particles can only move along the line, m links on m - 1 particles),
// so the factorization meets a vanishing pivot and the solve falls back to conjugate
// gradients, which stops on the dependent direction: nothing blows up.
TEST(Rods, ADependentSetFallsBackToConjugateGradients) {
    ParticleSet set;
    std::vector<DistanceConstraint> links;
    ParticleId prev = kNoParticle;
    for (int i = 0; i <= 5; ++i) {
        ParticleDef pd;
        pd.position = {0.2 * i, 0.0};
        pd.mass = (i == 0 || i == 5) ? 0.0 : 0.1;
        const ParticleId id = set.add(pd);
        if (prev != kNoParticle) {
            DistanceConstraint d;
            d.a = id;
            d.b = prev;
            d.length = 0.19;
            links.push_back(d);
        }
        prev = id;
    }
    ConstraintScratch w;
    solveConstraints(links, set, w, 4, 1e-9);
    EXPECT_EQ(w.lastDirectSolves, 0);
    EXPECT_GT(w.lastIterations, 0);
    for (std::size_t i = 0; i < set.slots(); ++i) {
        EXPECT_TRUE(std::isfinite(set.px[i]) && std::isfinite(set.py[i])) << i;
        EXPECT_NEAR(set.py[i], 0.0, 1e-12) << i;
    }
}
