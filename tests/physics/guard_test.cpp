// The simulation never explodes into the screen: every integrator at and beyond its
// stability limit, the stiffest springs, the fastest projectiles and a pile-up of
// contacts in one spot end with a finite world, and the guard names the cause.
#include "physics/guard.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace phys;

namespace {

// A hanging chain of springs whose stiffness puts the fastest mode at the given w dt
// (w_max = 2 sqrt(k/m) for a chain).
std::unique_ptr<World> chain(Integrator m, double omegaDt, int n = 12) {
    WorldDef d;
    d.integrator = m;
    auto w = std::make_unique<World>(d);
    const double mass = 0.1, h = d.tickSeconds;
    const double k = mass * std::pow(omegaDt / (2.0 * h), 2.0);
    ParticleId prev = kNoParticle;
    for (int i = 0; i < n; ++i) {
        ParticleDef pd;
        pd.position = {0.1 * (i + 1), 10.0};
        pd.mass = mass;
        pd.radius = 0.02;
        const auto id = w->particles.add(pd);
        Spring s;
        s.a = id;
        s.b = prev;
        s.anchor = {0.0, 10.0};
        s.restLength = 0.1;
        s.stiffness = k;
        w->springs.push_back(s);
        prev = id;
    }
    return w;
}

bool allFinite(const World& w) {
    for (std::size_t i = 0; i < w.particles.slots(); ++i)
        if (!std::isfinite(w.particles.px[i]) || !std::isfinite(w.particles.py[i]) ||
            !std::isfinite(w.particles.vx[i]) || !std::isfinite(w.particles.vy[i]))
            return false;
    return true;
}

} // namespace

TEST(Guard, EveryIntegratorAtAndBeyondItsLimitEndsFinite) {
    for (const auto& info : integrators()) {
        for (double factor : {0.9, 1.5, 50.0}) {
            const double limit = std::isinf(stableOmegaDt(info.id)) ? 4.0 : std::max(0.5, stableOmegaDt(info.id));
            auto w = chain(info.id, factor * limit);
            std::string cause;
            for (int t = 0; t < 1200; ++t) {
                w->step();
                const GuardReport g = guardWorld(*w);
                if (g.tripped() && cause.empty()) cause = g.cause;
                ASSERT_TRUE(allFinite(*w)) << info.name << " x" << factor << " tick " << t;
            }
            if (!cause.empty()) {
                EXPECT_NE(cause.find(info.name), std::string::npos) << cause;
            }
            if (info.id == Integrator::ImplicitEuler) {
                EXPECT_EQ(cause, "") << "never unstable";
            } else if (factor == 50.0) {
                EXPECT_NE(cause.find("is unstable at dt"), std::string::npos)
                    << info.name << ": " << cause;
            }
        }
    }
}

TEST(Guard, StiffestSpringsAreCutAndExplained) {
    auto w = chain(Integrator::ExplicitEuler, 1e6);
    GuardReport first;
    for (int t = 0; t < 200 && !first.tripped(); ++t) {
        w->step();
        first = guardWorld(*w);
    }
    ASSERT_TRUE(first.tripped());
    EXPECT_GT(first.springsCut, 0);
    EXPECT_NE(first.cause.find("explicit-euler with springs of"), std::string::npos) << first.cause;
    EXPECT_NE(first.cause.find("use implicit-euler"), std::string::npos);
    EXPECT_TRUE(allFinite(*w));
}

TEST(Guard, FastestProjectilesAreRemovedNotDrawn) {
    World w;
    ParticleDef pd;
    pd.velocity = {1e9, 0.0};
    const auto id = w.particles.add(pd);
    w.step();
    const GuardReport g = guardWorld(w);
    EXPECT_EQ(g.runaway, 1);
    EXPECT_FALSE(w.particles.alive(id));
    EXPECT_EQ(w.particles.px[id], 0.0) << "a removed slot holds no stale state";
}

TEST(Guard, NonFiniteStateIsRemoved) {
    World w;
    ParticleDef pd;
    pd.position = {NAN, 0.0};
    w.particles.add(pd);
    pd.position = {1.0, 1.0};
    const auto ok = w.particles.add(pd);
    const GuardReport g = guardWorld(w);
    EXPECT_EQ(g.nonFinite, 1);
    EXPECT_TRUE(w.particles.alive(ok));
    EXPECT_TRUE(allFinite(w));
}

TEST(Guard, AThousandOverlappingContactsInOneSpotStayFinite) {
    World w;
    w.shapes.addPolyline(std::vector<Vec2>{{-2, 5}, {-2, 0}, {2, 0}, {2, 5}});
    for (int i = 0; i < 1000; ++i) {
        ParticleDef pd;
        // All within a centimetre of one point: a pile-up of overlapping contacts.
        pd.position = {0.001 * (i % 10), 1.0 + 0.001 * (i / 10 % 10)};
        pd.radius = 0.05;
        w.particles.add(pd);
    }
    for (int t = 0; t < 20; ++t) {
        w.step();
        guardWorld(w);
        ASSERT_TRUE(allFinite(w)) << "tick " << t;
    }
}
