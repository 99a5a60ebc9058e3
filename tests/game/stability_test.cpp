// The stability bench agrees with theory within 2 %.
#include "game/bench/stability.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace game::bench;
using phys::Integrator;

TEST(Stability, SpringLimitsMatchTheory) {
    // Explicit Euler: |lambda|^2 = 1 + (w dt)^2 > 1 at every dt.
    EXPECT_EQ(maxStableOmegaDt(Integrator::ExplicitEuler), 0.0);
    for (double wdt : {1e-3, 1e-2, 0.1, 1.0})
        EXPECT_GT(energyGrowth(Integrator::ExplicitEuler, wdt), kGrowthTolerance) << wdt;
    // The symplectic family: w dt < 2.
    for (Integrator m : {Integrator::SymplecticEuler, Integrator::Verlet,
                         Integrator::VelocityVerlet, Integrator::Leapfrog})
        EXPECT_NEAR(maxStableOmegaDt(m), 2.0, 0.02 * 2.0) << phys::info(m).name;
    // RK4: |R(i w dt)| <= 1 up to 2 sqrt(2).
    EXPECT_NEAR(maxStableOmegaDt(Integrator::RK4), 2.0 * std::sqrt(2.0), 0.02 * 2.83);
    // Implicit Euler never goes unstable.
    EXPECT_TRUE(std::isinf(maxStableOmegaDt(Integrator::ImplicitEuler)));
}

TEST(Stability, RopeSpringLimitAtTheGameTick) {
    // A chain's fastest mode has w = 2 sqrt(k/m); symplectic Euler needs w dt < 2, so the
    // stiffest spring is k = m / dt^2 (0.1 kg at 120 Hz: 1440 N/m).
    RopeDef rope;
    const double theory = rope.particleMass / (rope.tickSeconds * rope.tickSeconds);
    EXPECT_NEAR(stiffestRopeSpring(Integrator::SymplecticEuler, rope), theory, 0.05 * theory);
    EXPECT_TRUE(std::isinf(stiffestRopeSpring(Integrator::ImplicitEuler, rope)));
    EXPECT_LT(stiffestRopeSpring(Integrator::ExplicitEuler, rope), 0.1 * theory);
}
