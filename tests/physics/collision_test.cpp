// Collisions against exact answers: head-on impacts (equation 4), continuous detection
// against tunnelling, shapes, friction, resting contact, penalty contacts.
#include "physics/collision/time_of_impact.h"
#include "physics/diagnostics.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

using namespace phys;

namespace {

WorldDef weightless(double dt = 1.0 / 120.0) {
    WorldDef d;
    d.tickSeconds = dt;
    d.forces.gravity = {0.0, 0.0};
    return d;
}

// A material with restitution e and no friction, and its pair with itself set to e.
MaterialId ballOf(World& w, double e, const char* name = "test-ball") {
    const MaterialId id = *w.materials.add({name, e, 0.0, 0.0});
    w.materials.setPair(id, id, {e, 0.0, 0.0});
    return id;
}

ParticleId addBall(World& w, Vec2 p, Vec2 v, double mass, double r, MaterialId m) {
    ParticleDef d;
    d.position = p;
    d.velocity = v;
    d.mass = mass;
    d.radius = r;
    d.material = m;
    return w.particles.add(d);
}

} // namespace

// Equation 4 with e = 1 and equal masses: the particles exchange velocities.
TEST(HeadOn, ElasticEqualMassesSwapVelocities) {
    World w(weightless());
    const MaterialId m = ballOf(w, 1.0);
    const auto a = addBall(w, {-1.0, 0.0}, {3.0, 0.0}, 2.0, 0.1, m);
    const auto b = addBall(w, {1.0, 0.0}, {-1.0, 0.0}, 2.0, 0.1, m);
    const Vec2 p0 = momentum(w.particles);
    for (int i = 0; i < 120; ++i)
        w.step();
    EXPECT_DOUBLE_EQ(w.particles.vx[a], -1.0);
    EXPECT_DOUBLE_EQ(w.particles.vx[b], 3.0);
    EXPECT_EQ(w.particles.vy[a], 0.0);
    EXPECT_EQ(w.particles.vy[b], 0.0);
    const Vec2 p1 = momentum(w.particles);
    EXPECT_NEAR(p1.x, p0.x, 4 * std::numeric_limits<double>::epsilon() * 8.0);
    // They met when the gap 2 - 0.2 m closed at 4 m/s, t = 0.45 s, at x = 0.35 and 0.55,
    // and left with each other's velocity for the remaining 0.55 s (a contact counts
    // from a gap of toiTolerance = 1e-9 m, hence the 1e-8 m).
    EXPECT_NEAR(w.particles.px[a], 0.35 - 1.0 * 0.55, 1e-8);
    EXPECT_NEAR(w.particles.px[b], 0.55 + 3.0 * 0.55, 1e-8);
}

// e = 0: they move on together at the centre-of-mass velocity.
TEST(HeadOn, PlasticEqualMassesMoveTogether) {
    World w(weightless());
    const MaterialId m = ballOf(w, 0.0);
    const auto a = addBall(w, {-1.0, 0.0}, {3.0, 0.0}, 2.0, 0.1, m);
    const auto b = addBall(w, {1.0, 0.0}, {-1.0, 0.0}, 2.0, 0.1, m);
    for (int i = 0; i < 120; ++i)
        w.step();
    EXPECT_DOUBLE_EQ(w.particles.vx[a], 1.0);
    EXPECT_DOUBLE_EQ(w.particles.vx[b], 1.0);
    EXPECT_NEAR(w.particles.px[b] - w.particles.px[a], 0.2, 1e-8); // touching
    EXPECT_NEAR(momentum(w.particles).x, 4.0, 1e-14);
}

