// The `fired` event's model and the `landed` event's closed_form_error_m, against the
// closed form p(t) = p0 + v0 t + g t^2/2 (game/landing.h, game/shot_model.h).
#include "game/effects/shot_feedback.h"
#include "game/landing.h"
#include "game/match.h"
#include "game/shot_model.h"
#include "shots.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

using namespace game;
using phys::Vec2;

namespace {

Command set(const std::string& name, SettingValue value) {
    Command c;
    c.kind = CommandKind::Set;
    c.text = name;
    c.value = std::move(value);
    return c;
}

struct Shot {
    std::optional<GameEvent> fired, landed;
    Vec2 p0, v0;
    double radius = 0.0;
};

/// First shot, flat ground at y = 0, no air: one shell at 45 degrees and 30 m/s under the
/// settings given, flown to its first contact.
Shot firstShot(const std::vector<Command>& settings,
               const Level& level = shots::level("12_first_shot.json")) {
    Match m(level);
    for (const Command& c : settings) EXPECT_EQ(m.apply(c), "") << c.text;
    Shot s;
    shots::shoot(m, 45.0, 30.0);
    const phys::ParticleId id = *m.shell();
    s.p0 = m.world().particles.position(id);
    s.v0 = m.world().particles.velocity(id);
    s.radius = m.world().particles.radius[id];
    for (int i = 0; i < 2400 && !s.landed; ++i) {
        m.step();
        for (const GameEvent& e : m.events()) {
            if (e.kind == EventKind::Fired) s.fired = e;
            if (e.kind == EventKind::Landed) s.landed = e;
        }
    }
    return s;
}

/// When y0 + vy t - g t^2/2 comes down to height y (the later root).
double descends(double y0, double vy, double g, double y) {
    return (vy + std::sqrt(vy * vy + 2.0 * g * (y0 - y))) / g;
}

} // namespace

TEST(FiredModel, NamesTheClosedFormUnderAutoAndTheIntegratorUnderIntegrate) {
    EXPECT_EQ(firstShot({}).fired->model, "closed-form");
    EXPECT_EQ(firstShot({set("model", std::string("integrate"))}).fired->model, "velocity-verlet")
        << "the default integrator";
    // An alias is reported by its canonical name, as `set integrator` lists it first.
    EXPECT_EQ(firstShot({set("model", std::string("integrate")),
                         set("integrator", std::string("euler-cromer"))})
                  .fired->model,
              "symplectic-euler");
    // Auto, but drag reaches the shell: the integrator flies it.
    EXPECT_EQ(firstShot({set("drag", true), set("integrator", std::string("rk4"))}).fired->model,
              "rk4");
}

// Wind acts on a shell only through drag (on v - wind): with drag off, a windy level flies
// the same path as a still one, the closed form stays exact, and the landing keeps its
// closed_form_error_m, the same to the bit.
TEST(LandedEvent, WindWithoutDragKeepsTheClosedFormExact) {
    Level windy = shots::level("12_first_shot.json");
    ASSERT_FALSE(windy.physics.drag);
    windy.physics.windMin = windy.physics.windMax = 8.0;
    const Match m(windy);
    ASSERT_NE(m.wind(), 0.0);
    EXPECT_FALSE(m.ballisticOnly()) << "the firing solutions still treat wind as unknown";
    EXPECT_TRUE(m.closedFormExact());
    const std::vector<Command> euler = {set("tick_hz", 30.0),
                                        set("model", std::string("integrate")),
                                        set("integrator", std::string("explicit-euler"))};
    const Shot still = firstShot(euler), blown = firstShot(euler, windy);
    ASSERT_TRUE(still.landed && blown.landed);
    ASSERT_TRUE(blown.landed->closedFormErrorM);
    EXPECT_EQ(*blown.landed->closedFormErrorM, *still.landed->closedFormErrorM);
    EXPECT_GT(*blown.landed->closedFormErrorM, 0.5);
    // With drag on, the wind bends the path: no closed form.
    windy.physics.drag = true;
    const Shot dragged = firstShot(euler, windy);
    ASSERT_TRUE(dragged.landed);
    EXPECT_FALSE(dragged.landed->closedFormErrorM);
}

