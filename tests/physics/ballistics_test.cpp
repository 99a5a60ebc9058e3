// Closed-form ballistics and the firing solution against the worked numbers of Rabin's
// "Real-time Game Physics" (Introduction to Game Development, 4.3).
#include "physics/ballistics.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace phys;

namespace {

// Angles (degrees) for a shot; the chapter gives them to 0.1 degree.
std::vector<double> angles(Vec2 from, Vec2 to, double speed, double g = 9.81) {
    std::vector<double> out;
    for (const auto& s : solveFiring(from, to, speed, g)) out.push_back(s.angleDeg);
    return out;
}

} // namespace

TEST(ClosedForm, StateMatchesTheFormula) {
    const Vec2 p0{10, 2}, v0{7.68, 29.0}, g{0, -9.81};
    const auto s = ballisticState(p0, v0, g, 0.2);
    EXPECT_DOUBLE_EQ(s.position.y, 2.0 + 29.0 * 0.2 - 0.5 * 9.81 * 0.04);
    EXPECT_NEAR(s.position.y, 7.6038, 1e-12);
    EXPECT_DOUBLE_EQ(s.velocity.y, 29.0 - 9.81 * 0.2);
    EXPECT_DOUBLE_EQ(s.position.x, 10.0 + 7.68 * 0.2);
}

TEST(ClosedForm, ApexRangeAndTimeToHeight) {
    const double g = 9.81, v = 20.0, a = 30.0 * std::numbers::pi / 180.0;
    const Vec2 v0{v * std::cos(a), v * std::sin(a)};
    EXPECT_NEAR(apexTime(v0, g), v0.y / g, 1e-15);
    EXPECT_NEAR(apex({0, 0}, v0, g).y, v0.y * v0.y / (2 * g), 1e-12);
    // Range v^2 sin(2a) / g.
    EXPECT_NEAR(range(v0, g), v * v * std::sin(2 * a) / g, 1e-12);
    // Back at launch height after 2 vy / g; at half the apex height on the way up
    // and on the way down, symmetric about the apex time.
    EXPECT_NEAR(*timeToHeight({0, 0}, v0, g, 0.0), 2 * v0.y / g, 1e-12);
    const double h = 0.5 * apex({0, 0}, v0, g).y;
    const double up = *timeToHeight({0, 0}, v0, g, h, true);
    const double down = *timeToHeight({0, 0}, v0, g, h, false);
    EXPECT_NEAR(up + down, 2 * apexTime(v0, g), 1e-12);
    EXPECT_FALSE(timeToHeight({0, 0}, v0, g, 100.0).has_value());
    // Below the launch point there is no ascending crossing, only the descent.
    EXPECT_FALSE(timeToHeight({0, 0}, v0, g, -5.0, true).has_value());
    EXPECT_TRUE(timeToHeight({0, 0}, v0, g, -5.0, false).has_value());
}

// Rabin 4.3, "target practice": from (10, 2) to (50, 20) at 30 m/s: 39.1 or 75.2 deg.
TEST(FiringSolution, NotesTargetAboveTheCannon) {
    const auto a = angles({10, 2}, {50, 20}, 30.0);
    ASSERT_EQ(a.size(), 2u);
    EXPECT_NEAR(a[0], 39.1, 0.05);
    EXPECT_NEAR(a[1], 75.2, 0.05);
}

// Rabin 4.3: a target 40 m away at the same height.
// As g -> 0 the direct shot tends to the straight line at constant speed, and stays a
// finite number even where g^2/4 underflows to zero (g = 1e-200): t = |d| / s to rounding.
TEST(FiringSolution, VanishingGravityGivesTheStraightShot) {
    const Vec2 from{10.0, 2.0}, to{50.0, 20.0};
    const double straightT = length(to - from) / 30.0;
    const double straightDeg = std::atan2(18.0, 40.0) * 180.0 / std::numbers::pi;
    for (const double g : {1e-9, 1e-100, 1e-200, 1e-300}) {
        const auto s = solveFiring(from, to, 30.0, g);
        ASSERT_FALSE(s.empty()) << g;
        EXPECT_NEAR(s[0].flightTime, straightT, 1e-9 * straightT) << g;
        EXPECT_NEAR(s[0].angleDeg, straightDeg, 1e-6) << g;
    }
}