// Momentum is conserved to rounding for any e and any masses, and the separating speed
// is e times the closing speed (the definition of e).
TEST(HeadOn, MomentumConservedAndSeparationIsETimesApproach) {
    for (const double e : {0.0, 0.3, 0.597, 0.858, 1.0})
        for (const double mb : {0.5, 1.0, 7.0}) {
            World w(weightless());
            const MaterialId m = ballOf(w, e);
            const auto a = addBall(w, {-1.0, 0.2}, {5.0, 0.0}, 1.5, 0.1, m);
            const auto b = addBall(w, {1.0, 0.2}, {-2.0, 0.0}, mb, 0.15, m);
            const Vec2 p0 = momentum(w.particles);
            for (int i = 0; i < 60; ++i)
                w.step();
            const Vec2 p1 = momentum(w.particles);
            EXPECT_NEAR(p1.x, p0.x, 1e-14 * (1.5 * 5.0 + mb * 2.0)) << e << " " << mb;
            EXPECT_EQ(p1.y, 0.0);
            EXPECT_NEAR(w.particles.vx[b] - w.particles.vx[a], e * 7.0, 1e-12) << e << " " << mb;
        }
}

// A glancing impact: the impulse acts along the line of centres only (no friction),
// so the tangential velocities are untouched and kinetic energy is kept at e = 1.
TEST(HeadOn, GlancingElasticImpactKeepsEnergyAndTangentialVelocity) {
    World w(weightless(1.0 / 240.0));
    const MaterialId m = ballOf(w, 1.0);
    const auto a = addBall(w, {-1.0, 0.1}, {4.0, 0.0}, 1.0, 0.1, m);
    const auto b = addBall(w, {0.0, 0.0}, {0.0, 0.0}, 1.0, 0.1, m);
    const double ke0 = energy(w.particles, w.springs, w.def().forces).kinetic;
    for (int i = 0; i < 240; ++i)
        w.step();
    const double ke1 = energy(w.particles, w.springs, w.def().forces).kinetic;
    EXPECT_NEAR(ke1, ke0, 1e-12 * ke0);
    // Equal masses, e = 1: the velocities leave at right angles.
    EXPECT_NEAR(dot(w.particles.velocity(a), w.particles.velocity(b)), 0.0, 1e-12);
    // The line of centres at contact made 30 degrees with x (sin = 0.1 / 0.2).
    const Vec2 vb = w.particles.velocity(b);
    EXPECT_NEAR(std::atan2(vb.y, vb.x), -std::numbers::pi / 6.0, 1e-9);
}

// 1000 m/s into a 1 cm wall at dt = 1/60 s (16.7 m per step): with continuous
// detection the particle bounces off the wall's face at the time of impact; without
// it the overlap test at the step ends never sees the wall and the particle tunnels.
TEST(Tunnelling, ContinuousDetectionStopsAThousandMetresPerSecond) {
    for (const bool continuous : {true, false}) {
        WorldDef d = weightless(1.0 / 60.0);
        d.collision.continuous = continuous;
        World w(d);
        const MaterialId m = ballOf(w, 1.0);
        w.shapes.addBox({5.0, -1.0}, {5.01, 1.0}, material::kPerfectlyElastic);
        const auto id = addBall(w, {0.0, 0.0}, {1000.0, 0.0}, 1.0, 0.005, m);
        w.step(); // the wall face is 4.995 m away: hit at t = 4.995 ms
        if (continuous) {
            ASSERT_EQ(w.contacts().size(), 1u);
            EXPECT_NEAR(w.contacts()[0].time, 4.995e-3, 1e-12);
            EXPECT_NEAR(w.contacts()[0].position.x, 4.995, 1e-9);
            EXPECT_DOUBLE_EQ(w.particles.vx[id], -1000.0);
            EXPECT_NEAR(w.particles.px[id], 4.995 - 1000.0 * (1.0 / 60.0 - 4.995e-3), 1e-9);
        } else {
            EXPECT_TRUE(w.contacts().empty());
            EXPECT_DOUBLE_EQ(w.particles.vx[id], 1000.0);
            EXPECT_NEAR(w.particles.px[id], 1000.0 / 60.0, 1e-9); // 16.67 m: through the wall
        }
    }
}

