// The work-precision of the compared shot: each integrator's landing error at the tick
// and its halvings, against the closed form under gravity alone and against fine RK4
// with drag; the slopes are the methods' orders.
#include "game/compare_work.h"
#include "shots.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace game;

namespace {

const ShotWorkLine& lineOf(const ShotWork& w, phys::Integrator id) {
    for (const ShotWorkLine& l : w.lines)
        if (l.integrator == id) return l;
    throw std::runtime_error("integrator missing from the work-precision sweep");
}

ShotWorkDef at(double tickSeconds, LandingSurface surface) {
    ShotWorkDef d;
    d.compare.tickSeconds = tickSeconds;
    d.compare.surface = surface;
    return d;
}

} // namespace

TEST(CompareWork, OneLineOfFivePointsPerIntegratorWithTheCostOfEach) {
    const Match m(shots::level("01_earth_basics.json"));
    const ShotWork w =
        shotWorkPrecision(m, 50.0, 30.0, at(1.0 / 30.0, LandingSurface::LaunchHeight));
    ASSERT_EQ(w.lines.size(), phys::integrators().size());
    EXPECT_EQ(w.reference, LandingReference::ClosedForm);
    for (const ShotWorkLine& l : w.lines) {
        ASSERT_EQ(l.points.size(), 5u) << l.name;
        const int evals = phys::info(l.integrator).evaluations * m.world().def().substeps;
        for (std::size_t k = 0; k < l.points.size(); ++k) {
            const ShotWorkPoint& p = l.points[k];
            EXPECT_DOUBLE_EQ(p.tickSeconds, std::ldexp(1.0 / 30.0, 2 - static_cast<int>(k)));
            // Every tick flown up to the one it lands in: about the exact flight time over
            // the tick (explicit Euler and position Verlet come down a tick late,
            // symplectic and implicit Euler early).
            const double a = 50.0 * std::numbers::pi / 180.0;
            const double flight = 2.0 * 30.0 * std::sin(a) / 9.81;
            const double steps = p.evaluations / evals;
            EXPECT_EQ(steps, std::round(steps)) << l.name;
            EXPECT_NEAR(steps, flight / p.tickSeconds, 2.0) << l.name << " tick " << k;
        }
    }
}

TEST(CompareWork, UnderGravityExplicitEulerIsFirstOrderAndRk4AndVelocityVerletAreExact) {
    const Match m(shots::level("01_earth_basics.json"));
    for (const LandingSurface s : {LandingSurface::LaunchHeight, LandingSurface::Terrain}) {
        const ShotWork w = shotWorkPrecision(m, 50.0, 30.0, at(1.0 / 30.0, s));
        const ShotWorkLine& euler = lineOf(w, phys::Integrator::ExplicitEuler);
        // Its error halves with the tick: order 1, slope 1 on the log-log chart.
        for (std::size_t k = 1; k < euler.points.size(); ++k)
            EXPECT_NEAR(euler.points[k - 1].error / euler.points[k].error, 2.0, 0.1) << k;
        EXPECT_NEAR(observedOrder(euler), 1.0, 0.05);
        EXPECT_GT(euler.points.front().error, 0.1);
        for (const phys::Integrator exact :
             {phys::Integrator::RK4, phys::Integrator::VelocityVerlet})
            for (const ShotWorkPoint& p : lineOf(w, exact).points)
                EXPECT_LT(p.error, 1e-9);
    }
}

TEST(CompareWork, WithDragEachSlopeIsTheMethodsOrderAgainstFineRk4) {
    const Match m(shots::level("03_windy_valley.json"));
    ASSERT_FALSE(m.closedFormExact());
    const ShotWork w =
        shotWorkPrecision(m, 50.0, 30.0, at(1.0 / 8.0, LandingSurface::LaunchHeight));
    EXPECT_EQ(w.reference, LandingReference::FineRK4);
    for (const ShotWorkLine& l : w.lines) {
        std::string errors;
        for (const ShotWorkPoint& p : l.points) errors.append(" ").append(std::to_string(p.error));
        EXPECT_NEAR(observedOrder(l), phys::info(l.integrator).order, 0.3)
            << l.name << ":" << errors;
    }
}