TEST(FiringSolution, NotesTargetAtTheSameHeight) {
    struct Case {
        double speed, low, high;
    };
    for (const Case c : {Case{25.0, 19.4, 70.6}, Case{20.0, 39.4, 50.6}, Case{19.85, 42.4, 47.6}}) {
        const auto a = angles({0, 0}, {40, 0}, c.speed);
        ASSERT_EQ(a.size(), 2u) << c.speed;
        EXPECT_NEAR(a[0], c.low, 0.05) << c.speed;
        EXPECT_NEAR(a[1], c.high, 0.05) << c.speed;
    }
    EXPECT_TRUE(angles({0, 0}, {40, 0}, 19.0).empty()) << "19 m/s cannot reach 40 m";
}

TEST(FiringSolution, EdgeOfRangeHasOneSolutionAt45Degrees) {
    // Maximum range on level ground is v^2/g at 45 degrees.
    const double v = 20.0, g = 9.81;
    const auto s = solveFiring({0, 0}, {v * v / g, 0}, v, g);
    ASSERT_GE(s.size(), 1u);
    EXPECT_NEAR(s[0].angleDeg, 45.0, 1e-3);
}

TEST(FiringSolution, ShotsToTheLeftAreAboveNinetyDegrees) {
    const auto right = solveFiring({0, 0}, {40, 0}, 25.0, 9.81);
    const auto left = solveFiring({0, 0}, {-40, 0}, 25.0, 9.81);
    ASSERT_EQ(left.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_GT(left[i].angleDeg, 90.0);
        EXPECT_NEAR(left[i].angleDeg, 180.0 - right[i].angleDeg, 1e-9);
        EXPECT_NEAR(left[i].flightTime, right[i].flightTime, 1e-12);
    }
    EXPECT_LT(left[0].flightTime, left[1].flightTime) << "low shot first";
}

TEST(FiringSolution, EverySolutionHitsTheTargetInTheClosedForm) {
    const Vec2 from{3, 7}, to{-55, -12};
    const double speed = 33.0, g = 3.71;
    const auto sols = solveFiring(from, to, speed, g);
    ASSERT_EQ(sols.size(), 2u);
    for (const auto& s : sols) {
        EXPECT_NEAR(length(s.launchVelocity), speed, 1e-9);
        const auto end = ballisticState(from, s.launchVelocity, {0, -g}, s.flightTime);
        EXPECT_NEAR(end.position.x, to.x, 1e-9);
        EXPECT_NEAR(end.position.y, to.y, 1e-9);
    }
}

TEST(FiringSolution, NoGravityMeansOneStraightShot) {
    const auto s = solveFiring({0, 0}, {3, 4}, 5.0, 0.0);
    ASSERT_EQ(s.size(), 1u);
    EXPECT_NEAR(s[0].flightTime, 1.0, 1e-15);
    EXPECT_NEAR(s[0].angleDeg, std::atan2(4.0, 3.0) * 180 / std::numbers::pi, 1e-12);
}

// Rabin 4.3, explicit Euler worked example: m = 2.5 kg, S = <mV, p> with
// mV = (19.2, 72.5) kg m/s and p = (10, 2) m, g = 9.81. One step of dt gives the
// numerical height; the closed form gives the exact one.
TEST(ExplicitEulerTable, OneStepReproducesTheNotes) {
    struct Row {
        double dt, numeric, exact;
    };
    const Row rows[] = {{0.2, 7.8000, 7.6038}, {0.1, 4.9000, 4.8510}, {0.01, 2.2900, 2.2895}};
    const double m = 2.5;
    const Vec2 momentum{19.2, 72.5}, p0{10, 2};
    for (const Row& r : rows) {
        WorldDef def;
        def.model = ModelPolicy::Integrate;
        def.tickSeconds = r.dt;
        def.integrator = Integrator::ExplicitEuler;
        World w(def);
        ParticleDef pd;
        pd.position = p0;
        pd.velocity = momentum / m;
        pd.mass = m;
        const auto id = w.particles.add(pd);
        w.step();
        EXPECT_NEAR(w.particles.py[id], r.numeric, 5e-5) << "dt " << r.dt;
        const auto exact = ballisticState(p0, momentum / m, {0, -9.81}, r.dt);
        EXPECT_NEAR(exact.position.y, r.exact, 5e-5) << "dt " << r.dt;
        // The truncation error is exactly g dt^2 / 2 for one step.
        EXPECT_NEAR(w.particles.py[id] - exact.position.y, 0.5 * 9.81 * r.dt * r.dt, 1e-12);
    }
}
