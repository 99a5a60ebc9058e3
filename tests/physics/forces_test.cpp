// Force generators against their closed forms: terminal velocity, exponential decay,
// wind, Hooke's law, Archimedes, Kepler, the blast falloff, plastic flow and breaking.
#include "physics/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace phys;

namespace {
World makeWorld(ForceDef f, Integrator m = Integrator::RK4, double dt = 1.0 / 120.0) {
    WorldDef d;
    d.forces = f;
    d.integrator = m;
    d.tickSeconds = dt;
    return World(d);
}
void run(World& w, double seconds) {
    const long n = std::lround(seconds / w.def().tickSeconds);
    for (long i = 0; i < n; ++i) w.step();
}
} // namespace

TEST(Gravity, PresetsMatchTheIssue) {
    EXPECT_EQ(gravityFromPlanet("earth"), 9.81);
    EXPECT_EQ(gravityFromPlanet("moon"), 1.62);
    EXPECT_EQ(gravityFromPlanet("mars"), 3.71);
    EXPECT_EQ(gravityFromPlanet("jupiter"), 24.79);
    EXPECT_FALSE(gravityFromPlanet("pluto").has_value());
}

TEST(Drag, QuadraticReachesTerminalVelocity) {
    // v_t = sqrt(2 m g / (rho Cd A)).
    ForceDef f;
    f.drag = DragModel::Quadratic;
    World w = makeWorld(f);
    ParticleDef pd;
    pd.mass = 0.0459; // golf ball
    pd.radius = 0.02135;
    pd.dragCoefficient = 0.25;
    const auto id = w.particles.add(pd);
    run(w, 60.0); // 13 time constants v_t / g
    const double area = std::numbers::pi * pd.radius * pd.radius;
    const double vt = std::sqrt(2 * pd.mass * 9.81 / (1.225 * pd.dragCoefficient * area));
    EXPECT_NEAR(-w.particles.vy[id], vt, 1e-6 * vt);
}

TEST(Drag, LinearDecaysExponentially) {
    // m v' = -b v (no gravity): v(t) = v0 e^{-b t / m}.
    ForceDef f;
    f.gravity = {0, 0};
    f.drag = DragModel::Linear;
    f.linearDrag = 0.5;
    World w = makeWorld(f);
    ParticleDef pd;
    pd.mass = 2.0;
    pd.velocity = {10.0, 0.0};
    const auto id = w.particles.add(pd);
    run(w, 3.0);
    EXPECT_NEAR(w.particles.vx[id], 10.0 * std::exp(-0.5 * 3.0 / 2.0), 1e-9);
    EXPECT_NEAR(w.particles.px[id], 10.0 * 2.0 / 0.5 * (1 - std::exp(-0.75)), 1e-9);
}

TEST(Drag, WindCarriesAParticleAtItsOwnSpeed) {
    // Linear drag on u = v - wind with no gravity: u(t) = u0 e^{-b t / m}, so a particle
    // at rest ends up moving with the air.
    ForceDef f;
    f.gravity = {0, 0};
    f.drag = DragModel::Linear;
    f.linearDrag = 0.1;
    f.wind = {7.0, -2.0};
    World w = makeWorld(f);
    ParticleDef pd;
    pd.mass = 0.05;
    const auto id = w.particles.add(pd);
    run(w, 1.0);
    const double decay = std::exp(-0.1 * 1.0 / 0.05);
    EXPECT_NEAR(w.particles.vx[id], 7.0 * (1 - decay), 1e-8); // RK4 at dt = 1/120 s
    EXPECT_NEAR(w.particles.vy[id], -2.0 * (1 - decay), 1e-8);
    // kNoDrag particles ignore the wind.
    pd.flags = kNoDrag;
    World w2 = makeWorld(f);
    const auto id2 = w2.particles.add(pd);
    run(w2, 1.0);
    EXPECT_EQ(w2.particles.velocity(id2), (Vec2{0, 0}));
}

