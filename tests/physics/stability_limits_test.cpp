// The largest stable step of each integrator on an undamped spring (physics/stability.h),
// against the closed forms of the one-step amplification and against the integrators
// themselves, run just inside and just past each limit.
#include "physics/stability.h"
#include "physics/diagnostics.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace phys;

namespace {

/// A mass m on a zero-rest-length spring k to the origin, no gravity, stepped `steps`
/// times at dt by `method`: its energy at the end over its energy at the start.
double energyRatio(Integrator method, double k, double m, double dt, int steps) {
    WorldDef d;
    d.model = ModelPolicy::Integrate;
    d.tickSeconds = dt;
    d.integrator = method;
    d.forces.gravity = {0, 0};
    World w(d);
    ParticleDef pd;
    pd.position = {1.0, 0.0};
    pd.mass = m;
    const ParticleId id = w.particles.add(pd);
    Spring s;
    s.a = id;
    s.restLength = 0.0;
    s.stiffness = k;
    w.springs.push_back(s);
    const double e0 = energy(w.particles, w.springs, d.forces).total();
    for (int i = 0; i < steps; ++i) w.step();
    return energy(w.particles, w.springs, d.forces).total() / e0;
}

} // namespace

TEST(StabilityLimits, TheIssuesExampleSymplecticEulerAt5000NPerMOn1Kg) {
    // 2 / sqrt(5000) = 0.02828 s.
    EXPECT_NEAR(largestStableStep(Integrator::SymplecticEuler, 5000.0, 1.0), 2.0 / std::sqrt(5000.0), 1e-15);
    EXPECT_EQ(stiffnessWarning(Integrator::SymplecticEuler, 5000.0, 1.0, 1.0 / 30.0),
              "k = 5000 N/m with 1 kg needs dt < 0.028 s with symplectic-euler (now 0.033 s)");
    EXPECT_EQ(stiffnessWarning(Integrator::SymplecticEuler, 5000.0, 1.0, 1.0 / 120.0), "");
}

TEST(StabilityLimits, Rk4sLimitIsWhereItsAmplificationOnTheImaginaryAxisIsOne) {
    // |R(ix)|^2 = (1 - x^2/2 + x^4/24)^2 + (x - x^3/6)^2 = 1 - x^6/72 + x^8/576.
    const double x = stableOmegaDt(Integrator::RK4);
    const double re = 1.0 - x * x / 2.0 + x * x * x * x / 24.0, im = x - x * x * x / 6.0;
    EXPECT_NEAR(re * re + im * im, 1.0, 1e-12);
    EXPECT_NEAR(x, 2.0 * std::sqrt(2.0), 1e-15);
}

TEST(StabilityLimits, ExplicitEulerGainsExactlyOnePlusOmegaDtSquaredAStep) {
    const double k = 400.0, m = 2.0, dt = 0.01; // w dt = 0.1414
    const double wdt = springOmega(k, m) * dt;
    const int n = 50;
    EXPECT_NEAR(energyRatio(Integrator::ExplicitEuler, k, m, dt, n),
                std::pow(explicitEulerEnergyGrowth(wdt), n), 1e-9);
    EXPECT_EQ(largestStableStep(Integrator::ExplicitEuler, k, m), 0.0);
    EXPECT_NE(stiffnessWarning(Integrator::ExplicitEuler, k, m, dt).find("gains energy at any dt"),
              std::string::npos);
}

TEST(StabilityLimits, EachBoundedMethodStaysBoundedInsideItsLimitAndGrowsPastIt) {
    const double k = 2500.0, m = 1.0; // w = 50 rad/s
    for (Integrator method : {Integrator::SymplecticEuler, Integrator::VelocityVerlet,
                              Integrator::Leapfrog, Integrator::RK4}) {
        const double limit = largestStableStep(method, k, m);
        ASSERT_GT(limit, 0.0) << info(method).name;
        // Inside, the energy only oscillates (by up to 1 / (1 - (w dt / 2)^2) for the
        // symplectic family, 5.3 at 0.9 of the limit); past it, it grows geometrically.
        EXPECT_LT(energyRatio(method, k, m, 0.9 * limit, 2000), 10.0) << info(method).name;
        EXPECT_GT(energyRatio(method, k, m, 1.03 * limit, 200), 1e3) << info(method).name;
    }
    EXPECT_TRUE(std::isinf(largestStableStep(Integrator::ImplicitEuler, k, m)));
    EXPECT_LT(energyRatio(Integrator::ImplicitEuler, k, m, 1.0, 200), 1.0);
}

TEST(StabilityLimits, TheStiffestSpringIsByItsReducedMass) {
    ParticleSet s;
    ParticleDef a, b;
    a.mass = 1.0;
    b.mass = 3.0;
    const ParticleId ia = s.add(a), ib = s.add(b);
    Spring anchored;
    anchored.a = ia;
    anchored.stiffness = 100.0; // w = 10
    Spring between;
    between.a = ia;
    between.b = ib;
    between.stiffness = 90.0; // reduced mass 3/4: w = sqrt(120)
    const StiffestSpring w = stiffestSpring({anchored, between}, s);
    EXPECT_DOUBLE_EQ(w.stiffness, 90.0);
    EXPECT_DOUBLE_EQ(w.mass, 0.75);
    EXPECT_DOUBLE_EQ(w.omega, std::sqrt(120.0));
}
