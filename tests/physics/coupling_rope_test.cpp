// Bodies on ropes and springs, and ropes holding bodies: the particle layer
// carries a Box2D body's weight. Checked against statics (where a crate must come to
// rest on an inextensible rope, how far springs compress under a load) and against the
// pendulum's period 2 pi sqrt(L/g), with momentum exact across the rod passes.
#include "physics/coupling.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace phys;

namespace {

constexpr double kG = 9.81;

struct Scene {
    World particles;
    RigidWorld rigid;
    ParticleBodyCoupling coupling;

    explicit Scene(double dt = 1.0 / 120.0)
        : particles([&] {
              WorldDef d;
              d.tickSeconds = dt;
              d.forces.gravity = {0, -kG};
              d.forces.airDensity = 0.0;
              return d;
          }()),
          rigid([] {
              RigidWorldDef d;
              d.gravity = {0, -kG};
              return d;
          }()) {}

    /// Particles from `from` to `to` joined by rods: the ends pinned when asked.
    std::vector<ParticleId> rope(Vec2 from, Vec2 to, int links, double linkLength, double linkMass,
                                 bool pinTo = true) {
        std::vector<ParticleId> ids;
        for (int i = 0; i <= links; ++i) {
            ParticleDef pd;
            pd.position = from + (to - from) * (static_cast<double>(i) / links);
            pd.mass = i == 0 || (i == links && pinTo) ? 0.0 : linkMass;
            pd.radius = 0.05;
            pd.material = material::kWooden;
            ids.push_back(particles.particles.add(pd));
            if (i > 0) {
                DistanceConstraint c;
                c.a = ids[i];
                c.b = ids[i - 1];
                c.length = linkLength;
                particles.constraints.push_back(c);
            }
        }
        return ids;
    }
    CouplingStats tick() {
        coupling.prepare(particles, rigid);
        particles.step();
        const CouplingStats s = coupling.exchange(particles, rigid);
        rigid.step(particles.def().tickSeconds);
        return s;
    }
    Vec2 particleMomentum() const {
        Vec2 p;
        const ParticleSet& s = particles.particles;
        for (std::size_t i = 0; i < s.slots(); ++i)
            if ((s.flags[i] & kAlive) && s.invMass[i] > 0.0)
                p += s.velocity(static_cast<ParticleId>(i)) * (1.0 / s.invMass[i]);
        return p;
    }
};

} // namespace

// A 40 kg crate dropped on a slack rope bridge rests where an inextensible rope must put
// it: the rope runs straight from each anchor to the crate's bottom corners and flat
// under it, so 2 sqrt((s/2 - w/2)^2 + d^2) + w = L fixes the depth d.
TEST(RopeCoupling, ABridgeOfRodsCarriesACrateAtTheDepthItsLengthAllows) {
    Scene s;
    const double span = 10.0, links = 40, slack = 0.04;
    const double ropeLength = span * (1.0 + slack);
    // Start the rope with its slack as a gentle sag so the rods are satisfied.
    const auto ids = s.rope({-5, 0}, {5, 0}, static_cast<int>(links), ropeLength / links, 0.25);
    for (std::size_t i = 1; i + 1 < ids.size(); ++i) {
        const double x = s.particles.particles.px[ids[i]];
        s.particles.particles.py[ids[i]] = -0.78 * (1.0 - (x * x) / 25.0);
    }
    for (int i = 0; i < 240; ++i) s.tick(); // let the rope settle on its own
    const double w = 1.0, h = 1.0;
    BodyDef bd;
    bd.position = {0.0, 1.0};
    const BodyId crate = s.rigid.createBox(bd, {w / 2, h / 2}, RigidMaterial{40.0, 0.6, 0.0});
    double yOneSecondAgo = 0.0;
    for (int i = 0; i < 6 * 120; ++i) {
        s.tick();
        if (i == 5 * 120) yOneSecondAgo = s.rigid.state(crate).position.y;
    }
    const RigidBodyState c = s.rigid.state(crate);
    const double depth = std::sqrt(std::pow((ropeLength - w) / 2.0, 2) - std::pow((span - w) / 2.0, 2));
    // The rope's centre line, the particles' radius, Box2D's 1 cm polygon skin, half the
    // height; the links (0.26 m) do not bend exactly at the crate's corners: 3 cm.
    const double expectedY = -depth + 0.05 + 0.01 + h / 2;
    EXPECT_NEAR(c.position.y, expectedY, 0.03) << "depth from the rope length " << depth;
    EXPECT_NEAR(c.position.y, yOneSecondAgo, 0.005) << "the crate must rest, not sink";
    EXPECT_LT(std::abs(c.linearVelocity.y), 0.02);
    EXPECT_LT(s.particles.constraintError(), 1e-4) << "the rods keep their length under load";
}

