// "Model no more than a scene needs": a shell under gravity alone follows the closed form
// (exact at any dt), switching drag on hands it to the integrator from its exact state,
// and the world counts which model each particle is in.
#include "physics/ballistics.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace phys;

namespace {
World flatGround(double tick, Integrator m = Integrator::ExplicitEuler) {
    WorldDef d;
    d.tickSeconds = tick;
    d.integrator = m; // the least accurate: the closed form must not depend on it
    // The time of impact counts a gap below this as touching (default 1e-9 m, which
    // would put the contact up to ~1.2e-9 m along a 30-degree descent).
    d.collision.toiTolerance = 1e-11;
    World w(d);
    w.shapes.addSegment({-10.0, 0.0}, {1000.0, 0.0}, material::kPerfectlyPlastic);
    return w;
}
} // namespace

TEST(ModelPolicy, AShotUnderGravityAloneLandsAtTheClosedFormPointAtAnyDt) {
    const Vec2 p0{0.0, 5.0}, v0{40.0, 25.0};
    const double r = 0.1, g = 9.81;
    // Where the closed form says the sphere touches the ground: y(t) = r.
    const double t = *timeToHeight(p0, v0, g, r);
    const Vec2 exact = ballisticState(p0, v0, {0.0, -g}, t).position;
    for (double tick : {1.0 / 30.0, 1.0 / 120.0, 1.0 / 7.0, 0.25}) {
        World w = flatGround(tick);
        ParticleDef pd;
        pd.position = p0;
        pd.velocity = v0;
        pd.radius = r;
        pd.material = material::kPerfectlyPlastic;
        const auto id = w.particles.add(pd);
        bool landed = false;
        for (int i = 0; i < 2000 && !landed; ++i) {
            w.step();
            EXPECT_TRUE(!(w.particles.flags[id] & kBallistic) || w.profile().closedForm == 1);
            for (const ContactEvent& e : w.contacts())
                if (e.a == id) {
                    landed = true;
                    EXPECT_NEAR(e.position.x, exact.x, 1e-9) << "tick " << tick;
                    EXPECT_NEAR(e.position.y, exact.y, 1e-9) << "tick " << tick;
                }
        }
        EXPECT_TRUE(landed) << tick;
    }
}

TEST(ModelPolicy, SwitchingDragOnMidFlightContinuesFromTheExactState) {
    WorldDef d;
    d.integrator = Integrator::RK4;
    World w(d);
    ParticleDef pd;
    pd.velocity = {30.0, 30.0};
    pd.radius = 0.05;
    const auto id = w.particles.add(pd);
    for (int i = 0; i < 120; ++i) w.step();
    EXPECT_TRUE(w.particles.flags[id] & kBallistic);
    EXPECT_EQ(w.profile().closedForm, 1);
    // The state after one second is the closed form's to the last bit.
    const auto exact = ballisticState({0, 0}, pd.velocity, d.forces.gravity, w.time());
    EXPECT_EQ(w.particles.position(id), exact.position);
    EXPECT_EQ(w.particles.velocity(id), exact.velocity);

    // Drag on: from the next tick the integrator carries it, starting from that state.
    WorldDef withDrag = d;
    withDrag.forces.drag = DragModel::Quadratic;
    w.setDef(withDrag);
    w.step();
    EXPECT_FALSE(w.particles.flags[id] & kBallistic);
    EXPECT_EQ(w.profile().integrated, 1);
    // The same tick taken by hand from the exact state with RK4 and drag.
    World ref(withDrag);
    ParticleDef from = pd;
    from.position = exact.position;
    from.velocity = exact.velocity;
    const auto rid = ref.particles.add(from);
    WorldDef integrate = withDrag;
    integrate.model = ModelPolicy::Integrate;
    ref.setDef(integrate);
    ref.step();
    EXPECT_EQ(w.particles.position(id), ref.particles.position(rid));
    EXPECT_EQ(w.particles.velocity(id), ref.particles.velocity(rid));
}

TEST(ModelPolicy, IntegratePolicySendsEveryParticleThroughTheIntegrator) {
    WorldDef d;
    d.model = ModelPolicy::Integrate;
    d.integrator = Integrator::ExplicitEuler;
    World w(d);
    ParticleDef pd;
    pd.velocity = {10.0, 10.0};
    const auto id = w.particles.add(pd);
    for (int i = 0; i < 120; ++i) w.step();
    EXPECT_EQ(w.profile().integrated, 1);
    EXPECT_EQ(w.profile().closedForm, 0);
    // Explicit Euler's truncation error shows: g t dt / 2 = 9.81 * 1 / 240 m.
    const auto exact = ballisticState({0, 0}, pd.velocity, d.forces.gravity, 1.0);
    EXPECT_NEAR(w.particles.py[id] - exact.position.y, 9.81 / 240.0, 1e-9);
}

TEST(ModelPolicy, SpringsAndAnchorsKeepParticlesOnTheIntegrator) {
    World w;
    ParticleDef pd;
    pd.position = {1.0, 0.0};
    const auto a = w.particles.add(pd);
    pd.position = {3.0, 0.0};
    const auto free = w.particles.add(pd);
    pd.mass = 0.0;
    w.particles.add(pd); // a fixed pin
    Spring s;
    s.a = a;
    s.restLength = 1.0;
    w.springs.push_back(s);
    w.step();
    EXPECT_FALSE(w.particles.flags[a] & kBallistic);
    EXPECT_TRUE(w.particles.flags[free] & kBallistic);
    EXPECT_EQ(w.profile().integrated, 1);
    EXPECT_EQ(w.profile().closedForm, 1);
    EXPECT_EQ(w.profile().fixed, 1);
}