// The same through a zero-thickness segment, at an angle, and between two particles
// passing each other at 1000 m/s each.
TEST(Tunnelling, SegmentAndParticlesAreNotTunnelledEither) {
    World w(weightless(1.0 / 60.0));
    const MaterialId m = ballOf(w, 1.0);
    w.shapes.addSegment({5.0, -10.0}, {5.0, 10.0}, material::kPerfectlyElastic);
    const auto s = addBall(w, {0.0, 0.0}, {800.0, 600.0}, 1.0, 0.01, m);
    const auto a = addBall(w, {-10.0, -5.0}, {1000.0, 0.0}, 1.0, 0.01, m);
    const auto b = addBall(w, {10.0, -5.0}, {-1000.0, 0.0}, 1.0, 0.01, m);
    w.step();
    EXPECT_NEAR(w.particles.vx[s], -800.0, 1e-9);
    EXPECT_NEAR(w.particles.vy[s], 600.0, 1e-9);
    EXPECT_LT(w.particles.px[s], 5.0);
    EXPECT_DOUBLE_EQ(w.particles.vx[a], -1000.0);
    EXPECT_DOUBLE_EQ(w.particles.vx[b], 1000.0);
    EXPECT_LT(w.particles.px[a], w.particles.px[b]);
}

// Static shapes: the normal at the contact decides the rebound. A ball dropped on the
// top of a circle, a polygon's face and a polygon's corner.
TEST(Shapes, ReboundFollowsTheSurfaceNormal) {
    WorldDef d = weightless(1.0 / 120.0);
    World w(d);
    const MaterialId m = ballOf(w, 1.0);
    ASSERT_EQ(w.shapes.addCircle({0.0, 0.0}, 1.0, material::kPerfectlyElastic), "");
    const Vec2 square[] = {{10.0, 0.0}, {12.0, 0.0}, {12.0, 1.0}, {10.0, 1.0}};
    ASSERT_EQ(w.shapes.addPolygon(square, material::kPerfectlyElastic), "");
    // Onto the circle at 45 degrees from above-right, aimed at its centre: straight back.
    const auto c = addBall(w, {2.0, 2.0}, {-1.0, -1.0}, 1.0, 0.1, m);
    // Onto the square's top face at an angle: vy flips, vx stays.
    const auto f = addBall(w, {10.5, 2.0}, {1.0, -2.0}, 1.0, 0.1, m);
    for (int i = 0; i < 360; ++i)
        w.step(); // the circle is hit at t = (2 sqrt 2 - 1.1) / sqrt 2
    EXPECT_NEAR(w.particles.vx[c], 1.0, 1e-12);
    EXPECT_NEAR(w.particles.vy[c], 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(w.particles.vx[f], 1.0);
    EXPECT_DOUBLE_EQ(w.particles.vy[f], 2.0);
    EXPECT_EQ(w.shapes.addPolygon(std::vector<Vec2>{{0, 0}, {1, 0}, {0.2, 0.2}, {0, 1}}),
              "polygon is not convex (vertex 2)");
}

TEST(Shapes, ClosestPointDistancesAreExact) {
    const Segment s{{0.0, 0.0}, {2.0, 0.0}};
    EXPECT_DOUBLE_EQ(closestPoint(s, {1.0, 3.0}).distance, 3.0);
    EXPECT_DOUBLE_EQ(closestPoint(s, {5.0, 4.0}).distance, 5.0);
    const Circle c{{1.0, 1.0}, 0.5};
    EXPECT_DOUBLE_EQ(closestPoint(c, {4.0, 5.0}).distance, 4.5);
    StaticShapes shapes;
    shapes.addBox({0.0, 0.0}, {2.0, 1.0});
    const auto inside = closestPoint(shapes.polygons[0], {1.0, 0.8});
    EXPECT_NEAR(inside.distance, -0.2, 1e-15);
    EXPECT_DOUBLE_EQ(inside.normal.y, 1.0);
    EXPECT_DOUBLE_EQ(closestPoint(shapes.polygons[0], {5.0, 5.0}).distance, 5.0);
    // The swept sphere (capsule) test: radius 0.5 around the segment, from (1, 3) down.
    EXPECT_DOUBLE_EQ(*sweptSphere(s, 0.5, {1.0, 3.0}, {1.0, -2.0}), 0.5);
    EXPECT_FALSE(sweptSphere(s, 0.5, {3.0, 3.0}, {3.0, -2.0}));
    // A point on the segment has no side; it gets the segment's left normal.
    const SurfacePoint on = closestPoint(s, {1.5, 0.0});
    EXPECT_EQ(on.distance, 0.0);
    EXPECT_EQ(on.normal.x, 0.0);
    EXPECT_EQ(on.normal.y, 1.0);
    EXPECT_EQ(closestPoint(s, {1.5, -0.25}).normal.y, -1.0);
}

// The time of impact's tolerances scale by max(1, |v|), taken without the square root
// when |v|^2 <= 1: the same bits as with it, just above and below 1 and far from it.
TEST(Shapes, AtLeastOneIsMaxOfOneAndTheLengthBitForBit) {
    std::vector<Vec2> vs{{0.0, 0.0},  {1.0, 0.0}, {0.0, -1.0},   {0.6, 0.8},
                         {-0.8, 0.6}, {3.0, 4.0}, {1e-300, 0.0}, {1e300, 1e300}};
    for (double x = 1.0 - 64 * 0x1p-53; x <= 1.0 + 64 * 0x1p-52; x = std::nextafter(x, 2.0))
        vs.push_back({x, 0.0}), vs.push_back({x * 0.6, x * 0.8});
    for (int k = 0; k < 2000; ++k) {
        const double angle = 0.001 * 3.1 * k, r = 0.5 + 0.0005 * k; // lengths 0.5 to 1.5
        vs.push_back({r * std::cos(angle), r * std::sin(angle)});
    }
    for (const Vec2 v : vs) {
        const double expected = std::max(1.0, length(v));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(atLeastOne(v)),
                  std::bit_cast<std::uint64_t>(expected))
            << v.x << ", " << v.y;
    }
}