// Without the rod passes a crate would fall through: with them it rests at once.
TEST(RopeCoupling, RodPassesRunOnlyWhenALinkIsTouched) {
    Scene s;
    s.rope({-2, 0}, {2, 0}, 8, 0.5, 0.25);
    BodyDef bd;
    bd.position = {0.0, 3.0};
    s.rigid.createBox(bd, {0.3, 0.3}, RigidMaterial{40.0, 0.6, 0.0});
    int maxPasses = 0, firstTouch = -1;
    for (int i = 0; i < 120; ++i) {
        const CouplingStats st = s.tick();
        if (st.contacts == 0) {
            EXPECT_EQ(st.passes, 1);
        }
        if (st.contacts > 0 && firstTouch < 0) firstTouch = i;
        maxPasses = std::max(maxPasses, st.passes);
    }
    ASSERT_GE(firstTouch, 0) << "the crate must land on the rope";
    EXPECT_GT(maxPasses, 1);
}

// A 10 kg ball tied to a rope of rods swings with the period of the compound pendulum
// of its links and the ball (the rope hangs straight under the ball).
TEST(RopeCoupling, ARopeHoldsABallAsAPendulum) {
    Scene s(1.0 / 240.0);
    const double L = 2.0, theta0 = 5.0 * std::numbers::pi / 180.0;
    const Vec2 end{L * std::sin(theta0), -L * std::cos(theta0)};
    const double link = 0.1; // kg: a rope a tenth of the ball's mass
    const auto ids = s.rope({0, 0}, end, 10, L / 10, link, /*pinTo=*/false);
    BodyDef bd;
    bd.position = end;
    const BodyId ball = s.rigid.createCircle(bd, 0.12, RigidMaterial{220.0, 0.3, 0.0});
    s.coupling.attach(ids.back(), ball, end, s.rigid);
    // Time the crossings of x = 0 (half periods) over about three periods.
    std::vector<double> crossings;
    double prevX = end.x, t = 0.0;
    const double dt = s.particles.def().tickSeconds;
    for (int i = 0; i < static_cast<int>(9.0 / dt); ++i) {
        s.tick();
        t += dt;
        const double x = s.rigid.state(ball).position.x;
        if ((prevX > 0.0) != (x > 0.0)) crossings.push_back(t - dt * x / (x - prevX));
        prevX = x;
    }
    ASSERT_GE(crossings.size(), 5u);
    const double period = 2.0 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
    // A compound pendulum of the links (at r_i = i L / 10) and the ball (at L):
    // T = 2 pi sqrt(I / (g S)), I = sum m r^2, S = sum m r; times 1 + theta0^2/16.
    const double M = s.rigid.state(ball).mass;
    double I = M * L * L, S = M * L;
    for (int i = 1; i <= 10; ++i) {
        I += link * std::pow(i * L / 10, 2);
        S += link * i * L / 10;
    }
    const double expected = 2.0 * std::numbers::pi * std::sqrt(I / (kG * S)) * (1.0 + theta0 * theta0 / 16.0);
    EXPECT_NEAR(period / expected, 1.0, 0.01) << "period " << period << " s, expected " << expected;
    EXPECT_LT(s.particles.constraintError(), 1e-4);
}

TEST(RopeCoupling, AHangingCrateRestsWhereTheRopeEnds) {
    Scene s;
    const auto ids = s.rope({0, 0}, {0, -3}, 6, 0.5, 0.05, /*pinTo=*/false);
    BodyDef bd;
    bd.position = {0.0, -3.5};
    const BodyId crate = s.rigid.createBox(bd, {0.5, 0.5}, RigidMaterial{50.0, 0.6, 0.0});
    s.coupling.attach(ids.back(), crate, {0.0, -3.0}, s.rigid);
    for (int i = 0; i < 4 * 120; ++i) s.tick();
    const RigidBodyState c = s.rigid.state(crate);
    // Baumgarte leaves the anchor g dt^2 / beta = 3.4 mm low at 120 Hz.
    EXPECT_NEAR(c.position.y, -3.5, 0.01);
    EXPECT_NEAR(c.position.x, 0.0, 1e-6);
    EXPECT_LT(std::abs(c.linearVelocity.y), 0.01);
}