TEST(FiredModel, TheAimsNameIsTheFiredOne) {
    Match m(shots::level("12_first_shot.json"));
    EXPECT_EQ(shotModelName(m), "closed-form");
    ASSERT_EQ(m.apply(set("model", std::string("integrate"))), "");
    ASSERT_EQ(m.apply(set("integrator", std::string("explicit-euler"))), "");
    EXPECT_EQ(shotModelName(m), "explicit-euler");
    EXPECT_EQ(shotModelLabel(shotModelName(m)), "explicit Euler");
}

// Explicit Euler from (y0, vy) gives y_n = y0 + vy t - g t^2/2 + g h t/2 at t = n h: the
// parabola launched at vy + g h/2, so it comes down later by about 2 (g h/2)/g = h and
// lands about vx h beyond the exact one. Between its samples the collision stage follows
// the path its positions imply, the chord (time_of_impact.h: a = 0 for explicit Euler),
// so the contact is where the chord across y = r meets it.
TEST(LandedEvent, ExplicitEulerAt30HzLandsTheHalfStepClimbBeyondTheClosedForm) {
    const Shot s = firstShot({set("tick_hz", 30.0), set("model", std::string("integrate")),
                              set("integrator", std::string("explicit-euler"))});
    ASSERT_TRUE(s.landed);
    ASSERT_TRUE(s.landed->closedFormErrorM);
    Match m(shots::level("12_first_shot.json"));
    const double g = -m.world().def().forces.gravity.y;
    const double h = (1.0 / 30.0) / m.world().def().substeps;
    const double exact = descends(s.p0.y, s.v0.y, g, s.radius);
    // Euler's samples, in closed form, to the first one at or below y = r.
    auto y = [&](double t) { return s.p0.y + (s.v0.y + 0.5 * g * h) * t - 0.5 * g * t * t; };
    int n = 1;
    while (y(n * h) > s.radius) ++n;
    const double t0 = (n - 1) * h, f = (y(t0) - s.radius) / (y(t0) - y(n * h));
    const double flown = t0 + f * h; // x moves at vx exactly, so time along the chord is x
    const double expected = s.v0.x * (flown - exact);
    EXPECT_NEAR(*s.landed->closedFormErrorM, expected, 1e-6);
    // The figure: the half-step climb alone, vx (t_euler - t_exact), 0.693 m; the
    // chord of the last step takes 1.3 mm off it.
    EXPECT_NEAR(s.v0.x * (descends(s.p0.y, s.v0.y + 0.5 * g * h, g, s.radius) - exact), 0.70, 0.01);
    EXPECT_NEAR(expected, 0.69, 0.005);
    EXPECT_EQ(s.landed->text, "shape");
    EXPECT_NEAR(s.landed->where.y, s.radius, 1e-6) << "its centre, on the ground";
}

TEST(LandedEvent, ExactMethodsLandOnTheClosedForm) {
    const Shot closed = firstShot({set("tick_hz", 30.0)});
    ASSERT_TRUE(closed.landed && closed.landed->closedFormErrorM);
    EXPECT_NEAR(*closed.landed->closedFormErrorM, 0.0, 1e-6);
    const Shot verlet = firstShot({set("tick_hz", 30.0), set("model", std::string("integrate")),
                                   set("integrator", std::string("velocity-verlet"))});
    ASSERT_TRUE(verlet.landed && verlet.landed->closedFormErrorM);
    EXPECT_NEAR(*verlet.landed->closedFormErrorM, 0.0, 1e-6);
}

TEST(LandedEvent, NoClosedFormErrorWhereNoClosedFormExists) {
    const Shot drag = firstShot({set("drag", true)});
    ASSERT_TRUE(drag.landed);
    EXPECT_FALSE(drag.landed->closedFormErrorM);
    const Shot wind = firstShot({set("drag", true), set("wind", 5.0)});
    ASSERT_TRUE(wind.landed);
    EXPECT_FALSE(wind.landed->closedFormErrorM);
}