// Coulomb friction on a flat floor: a particle sliding at v0 stops after
// v0^2 / (2 mu_d g), having decelerated at mu_d g throughout.
TEST(Friction, SlidingStopsAfterTheCoulombDistance) {
    WorldDef d;
    d.tickSeconds = 1.0 / 120.0;
    World w(d);
    const MaterialId m = *w.materials.add({"slider", 0.0, 0.5, 0.3});
    w.materials.setPair(m, material::kFloor, {0.0, 0.5, 0.3});
    w.shapes.addSegment({-10.0, 0.0}, {100.0, 0.0}, material::kFloor);
    const auto id = addBall(w, {0.0, 0.1}, {6.0, 0.0}, 1.0, 0.1, m);
    for (int i = 0; i < 600; ++i)
        w.step();
    EXPECT_DOUBLE_EQ(w.particles.vx[id], 0.0);
    EXPECT_NEAR(w.particles.px[id], 36.0 / (2.0 * 0.3 * 9.81), 1e-9);
    EXPECT_NEAR(w.particles.py[id], 0.1, 1e-12);
}

// Static friction holds a particle on a slope flatter than atan(mu_s); a steeper one
// slides, accelerating at g (sin - mu_d cos).
TEST(Friction, StaticFrictionHoldsOnAGentleSlopeOnly) {
    for (const double deg : {20.0, 40.0}) {
        WorldDef d;
        World w(d);
        const MaterialId m = *w.materials.add({"block", 0.0, 0.5, 0.3});
        w.materials.setPair(m, material::kFloor, {0.0, 0.5, 0.3});
        const double th = deg * std::numbers::pi / 180.0;
        const Vec2 dir{std::cos(th), -std::sin(th)}, n{std::sin(th), std::cos(th)};
        w.shapes.addSegment(dir * -50.0, dir * 50.0, material::kFloor);
        const auto id = addBall(w, n * 0.1, {}, 1.0, 0.1, m);
        for (int i = 0; i < 120; ++i)
            w.step();
        const Vec2 p = w.particles.position(id);
        if (deg < std::atan(0.5) * 180.0 / std::numbers::pi) {
            EXPECT_NEAR(length(p - n * 0.1), 0.0, 1e-12) << deg;
        } else {
            const double a = 9.81 * (std::sin(th) - 0.3 * std::cos(th));
            EXPECT_NEAR(dot(p, dir), 0.5 * a * 1.0, 1e-6) << deg; // s = a t^2 / 2 at t = 1 s
            EXPECT_NEAR(dot(p, n), 0.1, 1e-9) << deg;
        }
    }
}

