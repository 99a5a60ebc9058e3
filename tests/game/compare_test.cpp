// Compare: every integrator fired with the same shot, measured at the landing
// against the closed form (gravity alone) or fine RK4 (drag, wind).
#include "game/compare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace game;
namespace fs = std::filesystem;

namespace {
const fs::path kLevels = fs::path(ARTILLERY_SOURCE_DIR) / "levels";
Level level(const std::string& name) { return loadLevel((kLevels / name).string()); }

const IntegratorPath& find(const std::vector<IntegratorPath>& paths, phys::Integrator id) {
    for (const auto& p : paths)
        if (!p.isReference && p.integrator == id) return p;
    throw std::runtime_error("integrator missing from compare");
}


CompareDef onLaunchHeight() {
    CompareDef d;
    d.surface = LandingSurface::LaunchHeight;
    return d;
}
} // namespace

TEST(Compare, OnePathPerIntegratorPlusTheClosedFormLast) {
    Match m(level("01_earth_basics.json"));
    ASSERT_TRUE(m.ballisticOnly());
    const auto paths = compareIntegrators(m, 50.0, 30.0, onLaunchHeight());
    ASSERT_EQ(paths.size(), phys::integrators().size() + 1);
    EXPECT_TRUE(paths.back().isReference);
    EXPECT_EQ(paths.back().name, "closed-form");
    for (const auto& p : paths) {
        EXPECT_TRUE(p.landed) << p.name;
        EXPECT_EQ(p.reference, LandingReference::ClosedForm) << p.name;
        EXPECT_EQ(p.points.front().x, m.muzzle(50.0).x) << p.name;
    }
    // The closed form lands at range v0x * 2 v0y / g from the muzzle.
    const double a = 50.0 * 3.14159265358979323846 / 180.0;
    const double range = 30.0 * std::cos(a) * 2.0 * 30.0 * std::sin(a) / 9.81;
    EXPECT_NEAR(paths.back().landing.x - m.muzzle(50.0).x, range, 1e-9);
}

TEST(Compare, Rk4AndVelocityVerletLandOnTheClosedFormWithoutDrag) {
    Match m(level("01_earth_basics.json"));
    for (const CompareDef& d : {CompareDef{}, onLaunchHeight()}) {
        const auto paths = compareIntegrators(m, 50.0, 30.0, d);
        EXPECT_LT(find(paths, phys::Integrator::RK4).landingError, 1e-9);
        EXPECT_LT(find(paths, phys::Integrator::VelocityVerlet).landingError, 1e-9);
    }
}

TEST(Compare, PathsLandOnTheTerrainWhereTheClosedFormMeetsIt) {
    Match m(level("01_earth_basics.json"));
    const double angle = 50.0, speed = 30.0;
    const auto paths = compareIntegrators(m, angle, speed);
    const IntegratorPath& ref = paths.back();
    ASSERT_TRUE(ref.landed);
    const Heightfield& ground = m.terrain();
    // The landing is on the ground, and on the parabola at the flight time.
    EXPECT_NEAR(ref.landing.y, ground.heightAt(ref.landing.x), 1e-9);
    const double a = angle * 3.14159265358979323846 / 180.0;
    const phys::Vec2 p0 = m.muzzle(angle), v0{speed * std::cos(a), speed * std::sin(a)};
    const double t = ref.flightTime;
    EXPECT_NEAR(ref.landing.x, p0.x + v0.x * t, 1e-9);
    EXPECT_NEAR(ref.landing.y, p0.y + v0.y * t - 0.5 * 9.81 * t * t, 1e-9);
    // Not the launch height: this level's ground is not level with the muzzle.
    EXPECT_GT(std::abs(ref.landing.y - p0.y), 0.1);
    for (const auto& p : paths) {
        ASSERT_TRUE(p.landed) << p.name;
        EXPECT_NEAR(p.landing.y, ground.heightAt(p.landing.x), 1e-6) << p.name;
    }
}

TEST(Compare, ExplicitEulerIsFirstOrderAtLanding) {
    Match m(level("01_earth_basics.json"));
    CompareDef d = onLaunchHeight();
    d.tickSeconds = 1.0 / 120.0;
    const double e1 = find(compareIntegrators(m, 50.0, 30.0, d), phys::Integrator::ExplicitEuler).landingError;
    d.tickSeconds /= 2.0;
    const double e2 = find(compareIntegrators(m, 50.0, 30.0, d), phys::Integrator::ExplicitEuler).landingError;
    d.tickSeconds /= 2.0;
    const double e3 = find(compareIntegrators(m, 50.0, 30.0, d), phys::Integrator::ExplicitEuler).landingError;
    // Measurably off (centimetres at 120 Hz), and halving with the tick: order 1.
    EXPECT_GT(e1, 1e-3);
    EXPECT_NEAR(e1 / e2, 2.0, 0.1);
    EXPECT_NEAR(e2 / e3, 2.0, 0.1);
}

TEST(Compare, WithDragTheReferenceIsFineRk4AndRk4IsClose) {
    Match m(level("03_windy_valley.json"));
    ASSERT_FALSE(m.ballisticOnly()) << "03_windy_valley must have drag or wind for this test";
    const auto paths = compareIntegrators(m, 50.0, 30.0);
    EXPECT_EQ(paths.back().reference, LandingReference::FineRK4);
    EXPECT_TRUE(paths.back().isReference);
    const double rk4 = find(paths, phys::Integrator::RK4).landingError;
    const double euler = find(paths, phys::Integrator::ExplicitEuler).landingError;
    EXPECT_LT(rk4, 1e-3);
    EXPECT_GT(euler, 100.0 * rk4);
}

TEST(Compare, WindWithoutDragKeepsTheClosedFormAsTheReference) {
    Level windy = level("01_earth_basics.json");
    ASSERT_FALSE(windy.physics.drag);
    windy.physics.windMin = windy.physics.windMax = -12.0;
    const Match m(windy);
    ASSERT_NE(m.wind(), 0.0);
    const auto paths = compareIntegrators(m, 50.0, 30.0, onLaunchHeight());
    EXPECT_EQ(paths.back().reference, LandingReference::ClosedForm);
    EXPECT_EQ(paths.back().name, "closed-form");
    // The wind reaches no shell without drag: RK4 still lands on the closed form, and
    // every path lands where it does on the still level, to the bit.
    EXPECT_LT(find(paths, phys::Integrator::RK4).landingError, 1e-9);
    const Match calm(level("01_earth_basics.json"));
    const auto still = compareIntegrators(calm, 50.0, 30.0, onLaunchHeight());
    for (std::size_t i = 0; i < paths.size(); ++i)
        EXPECT_EQ(paths[i].landing.x, still[i].landing.x) << paths[i].name;
}