TEST(Drag, QuadraticRelativeSpeedDecaysAsOneOverT) {
    // m u' = -k |u| u along a fixed direction: u(t) = u0 / (1 + k |u0| t / m).
    ForceDef f;
    f.gravity = {0, 0};
    f.drag = DragModel::Quadratic;
    f.wind = {-6.0, 8.0}; // |wind| = 10
    World w = makeWorld(f);
    ParticleDef pd;
    pd.mass = 0.01;
    pd.radius = 0.05;
    const auto id = w.particles.add(pd);
    run(w, 2.0);
    const double k = 0.5 * 1.225 * 0.47 * std::numbers::pi * 0.05 * 0.05;
    const double u = 10.0 / (1.0 + k * 10.0 * 2.0 / 0.01); // remaining relative speed
    EXPECT_NEAR(length(w.particles.velocity(id) - f.wind), u, 1e-8);
}

TEST(Springs, HookeForceAndDampingAlongTheSpring) {
    ParticleSet set;
    ParticleDef pd;
    pd.position = {0, 0};
    const auto a = set.add(pd);
    pd.position = {3, 4}; // distance 5
    pd.velocity = {0.6, 0.8}; // moving apart at 1 m/s along the spring
    const auto b = set.add(pd);
    std::vector<Spring> springs(1);
    springs[0].a = a;
    springs[0].b = b;
    springs[0].restLength = 4.0;
    springs[0].stiffness = 10.0;
    springs[0].damping = 2.0;
    ForceDef f;
    Dynamics dyn(f, springs, set);
    std::vector<double> fx(2), fy(2);
    dyn.nonGravityForces(set.px.data(), set.py.data(), set.vx.data(), set.vy.data(), fx.data(),
                         fy.data());
    // |F| = k (L - L0) + c v_rel = 10 * 1 + 2 * 1 = 12, pulling a toward b.
    EXPECT_NEAR(fx[a], 12.0 * 0.6, 1e-12);
    EXPECT_NEAR(fy[a], 12.0 * 0.8, 1e-12);
    EXPECT_NEAR(fx[b], -fx[a], 1e-12);
    EXPECT_NEAR(fy[b], -fy[a], 1e-12);
}

TEST(Springs, HangingMassSettlesAtMgOverK) {
    ForceDef f;
    World w = makeWorld(f);
    ParticleDef pd;
    pd.mass = 2.0;
    const auto id = w.particles.add(pd);
    Spring s;
    s.a = id;
    s.anchor = {0, 1};
    s.restLength = 1.0;
    s.stiffness = 200.0;
    s.damping = 20.0;
    w.springs.push_back(s);
    run(w, 20.0);
    EXPECT_NEAR(w.particles.py[id], -2.0 * 9.81 / 200.0, 1e-9);
}

TEST(Springs, PlasticFlowAndBreaking) {
    ParticleSet set;
    ParticleDef pd;
    const auto a = set.add(pd);
    std::vector<Spring> springs(2);
    springs[0].a = a;
    springs[0].anchor = {1.3, 0}; // strain 0.3
    springs[0].restLength = 1.0;
    springs[0].yieldStrain = 0.1;
    springs[0].plasticRate = 1e9; // flow fully in one step
    springs[1] = springs[0];
    springs[1].yieldStrain = INFINITY;
    springs[1].breakStrain = 0.25;
    EXPECT_EQ(updateSprings(springs, set, 0.01), 1);
    // Rest length flows to where the strain equals the yield strain: 1.3 / 1.1.
    EXPECT_NEAR(springs[0].restLength, 1.3 / 1.1, 1e-12);
    EXPECT_FALSE(springs[0].broken);
    EXPECT_TRUE(springs[1].broken);
}