// The rope passes exchange impulses only between particles and the body (the anchors
// aside): with the rope pinned nowhere, the total momentum of rope and body changes by
// gravity's impulse alone, to rounding.
TEST(RopeCoupling, MomentumIsExactAcrossRodPasses) {
    Scene s;
    s.particles.setDef([&] {
        WorldDef d = s.particles.def();
        d.forces.gravity = {0, 0};
        return d;
    }());
    RigidWorld rigid([] {
        RigidWorldDef d;
        d.gravity = {0, 0};
        return d;
    }());
    std::vector<ParticleId> ids;
    for (int i = 0; i <= 6; ++i) {
        ParticleDef pd;
        pd.position = {-1.5 + 0.5 * i, 0.0};
        pd.mass = 0.3;
        pd.radius = 0.05;
        ids.push_back(s.particles.particles.add(pd));
        if (i > 0) s.particles.constraints.push_back({ConstraintKind::Rod, ids[i], ids[i - 1], {}, 0.5});
    }
    BodyDef bd;
    bd.position = {0.1, 0.6};
    bd.linearVelocity = {0.0, -3.0};
    const BodyId box = rigid.createBox(bd, {0.5, 0.5}, RigidMaterial{20.0, 0.5, 0.0});
    auto momentum = [&] {
        const RigidBodyState b = rigid.state(box);
        return s.particleMomentum() + b.linearVelocity * b.mass;
    };
    const Vec2 p0 = momentum();
    int linkedPasses = 0;
    for (int i = 0; i < 60; ++i) {
        s.particles.step();
        const CouplingStats st = s.coupling.exchange(s.particles, rigid);
        if (st.passes > 1) ++linkedPasses;
        rigid.step(s.particles.def().tickSeconds);
    }
    ASSERT_GT(linkedPasses, 0) << "the box must land on the rope";
    const Vec2 p1 = momentum();
    EXPECT_NEAR(p1.x, p0.x, 1e-9 * length(p0));
    EXPECT_NEAR(p1.y, p0.y, 1e-9 * length(p0));
}

// A crate on two spring-mounted particles sinks until the springs carry it:
// each spring shortens by (M g / 2 + m g) / k.
TEST(RopeCoupling, SpringsCarryACrateAtHookesCompression) {
    Scene s;
    const double k = 4000.0, m = 0.5, M = 20.0, L0 = 1.0;
    for (const double x : {-0.3, 0.3}) {
        ParticleDef pd;
        pd.position = {x, L0};
        pd.mass = m;
        pd.radius = 0.05;
        const ParticleId id = s.particles.particles.add(pd);
        Spring sp;
        sp.a = id;
        sp.anchor = {x, 0.0};
        sp.restLength = L0;
        sp.stiffness = k;
        sp.damping = 60.0; // c dt / m < 2 keeps the explicit damping stable
        s.particles.springs.push_back(sp);
        // Horizontal guy springs keep the compressed spring from buckling sideways; at
        // their rest length they add no vertical force (second order in the sag: 0.04 N).
        for (const double side : {-1.0, 1.0}) {
            sp.anchor = {x + side, L0};
            sp.damping = 20.0;
            sp.stiffness = 4000.0;
            s.particles.springs.push_back(sp);
        }
    }
    BodyDef bd;
    bd.position = {0.0, L0 + 0.05 + 0.25 + 0.02};
    const double area = 1.0 * 0.5;
    const BodyId crate = s.rigid.createBox(bd, {0.5, 0.25}, RigidMaterial{M / area, 0.8, 0.0});
    for (int i = 0; i < 5 * 120; ++i) s.tick();
    const double compression = (M * kG / 2.0 + m * kG) / k;
    for (const ParticleId id : {ParticleId{0}, ParticleId{1}})
        EXPECT_NEAR(L0 - s.particles.particles.py[id], compression, 0.03 * compression)
            << "Hooke: each spring carries half the crate and its particle";
    // Box2D keeps polygons a skin of 1 cm (b2_polygonRadius) from what they rest on.
    const double skin = 0.01;
    EXPECT_NEAR(s.rigid.state(crate).position.y, L0 - compression + 0.05 + skin + 0.25, 0.002);
    EXPECT_LT(std::abs(s.rigid.state(crate).linearVelocity.y), 1e-3);
}

// A joint on a pinned particle holds the body from a fixed point (nothing to lump).
TEST(RopeCoupling, ABodyTiedToAPinnedEndHangsFromIt) {
    Scene s;
    const auto ids = s.rope({-1, 0}, {0, 0}, 2, 0.5, 0.5, /*pinTo=*/true);
    BodyDef bd;
    bd.position = {0.0, -0.5};
    const BodyId crate = s.rigid.createBox(bd, {0.5, 0.5}, RigidMaterial{50.0, 0.6, 0.0});
    s.coupling.attach(ids.back(), crate, {0.0, 0.0}, s.rigid);
    for (int i = 0; i < 2 * 120; ++i) s.tick();
    const RigidBodyState c = s.rigid.state(crate);
    EXPECT_NEAR(c.position.y, -0.5, 0.01);
    EXPECT_TRUE(std::isfinite(c.position.x) && std::isfinite(s.particles.particles.px[ids[1]]));
}