TEST(LandedEvent, ClosedFormErrorIsSignedByTheDirectionOfFire) {
    // A shell fired left that lands 1 m farther left landed beyond: +1.
    const ShellLaunch left{{0.0, 0.0}, {-10.0, 10.0}, 0.1};
    const Vec2 g{0.0, -10.0};
    const double t = 2.0; // back at y = 0, x = -20
    EXPECT_DOUBLE_EQ(landingErrorAlongX(left, g, t, {-21.0, 0.0}), 1.0);
    const ShellLaunch right{{0.0, 0.0}, {10.0, 10.0}, 0.1};
    EXPECT_DOUBLE_EQ(landingErrorAlongX(right, g, t, {19.5, 0.0}), -0.5);
}

TEST(LandedEvent, FirstTouchFindsTheExactPathsMeetingWithALine) {
    // Over y = 0 from (0, 1) at (3, 4) under g = 10: y = 1 + 4t - 5t^2 = r at the later root.
    const ShellLaunch s{{0.0, 1.0}, {3.0, 4.0}, 0.25};
    const auto t = firstTouchTime(s, {0.0, -10.0}, 10.0, INFINITY,
                                  [&](Vec2 p) { return p.y - s.radius; });
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, (4.0 + std::sqrt(16.0 + 20.0 * 0.75)) / 10.0, 1e-9);
    EXPECT_FALSE(firstTouchTime(s, {0.0, -10.0}, 10.0, INFINITY,
                                [&](Vec2 p) { return p.y + 1000.0; }))
        << "a surface the path never meets within the time";
}

namespace {
/// Fires at 45 degrees and 30 m/s and lets the shot feedback watch `ticks` ticks of it.
ShotFeedback watchShot(Match& m, int ticks) {
    ShotFeedback feedback;
    shots::shoot(m, 45.0, 30.0);
    std::size_t seen = 0;
    for (int i = 0; i < ticks; ++i) {
        m.step();
        for (; seen < m.events().size(); ++seen) feedback.event(m, m.events()[seen]);
    }
    return feedback;
}
} // namespace

TEST(ExactPath, TheVerdictSaysHowFarFromTheExactPathAndTheViewDrawsIt) {
    Match m(shots::level("12_first_shot.json"));
    for (const Command& c : {set("tick_hz", 30.0), set("model", std::string("integrate")),
                             set("integrator", std::string("explicit-euler"))})
        ASSERT_EQ(m.apply(c), "");
    const ShotFeedback feedback = watchShot(m, 400);
    const auto& exact = feedback.exactPath();
    ASSERT_TRUE(exact);
    // The verdict, the one line the screen shows, carries the comparison.
    const std::string verdict = feedback.verdict();
    const std::string words =
        "; explicit Euler, 30 Hz: 0.69 m long of the exact path; energy +1.5 %";
    ASSERT_GE(verdict.size(), words.size()) << verdict;
    EXPECT_EQ(verdict.substr(verdict.size() - words.size()), words) << verdict;
    EXPECT_EQ(verdict.rfind("missed by ", 0), 0u) << verdict;
    // The path drawn is the closed form from the muzzle, to the exact landing: 0.69 m
    // short of where the flown shell came down, at the same height.
    EXPECT_EQ(exact->points.front(), m.flight().launchPosition);
    EXPECT_NEAR(exact->flownLanding.x - exact->exactLanding.x, exact->errorM, 1e-9);
    EXPECT_NEAR(exact->exactLanding.y, exact->flownLanding.y, 1e-6);
    // Explicit Euler: v_n exact, y_n high by |g| h t / 2, so the energy per kg has grown
    // by |g|^2 h t / 2 at the last tick before the contact.
    const double g = -m.world().def().forces.gravity.y, h = 1.0 / 30.0;
    const phys::Vec2 p0 = m.flight().launchPosition, v0 = m.flight().launchVelocity;
    const double e0 = 0.5 * phys::dot(v0, v0) + g * p0.y;
    // Its x moves at vx exactly, so the time of that tick is (x - x0) / vx.
    const double tBefore = (m.flight().preLandingPosition.x - p0.x) / v0.x;
    EXPECT_NEAR(tBefore / h, std::round(tBefore / h), 1e-9) << "a tick of the flight";
    EXPECT_NEAR(exact->energyChange, g * g * h * tBefore / 2.0 / e0, 1e-9);
}

TEST(ExactPath, NoneWhenTheClosedFormFlewTheShell) {
    Match m(shots::level("12_first_shot.json"));
    EXPECT_FALSE(watchShot(m, 1000).exactPath());
}
