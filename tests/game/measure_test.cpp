// The measuring tools' figures (game/measure.h) against the closed form of the shot they
// measure and against plane geometry.
#include "game/measure.h"
#include "physics/ballistics.h"
#include "shots.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace game;
using phys::Vec2;

TEST(Measure, TheProbeReadsTheExactPathsStateAndEnergies) {
    Match m(shots::level("12_first_shot.json")); // no air: the closed form flies it
    ShotRecorder rec;
    shots::shoot(m, 45.0, 30.0);
    const Vec2 p0 = m.flight().launchPosition, v0 = m.flight().launchVelocity;
    const Vec2 g = m.world().def().forces.gravity;
    const double dt = m.world().def().tickSeconds;
    for (int i = 0; i < 120; ++i) {
        m.step();
        rec.observe(m);
    }
    ASSERT_EQ(rec.shots().size(), 1u);
    // One second after the shot, exactly: the 120th tick.
    const phys::BallisticState at = phys::ballisticState(p0, v0, g, 120 * dt);
    const auto p = probe(rec.shots(), at.position + Vec2{0.2, 0.1}, 0.5);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->t, 1.0, 1e-12);
    EXPECT_NEAR(p->position.x, at.position.x, 1e-9);
    EXPECT_NEAR(p->position.y, at.position.y, 1e-9);
    EXPECT_NEAR(p->speed, phys::length(at.velocity), 1e-9);
    const double mass = rec.shots()[0].mass;
    EXPECT_DOUBLE_EQ(mass, m.selectedAmmo().preset.mass);
    EXPECT_NEAR(p->kinetic, 0.5 * mass * phys::dot(at.velocity, at.velocity), 1e-6);
    EXPECT_NEAR(p->potential, mass * -g.y * at.position.y, 1e-6);
    // Gravity alone: kinetic + potential is the launch's.
    const double launch = 0.5 * mass * phys::dot(v0, v0) + mass * -g.y * p0.y;
    EXPECT_NEAR(p->kinetic + p->potential, launch, 1e-6);
    EXPECT_FALSE(probe(rec.shots(), at.position + Vec2{0.0, 5.0}, 0.5)) << "nothing within reach";
    EXPECT_NEAR(*stopwatch(rec.shots()), 1.0, 1e-12);
    EXPECT_TRUE(rec.shots()[0].flying);
}

TEST(Measure, TheStopwatchStopsWhenTheShotIsOver) {
    Match m(shots::level("12_first_shot.json"));
    ShotRecorder rec;
    EXPECT_FALSE(stopwatch(rec.shots()));
    shots::shoot(m, 45.0, 30.0);
    for (int i = 0; i < 1200 && m.shell(); ++i) {
        m.step();
        rec.observe(m);
    }
    const double flight = *stopwatch(rec.shots());
    for (int i = 0; i < 60; ++i) {
        m.step();
        rec.observe(m);
    }
    EXPECT_FALSE(rec.shots()[0].flying);
    EXPECT_EQ(*stopwatch(rec.shots()), flight) << "stopped";
    EXPECT_GT(flight, 4.0);
    EXPECT_LT(flight, 5.0);
}

TEST(Measure, TheTapeIsTheDistanceAndAngleOfTheLine) {
    const TapeReading t = tape({1.0, 2.0}, {4.0, 6.0});
    EXPECT_DOUBLE_EQ(t.distance, 5.0);
    EXPECT_NEAR(t.angleDeg, std::atan2(4.0, 3.0) * 180.0 / 3.14159265358979323846, 1e-12);
    EXPECT_DOUBLE_EQ(tape({0.0, 0.0}, {-2.0, 0.0}).angleDeg, 180.0);
}
