// The Stats window's live plot samples (conservedQuantities): energy and momentum of
// particles and Box2D bodies, against what free fall gives exactly.
#include "game/match.h"
#include "ui/game/stats_panel.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using game::Command;
using game::CommandKind;

// Flat ground at y = 0, no air, a sandbox: things spawned in the air fall freely.
game::Match sandbox() {
    return game::Match(game::parseLevel("flat.json", R"({"format": 1, "name": "flat",
      "mode": "sandbox",
      "world": {"min": [-50, -10], "max": [50, 60]},
      "physics": {"planet": "earth", "drag": false, "wind": 0, "water_level": -100},
      "terrain": {"points": [[-50, 0], [50, 0]], "destructible": false},
      "cannons": [{"position": [-40, 1]}],
      "targets": [{"position": [40, 5]}]})"));
}

Command spawn(const char* what, phys::Vec2 at) {
    Command c;
    c.kind = CommandKind::Spawn;
    c.text = what;
    c.at = at;
    return c;
}

TEST(ConservedQuantities, ABallInFreeFallKeepsItsEnergyAndGainsMomentumMgT) {
    game::Match m = sandbox();
    ASSERT_EQ(m.apply(spawn("golf-ball", {0.0, 40.0})), "");
    const ui::ConservedSample s0 = ui::conservedQuantities(m);
    const double mass = 0.04593, g = 9.81;
    for (int i = 0; i < 120; ++i) m.step(); // 1 s at 120 Hz: it falls 4.9 m
    const ui::ConservedSample s1 = ui::conservedQuantities(m);
    const double t = s1.time - s0.time;
    EXPECT_NEAR(t, 1.0, 1e-12);
    // On the closed form the state is exact, so E = 1/2 m v^2 + m g y is too.
    EXPECT_NEAR(s1.energy, s0.energy, 1e-9 * std::abs(s0.energy));
    EXPECT_NEAR(s0.energy, mass * g * 40.0, 1e-9);
    EXPECT_NEAR(s1.momentumX, 0.0, 1e-12);
    EXPECT_NEAR(s1.momentumY - s0.momentumY, -mass * g * t, 1e-9);
}

TEST(ConservedQuantities, AFallingBlockLosesExactlyWhatSymplecticEulerLoses) {
    // Box2D integrates v += g dt, then x += v dt: after n steps from rest
    // v = -g n dt and y = y0 - g dt^2 n (n + 1) / 2, so E = 1/2 m v^2 - m g.c falls by
    // exactly m g^2 dt^2 n / 2 (the energy the method's lag costs), and p_y = -m g n dt.
    game::Match m = sandbox();
    ASSERT_EQ(m.apply(spawn("block", {0.0, 40.0})), "");
    ASSERT_EQ(m.blocks().size(), 1u);
    const ui::ConservedSample s0 = ui::conservedQuantities(m);
    const int n = 60;
    for (int i = 0; i < n; ++i) m.step();
    const ui::ConservedSample s1 = ui::conservedQuantities(m);
    const phys::RigidBodyState b = m.rigid().state(m.blocks().front().body);
    const double mass = b.mass, g = 9.81, dt = (s1.time - s0.time) / n;
    ASSERT_GT(b.centerOfMass.y, 5.0) << "still in the air";
    // Box2D keeps state in single precision: velocities to ~1e-7 relative, positions
    // near y = 40 m to ~4e-6 m, so m g times 1e-5 m bounds the energy's rounding.
    EXPECT_NEAR(s1.momentumY - s0.momentumY, -mass * g * n * dt, 1e-5 * mass * g * n * dt);
    EXPECT_NEAR(s1.energy - s0.energy, -0.5 * mass * g * g * dt * dt * n, mass * g * 1e-5);
}

} // namespace
