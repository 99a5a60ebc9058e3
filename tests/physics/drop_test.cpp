// The drop experiment (Claypool, Game Physics (ch. 10)): apex k of a ball dropped from H is e^(2k) H. With
// the time-of-impact response and an integrator exact under constant acceleration,
// that holds at any step size; the Euler methods show their own error.
#include "physics/experiments/drop.h"
#include "physics/materials.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace phys;

namespace {

DropResult drop(MaterialId m, Integrator method, double dt, double H = 0.92, int bounces = 3) {
    DropDef d;
    d.height = H;
    d.material = m;
    d.integrator = method;
    d.dt = dt;
    d.bounces = bounces;
    return simulateDrop(d);
}

} // namespace

// Every preset, both steps, the three exact integrators: the first three apexes within
// 0.5 % of e^(2k) H (H = 0.92 m, the measurements' drop height).
TEST(Drop, EveryPresetMatchesESquaredKHAtBothSteps) {
    for (const RestitutionPreset& p : kRestitutionPresets)
        for (const double dt : {1.0 / 60.0, 1.0 / 240.0})
            for (const Integrator m :
                 {Integrator::VelocityVerlet, Integrator::Midpoint, Integrator::RK4}) {
                const DropResult r = drop(p.id, m, dt);
                SCOPED_TRACE(std::string(p.name) + " " + info(m).name +
                             " dt=" + std::to_string(dt));
                EXPECT_DOUBLE_EQ(r.restitution, p.restitution);
                ASSERT_EQ(r.bounces.size(), 3u);
                for (int k = 0; k < 3; ++k) {
                    const double expected = std::pow(p.restitution, 2 * (k + 1)) * 0.92;
                    EXPECT_DOUBLE_EQ(r.bounces[k].expected, expected);
                    if (expected > 0.0)
                        EXPECT_NEAR(r.bounces[k].apex / expected, 1.0, 0.005) << "bounce " << k + 1;
                    else
                        EXPECT_NEAR(r.bounces[k].apex, 0.0, 1e-6) << "bounce " << k + 1;
                }
            }
}

// The defaults (velocity Verlet, dt = 1/120 s, continuous detection) do the same, and
// so does overlap testing with bisection (continuous detection off) for a drop, which
// cannot tunnel.
TEST(Drop, DefaultsAndOverlapTestingMatchToo) {
    for (const bool continuous : {true, false})
        for (const RestitutionPreset& p : kRestitutionPresets) {
            DropDef d;
            d.material = p.id;
            d.collision.continuous = continuous;
            const DropResult r = simulateDrop(d);
            ASSERT_EQ(r.bounces.size(), 3u) << p.name;
            for (int k = 0; k < 3; ++k) {
                const double expected = std::pow(p.restitution, 2 * (k + 1)) * d.height;
                EXPECT_NEAR(r.bounces[k].apex, expected, 0.005 * expected + 1e-9)
                    << p.name << " " << k;
            }
        }
}

// A pair entry overrides the table: --cor E.
TEST(Drop, CoefficientOverridesTheMaterial) {
    DropDef d;
    d.material = material::kGolf;
    d.restitution = 0.5;
    d.height = 2.0;
    const DropResult r = simulateDrop(d);
    EXPECT_DOUBLE_EQ(r.restitution, 0.5);
    ASSERT_EQ(r.bounces.size(), 3u);
    EXPECT_NEAR(r.bounces[0].apex, 0.5, 0.5 * 1e-6);
    EXPECT_NEAR(r.bounces[1].apex, 0.125, 0.125 * 1e-6);
    EXPECT_NEAR(r.bounces[2].apex, 0.03125, 0.03125 * 1e-6);
}

// The Euler methods: their apexes are what their own positions give, so the report
// shows their error rather than hiding it. It is first order: it shrinks about 4x from
// dt = 1/60 to 1/240, and is far beyond the exact integrators' at the same step.
TEST(Drop, EulerMethodsShowTheirFirstOrderError) {
    for (const Integrator m : {Integrator::ExplicitEuler, Integrator::SymplecticEuler}) {
        const DropResult coarse = drop(material::kGolf, m, 1.0 / 60.0);
        const DropResult fine = drop(material::kGolf, m, 1.0 / 240.0);
        const DropResult exact = drop(material::kGolf, Integrator::VelocityVerlet, 1.0 / 60.0);
        ASSERT_EQ(coarse.bounces.size(), 3u);
        ASSERT_EQ(fine.bounces.size(), 3u);
        const double ec = std::abs(coarse.bounces[0].relativeError);
        const double ef = std::abs(fine.bounces[0].relativeError);
        std::printf("%s golf first apex error: dt=1/60 %.4f %%, dt=1/240 %.4f %%, velocity-verlet "
                    "%.2e %%\n",
                    info(m).name, 100 * coarse.bounces[0].relativeError,
                    100 * fine.bounces[0].relativeError, 100 * exact.bounces[0].relativeError);
        EXPECT_GT(ec, 100.0 * std::abs(exact.bounces[0].relativeError));
        EXPECT_NEAR(ec / ef, 4.0, 1.0) << info(m).name; // order 1: dt / 4 -> error / 4
    }
}