// Resting contact: a ball dropped on the floor settles and then stays within 1e-6 m
// of where it settled for 10 simulated minutes: no jitter, no creep. It falls asleep,
// and a blast wakes it.
TEST(Resting, StaysPutForTenMinutesThenWakesOnABlast) {
    for (const bool sleep : {true, false})
        for (const Integrator method :
             {Integrator::VelocityVerlet, Integrator::RK4, Integrator::SymplecticEuler}) {
            SCOPED_TRACE(sleep ? "sleep on" : "sleep off (the contact alone holds it)");
            WorldDef d;
            d.integrator = method;
            d.collision.sleep = sleep;
            World w(d);
            w.shapes.addSegment({-10.0, 0.0}, {10.0, 0.0}, material::kFloor);
            const Vec2 slope[] = {{-10.0, 0.0}, {-10.0, 5.0}, {-20.0, 0.0}};
            w.shapes.addPolyline(slope, material::kFloor);
            ParticleDef pd;
            pd.position = {0.5, 1.0};
            pd.velocity = {0.3, 0.0};
            pd.radius = 0.05;
            pd.material = material::kTennis;
            const auto id = w.particles.add(pd);
            for (int i = 0; i < 120 * 20; ++i)
                w.step(); // 20 s to settle
            const Vec2 settled = w.particles.position(id);
            EXPECT_NEAR(settled.y, 0.05, 1e-8) << info(method).name;
            double worst = 0.0;
            for (int i = 0; i < 120 * 600; ++i) {
                w.step();
                worst = std::max(worst, length(w.particles.position(id) - settled));
            }
            EXPECT_LE(worst, 1e-6) << info(method).name;
            EXPECT_EQ((w.particles.flags[id] & kSleeping) != 0, sleep) << info(method).name;
            applyBlast(w.particles, {{settled.x - 1.0, 0.0}, 1.0, 2.0});
            EXPECT_FALSE(w.particles.flags[id] & kSleeping);
            w.step();
            EXPECT_GT(length(w.particles.position(id) - settled), 1e-3);
        }
}

// A stack of resting particles on the floor stays put too (particle-particle resting).
TEST(Resting, ABallOnABallSettles) {
    World w;
    w.shapes.addSegment({-10.0, 0.0}, {10.0, 0.0}, material::kFloor);
    ParticleDef pd;
    pd.radius = 0.1;
    pd.material = material::kPerfectlyPlastic;
    pd.position = {0.0, 0.1};
    const auto low = w.particles.add(pd);
    pd.position = {0.0, 0.35};
    const auto high = w.particles.add(pd);
    for (int i = 0; i < 120 * 5; ++i)
        w.step();
    const Vec2 settled = w.particles.position(high);
    EXPECT_NEAR(settled.y, 0.3, 1e-6);
    EXPECT_NEAR(settled.x, 0.0, 1e-12);
    for (int i = 0; i < 120 * 60; ++i)
        w.step();
    EXPECT_LE(length(w.particles.position(high) - settled), 1e-6);
    EXPECT_NEAR(w.particles.py[low], 0.1, 1e-9);
}

