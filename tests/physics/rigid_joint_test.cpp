// Joints: each kind holds what it should, and a breakable joint breaks above its break
// force (or torque) and not below.
#include "physics/rigid/rigid_world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace phys {
namespace {

constexpr double kTick = 1.0 / 120.0;
constexpr double kG = 9.81;

struct Hanging {
    RigidWorld world;
    BodyId anchor;
    BodyId weight;
    double mass = 0.0;
};

// A weight hanging 1 m below a static anchor. At rest the joint carries exactly m g.
void hang(Hanging& h, double breakForce, Vec2 velocity = {}) {
    BodyDef fixed;
    fixed.type = BodyType::Static;
    fixed.position = {0.0, 5.0};
    h.anchor = h.world.createBody(fixed);
    BodyDef bd;
    bd.position = {0.0, 4.0};
    bd.linearVelocity = velocity;
    h.weight = h.world.createCircle(bd, 0.1, {});
    h.mass = h.world.state(h.weight).mass;
    DistanceJointDef rod;
    rod.a = h.anchor;
    rod.b = h.weight;
    rod.anchorA = {0.0, 5.0};
    rod.anchorB = {0.0, 4.0};
    rod.breakForce = breakForce * h.mass * kG;
    ASSERT_TRUE(h.world.createDistance(rod).valid());
}

TEST(RigidJoint, ReactionOfAHangingWeightIsItsWeight) {
    Hanging h;
    hang(h, std::numeric_limits<double>::infinity());
    h.world.step(kTick);
    const JointId j{0, 0};
    EXPECT_NEAR(h.world.jointReactionForce(j).y, h.mass * kG, 1e-4 * h.mass * kG);
}

TEST(RigidJoint, BreaksAboveItsBreakForceNotBelow) {
    Hanging holds;
    hang(holds, 1.1); // 10 % above the static load
    for (int t = 0; t < 2 * 120; ++t)
        holds.world.step(kTick);
    EXPECT_EQ(holds.world.brokenJoints(), 0);
    EXPECT_EQ(holds.world.jointCount(), 1);
    EXPECT_NEAR(holds.world.state(holds.weight).position.y, 4.0, 1e-3);

    Hanging breaks;
    hang(breaks, 0.9); // 10 % below it
    breaks.world.step(kTick);
    EXPECT_EQ(breaks.world.profile().jointsBroken, 1);
    EXPECT_EQ(breaks.world.jointCount(), 0);
    EXPECT_FALSE(breaks.world.alive(JointId{0, 0}));
    for (int t = 0; t < 60; ++t)
        breaks.world.step(kTick);
    EXPECT_LT(breaks.world.state(breaks.weight).position.y, 3.0) << "the weight falls";
    EXPECT_EQ(breaks.world.brokenJoints(), 1);
}

TEST(RigidJoint, SwingingLoadBreaksWhatStaticLoadDoesNot) {
    // At the bottom of a swing the rod carries m (g + v^2 / L). With v^2 / L = g the
    // tension is 2 m g: a 1.5 m g joint breaks, a 2.5 m g joint holds.
    const Vec2 v{std::sqrt(kG * 1.0), 0.0};
    Hanging weak;
    hang(weak, 1.5, v);
    // Box2D's rod sees the centripetal load from the second step on (the first step's
    // velocity is still tangent to the rod).
    for (int t = 0; t < 5; ++t)
        weak.world.step(kTick);
    EXPECT_EQ(weak.world.brokenJoints(), 1);
    Hanging strong;
    hang(strong, 2.5, v);
    for (int t = 0; t < 120; ++t)
        strong.world.step(kTick);
    EXPECT_EQ(strong.world.brokenJoints(), 0);
}

TEST(RigidJoint, WeldBreaksAboveItsBreakTorque) {
    // A 2 m beam welded at its end to a wall carries a torque m g L/2 at the weld.
    for (const double factor : {0.8, 1.2}) {
        RigidWorld world;
        BodyDef wall;
        wall.type = BodyType::Static;
        const BodyId w = world.createBox(wall, {0.1, 1.0}, {});
        BodyDef bd;
        bd.position = {1.1, 0.0};
        const BodyId beam = world.createBox(bd, {1.0, 0.05}, {});
        const double torque = world.state(beam).mass * kG * 1.0;
        WeldJointDef weld;
        weld.a = w;
        weld.b = beam;
        weld.anchor = {0.1, 0.0};
        weld.breakTorque = factor * torque;
        ASSERT_TRUE(world.createWeld(weld).valid());
        for (int t = 0; t < 120; ++t)
            world.step(kTick);
        EXPECT_EQ(world.brokenJoints(), factor < 1.0 ? 1 : 0) << "factor " << factor;
    }
}

TEST(RigidJoint, RevolutePendulumKeepsItsPivot) {
    RigidWorld world;
    BodyDef fixed;
    fixed.type = BodyType::Static;
    const BodyId pivot = world.createBody(fixed);
    BodyDef bd;
    bd.position = {1.0, 0.0};
    const BodyId bob = world.createBox(bd, {0.5, 0.05}, {}); // rod from 0.5 to 1.5 m
    RevoluteJointDef pin;
    pin.a = pivot;
    pin.b = bob;
    pin.anchor = {0.5, 0.0};
    ASSERT_TRUE(world.createRevolute(pin).valid());
    for (int t = 0; t < 240; ++t) {
        world.step(kTick);
        const RigidBodyState s = world.state(bob);
        // The pinned end stays at the pivot (to the solver's position tolerance).
        const Vec2 end = s.position - Vec2{std::cos(s.angle), std::sin(s.angle)} * 0.5;
        ASSERT_NEAR(end.x, 0.5, 5e-3) << "tick " << t;
        ASSERT_NEAR(end.y, 0.0, 5e-3) << "tick " << t;
    }
}

TEST(RigidJoint, PrismaticSlidesOnlyAlongItsAxis) {
    RigidWorld world;
    BodyDef fixed;
    fixed.type = BodyType::Static;
    const BodyId rail = world.createBody(fixed);
    const BodyId cart = world.createBox({}, {0.2, 0.1}, {});
    PrismaticJointDef slide;
    slide.a = rail;
    slide.b = cart;
    slide.axis = {1.0, 1.0}; // a 45 degree incline without friction
    slide.enableLimit = true;
    slide.lowerTranslation = -10.0;
    slide.upperTranslation = 10.0;
    ASSERT_TRUE(world.createPrismatic(slide).valid());
    for (int t = 0; t < 60; ++t)
        world.step(kTick);
    const RigidBodyState s = world.state(cart);
    EXPECT_NEAR(s.position.x, s.position.y, 1e-4) << "stays on the incline";
    EXPECT_NEAR(s.angle, 0.0, 1e-5);
    // Along the incline it accelerates at g sin 45 deg; symplectic Euler over 60 steps:
    // s = a h^2 n (n + 1) / 2.
    const double a = kG * std::sqrt(0.5);
    const double along = a * kTick * kTick * 60.0 * 61.0 / 2.0;
    EXPECT_NEAR(-s.position.x * std::sqrt(2.0), along, 2e-3 * along);
}

TEST(RigidJoint, BadDefinitionsSayWhatIsWrong) {
    RigidWorld world;
    const BodyId a = world.createCircle({}, 0.1, {});
    std::string error;
    RevoluteJointDef self;
    self.a = a;
    self.b = a;
    EXPECT_FALSE(world.createRevolute(self, &error).valid());
    EXPECT_NE(error.find("itself"), std::string::npos);
    RevoluteJointDef stale;
    stale.a = a;
    stale.b = BodyId{7, 0};
    EXPECT_FALSE(world.createRevolute(stale, &error).valid());
    EXPECT_NE(error.find("body b"), std::string::npos);
}

} // namespace
} // namespace phys
