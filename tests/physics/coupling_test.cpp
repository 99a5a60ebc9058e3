// Particle <-> Box2D body coupling: momentum conserved across the exchange, kinetic
// energy never rises for e <= 1, and a bounce off a heavy block by the pair's restitution.
#include "physics/coupling.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace phys;

namespace {

struct Scene {
    World particles;
    RigidWorld rigid;
    ParticleBodyCoupling coupling;
    BodyId block;
    ParticleId ball;

    Scene(double blockDensity, double blockRestitution, MaterialId ballMaterial, Vec2 ballVelocity)
        : particles([] {
              WorldDef d;
              d.forces.gravity = {0, 0};
              return d;
          }()),
          rigid([] {
              RigidWorldDef d;
              d.gravity = {0, 0};
              return d;
          }()) {
        BodyDef bd;
        bd.position = {0.0, 0.0};
        block = rigid.createBox(bd, {0.5, 0.5}, RigidMaterial{blockDensity, 0.0, blockRestitution});
        ParticleDef pd;
        pd.position = {-2.0, 0.2};
        pd.velocity = ballVelocity;
        pd.mass = 2.0;
        pd.radius = 0.1;
        pd.material = ballMaterial;
        ball = particles.particles.add(pd);
    }
    Vec2 momentum() const {
        const auto s = rigid.state(block);
        return particles.particles.velocity(ball) * 2.0 + s.linearVelocity * s.mass;
    }
    double kinetic() const {
        const auto s = rigid.state(block);
        return 0.5 * 2.0 * lengthSquared(particles.particles.velocity(ball)) +
               0.5 * s.mass * lengthSquared(s.linearVelocity) +
               0.5 * s.inertia * s.angularVelocity * s.angularVelocity;
    }
    // One game tick: particles, exchange, bodies.
    int tick() {
        particles.step();
        const auto stats = coupling.exchange(particles, rigid);
        rigid.step(particles.def().tickSeconds);
        return stats.impulses;
    }
};

} // namespace

TEST(Coupling, MomentumIsConservedAcrossTheExchange) {
    for (MaterialId m : {material::kPerfectlyElastic, material::kGolf, material::kPerfectlyPlastic}) {
        Scene s(500.0, 1.0, m, {20.0, 0.0});
        const Vec2 p0 = s.momentum();
        int impulses = 0;
        for (int i = 0; i < 60; ++i) impulses += s.tick();
        ASSERT_GT(impulses, 0) << "the ball must reach the block";
        const Vec2 p1 = s.momentum();
        EXPECT_NEAR(p1.x, p0.x, 1e-9 * length(p0)) << "material " << m;
        EXPECT_NEAR(p1.y, p0.y, 1e-9 * length(p0)) << "material " << m;
    }
}

TEST(Coupling, KineticEnergyNeverRises) {
    for (MaterialId m : {material::kPerfectlyElastic, material::kTennis, material::kPerfectlyPlastic}) {
        Scene s(300.0, 1.0, m, {15.0, -1.0});
        double e = s.kinetic();
        for (int i = 0; i < 120; ++i) {
            s.tick();
            const double next = s.kinetic();
            // Box2D stores velocities as float: allow its rounding, nothing more.
            EXPECT_LE(next, e * (1.0 + 1e-6)) << "material " << m << " tick " << i;
            e = next;
        }
    }
}

TEST(Coupling, BounceOffAnImmovableBlockKeepsThePairsRestitution) {
    // A block a million times heavier than the ball: the ball comes back at e times its
    // speed, with e = e_ball * e_block (the materials' combine rule).
    Scene s(2e6, 1.0, material::kGolf, {10.0, 0.0});
    for (int i = 0; i < 60; ++i) s.tick();
    EXPECT_NEAR(s.particles.particles.vx[s.ball], -0.858 * 10.0, 1e-3);
}