// Penalty contacts (gradual response): a ball resting on the floor sinks to where the
// spring carries its weight, m w^2 d = m g, d = g / w^2; and a spring too stiff for
// the step (w dt > 2) is unstable: the ball gains energy and is flung away.
TEST(Penalty, SinksByGOverOmegaSquaredAndBlowsUpWhenStiff) {
    WorldDef d;
    d.collision.model = ContactModel::Penalty;
    d.collision.penaltyHertz = 10.0;
    World w(d);
    w.shapes.addSegment({-10.0, 0.0}, {10.0, 0.0}, material::kFloor);
    ParticleDef pd;
    pd.position = {0.0, 0.5};
    pd.radius = 0.05;
    pd.material = material::kTennis;
    const auto id = w.particles.add(pd);
    for (int i = 0; i < 120 * 20; ++i)
        w.step();
    // The continuous spring would rest at d = g / w^2. The explicit step (integrate, then
    // the impulse F h) has its fixed point where the step's own fall, v h - g h^2/2, is
    // zero, v = g h / 2, and there the damper adds zeta w g h: d = g (1 - zeta w h) / w^2.
    const double omega = 2.0 * std::numbers::pi * 10.0, h = 1.0 / 120.0;
    const double lnE = std::log(0.712);
    const double zeta = -lnE / std::sqrt(std::numbers::pi * std::numbers::pi + lnE * lnE);
    const double depth = 9.81 * (1.0 - zeta * omega * h) / (omega * omega);
    EXPECT_NEAR(0.05 - w.particles.py[id], depth, 1e-9);
    EXPECT_GT(depth, 2e-3); // millimetres inside the floor: the model's interpenetration

    d.collision.penaltyHertz = 60.0; // w dt = 2 pi 60 / 120 = 3.1 > 2
    World stiff(d);
    stiff.shapes.addSegment({-10.0, 0.0}, {10.0, 0.0}, material::kFloor);
    const auto s = stiff.particles.add(pd);
    double top = 0.0;
    for (int i = 0; i < 120 * 5; ++i) {
        stiff.step();
        top = std::max(top, stiff.particles.py[s]);
    }
    EXPECT_GT(top, 1.0); // rose above twice its drop height: energy came from nowhere
}

// Bad settings are refused by validate() with what to change.
TEST(CollisionDef, ValidateSaysWhatIsWrong) {
    WorldDef d;
    EXPECT_EQ(validate(d), "");
    d.collision.bisectionHalvings = -1;
    EXPECT_EQ(validate(d), "collision bisection halvings must be in 0..60");
    d = {};
    d.collision.penaltyHertz = 0.0;
    EXPECT_EQ(validate(d), "penalty stiffness must be > 0 Hz");
    d = {};
    d.collision.gridCellSize = -1.0;
    EXPECT_EQ(validate(d), "grid cell size must be >= 0 m (0: automatic)");
    EXPECT_STREQ(contactModelName(ContactModel::Penalty), "penalty");
    EXPECT_STREQ(broadPhaseName(BroadPhase::Grid), "grid");
}

// A sleeper whose support is removed (a crater) falls once the world is woken.
TEST(Resting, WakeAllAfterTheTerrainChanges) {
    World w;
    w.shapes.addSegment({-1.0, 0.0}, {1.0, 0.0}, material::kFloor);
    ParticleDef pd;
    pd.position = {0.0, 0.1};
    const auto id = w.particles.add(pd);
    for (int i = 0; i < 120; ++i) w.step();
    ASSERT_TRUE(w.particles.flags[id] & kSleeping);
    w.shapes.clear();
    w.step();
    EXPECT_EQ(w.particles.py[id], 0.1); // asleep: it does not notice
    w.wakeAll();
    for (int i = 0; i < 12; ++i) w.step(); // 0.1 s of free fall: 4.905 cm
    EXPECT_NEAR(w.particles.py[id], 0.1 - 0.5 * 9.81 * 0.01, 1e-12);
}