TEST(Buoyancy, ArchimedesLiftOnTheSubmergedCap) {
    // Lift = rho_w V_submerged g: the whole sphere below the surface, half of it with
    // the centre at the surface, nothing above.
    ForceDef f;
    f.water = true;
    f.waterLevel = 0.0;
    ParticleSet set;
    ParticleDef pd;
    pd.radius = 0.1;
    for (double y : {-1.0, 0.0, 1.0}) {
        pd.position = {0, y};
        set.add(pd);
    }
    std::vector<Spring> none;
    Dynamics dyn(f, none, set);
    std::vector<double> fx(3), fy(3);
    dyn.nonGravityForces(set.px.data(), set.py.data(), set.vx.data(), set.vy.data(), fx.data(),
                         fy.data());
    const double volume = 4.0 / 3.0 * std::numbers::pi * 0.001;
    EXPECT_NEAR(fy[0], kWaterDensity * volume * 9.81, 1e-9);
    EXPECT_NEAR(fy[1], kWaterDensity * volume * 9.81 / 2, 1e-9);
    EXPECT_EQ(fy[2], 0.0);
}

TEST(Buoyancy, LightBallsFloatAndHeavyBallsSink) {
    ForceDef f;
    f.water = true;
    f.waterLevel = 0.0;
    World w = makeWorld(f);
    ParticleDef pd;
    pd.radius = 0.1;
    const double volume = 4.0 / 3.0 * std::numbers::pi * 0.001;
    pd.position = {0, -2};
    pd.mass = 0.5 * kWaterDensity * volume; // wood-like: floats with its centre at the surface
    const auto cork = w.particles.add(pd);
    pd.mass = 7.8 * kWaterDensity * volume; // steel
    pd.position = {1, -2};
    const auto steel = w.particles.add(pd);
    run(w, 60.0);
    EXPECT_NEAR(w.particles.py[cork], 0.0, 0.02) << "bobbing about the surface";
    EXPECT_LT(w.particles.py[steel], -50.0) << "sinking at its terminal speed in water";
}

TEST(PointGravity, CircularOrbitKeepsRadiusAndPeriod) {
    // A light satellite around a heavy fixed mass: v = sqrt(G M / r), T = 2 pi r / v.
    ForceDef f;
    f.gravity = {0, 0};
    f.pointGravity = true;
    f.gravitationalConstant = 1.0;
    f.pointGravitySoftening = 0.0;
    const double v = std::sqrt(1e12 / 1000.0);
    const double period = 2 * std::numbers::pi * 1000.0 / v;
    World w = makeWorld(f, Integrator::RK4, period / 400); // a whole number of steps
    // The sun is 1e12 times heavier than the planet, so it barely moves (~1e-9 m).
    ParticleDef sun;
    sun.flags = kAttractor;
    sun.mass = 1e12;
    const auto s = w.particles.add(sun);
    ParticleDef planet;
    planet.mass = 1.0;
    planet.flags = kAttractor;
    planet.position = {1000.0, 0.0};
    planet.velocity = {0.0, v};
    const auto p = w.particles.add(planet);
    run(w, period);
    EXPECT_NEAR(w.particles.px[p], 1000.0, 1e-3);
    EXPECT_NEAR(w.particles.py[p], 0.0, 0.1);
    EXPECT_LT(length(w.particles.position(s)), 1e-6);
}

TEST(Blast, ImpulseFallsOffLinearlyWithDistance) {
    ParticleSet set;
    ParticleDef pd;
    pd.mass = 2.0;
    pd.position = {1, 0};
    const auto near = set.add(pd);
    pd.position = {0, 3};
    const auto mid = set.add(pd);
    pd.position = {5, 0};
    const auto far = set.add(pd);
    pd.mass = 0.0; // fixed: never pushed
    pd.position = {0, 1};
    const auto fixed = set.add(pd);
    EXPECT_EQ(applyBlast(set, {{0, 0}, 10.0, 4.0}), 2);
    EXPECT_NEAR(set.vx[near], 10.0 * (1 - 1.0 / 4) / 2.0, 1e-12);
    EXPECT_NEAR(set.vy[mid], 10.0 * (1 - 3.0 / 4) / 2.0, 1e-12);
    EXPECT_EQ(set.velocity(far), (Vec2{0, 0}));
    EXPECT_EQ(set.velocity(fixed), (Vec2{0, 0}));
}
