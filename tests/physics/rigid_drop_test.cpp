// The rigid drop: Box2D's bounce apexes against e^(2k) H for every restitution preset,
// within a tolerance derived from how Box2D resolves a bounce.
#include "physics/rigid/rigid_drop.h"

#include <box2d/b2_common.h>
#include <gtest/gtest.h>

#include <cmath>

namespace phys {
namespace {

struct Preset {
    const char* name;
    double e;
};
// Claypool's measured presets ("Game Physics": balls dropped from 92 cm).
constexpr Preset kPresets[] = {
    {"golf", 0.858},         {"tennis", 0.712},           {"billiard", 0.804},
    {"hand ball", 0.752},    {"wooden", 0.603},           {"steel bearing", 0.597},
    {"glass marble", 0.658}, {"rubber-band ball", 0.828}, {"hollow hard plastic", 0.688},
};

// Why the tolerance is what it is. Box2D reverses, at a step boundary, the velocity the
// body has after that step's gravity: the reflected speed is off the true impact speed
// by up to one step of gravity, g h, at every bounce, and the errors add up over k
// bounces. On top of that the bounce happens somewhere inside the contact skin
// (b2_polygonRadius = 1 cm), moving the apex by up to about a skin, i.e. a launch-speed
// error of g skin / u. So compare launch speeds u = sqrt(2 g apex):
//     |u_k - e^k sqrt(2 g H)| <= k g h + g skin / u_k.
// Measured over the nine presets, H = 0.5..10 m, dt = 1/60..1/240 s and 1..4 sub-steps:
// the worst error is 0.85 of this bound (bench_rigid prints the apex errors).
void expectWithinBox2DTolerance(double height, double dt, int substeps) {
    const double g = 9.81;
    const double h = dt / substeps;
    for (const Preset& p : kPresets) {
        const std::vector<double> apex = rigidDropApexes(height, p.e, 3, dt, substeps);
        ASSERT_EQ(apex.size(), 3u) << p.name;
        for (int k = 1; k <= 3; ++k) {
            const double expected = std::pow(p.e, 2.0 * k) * height;
            const double uExact = std::sqrt(2.0 * g * expected);
            const double u = std::sqrt(2.0 * g * apex[k - 1]);
            const double tolerance = k * g * h + g * b2_polygonRadius / uExact;
            EXPECT_NEAR(u, uExact, tolerance) << p.name << " bounce " << k << ": apex "
                                              << apex[k - 1] << " m, expected " << expected << " m";
        }
    }
}

TEST(RigidDrop, ApexesWithinBox2DToleranceAt120Hz) {
    expectWithinBox2DTolerance(1.0, 1.0 / 120.0, 1);
}

TEST(RigidDrop, ApexesWithinBox2DToleranceWithSubSteps) {
    expectWithinBox2DTolerance(2.0, 1.0 / 120.0, 2);
    expectWithinBox2DTolerance(5.0, 1.0 / 60.0, 1);
}

TEST(RigidDrop, FirstBounceWithinFourPercentFromOneMetre) {
    // The figure README quotes: at dt = 1/120 s the first apex from 1 m is within 3.5 %
    // for every preset (measured 2.6..3.5 %, low: the reflected speed lacks up to g h).
    for (const Preset& p : kPresets) {
        const std::vector<double> apex = rigidDropApexes(1.0, p.e, 1, 1.0 / 120.0, 1);
        ASSERT_EQ(apex.size(), 1u);
        EXPECT_NEAR(apex[0], p.e * p.e, 0.04 * p.e * p.e) << p.name;
    }
}

TEST(RigidDrop, Box2DDefaultThresholdKillsSlowBounces) {
    // Box2D's default 1 m/s threshold: from 20 cm, wood's third impact is at
    // e^2 sqrt(2 g 0.2) = 0.72 m/s, so the ball stops dead after two bounces. The
    // project's 0.25 m/s keeps all three.
    RigidDropDef def;
    def.height = 0.2;
    def.restitution = 0.603;
    def.bounces = 3;
    EXPECT_EQ(rigidDropApexes(def).size(), 3u);
    def.restitutionThreshold = 1.0;
    EXPECT_EQ(rigidDropApexes(def).size(), 2u);
}

TEST(RigidDrop, PerfectlyPlasticDoesNotBounce) {
    EXPECT_TRUE(rigidDropApexes(1.0, 0.0, 3, 1.0 / 120.0, 1).empty());
}

} // namespace
} // namespace phys
