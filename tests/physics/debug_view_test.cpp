// What the debug view draws, computed by physics/diagnostics.h against exact answers:
// net forces against the force laws, the closed-form ghosts against ballisticState and
// explicit Euler's known error, the grid cells of a known arrangement, contact normals
// of balls resting on the ground (particle and Box2D), and the model of each particle.
#include "physics/diagnostics.h"
#include "physics/rigid/rigid_world.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

namespace phys {
namespace {

constexpr double kTick = 1.0 / 120.0;

ParticleId addBall(World& w, Vec2 at, Vec2 v = {}, double mass = 1.0, double radius = 0.1) {
    ParticleDef pd;
    pd.position = at;
    pd.velocity = v;
    pd.mass = mass;
    pd.radius = radius;
    return w.particles.add(pd);
}

// ---- net forces ------------------------------------------------------------------------

TEST(NetForces, AParticleAtRestUnderGravityFeelsItsWeight) {
    WorldDef def;
    def.forces.drag = DragModel::Quadratic; // no air speed, no drag
    World w(def);
    const ParticleId p = addBall(w, {0.0, 5.0}, {}, 2.5);
    std::vector<Vec2> f;
    netForces(w, f);
    ASSERT_EQ(f.size(), w.particles.slots());
    EXPECT_EQ(f[p], (Vec2{0.0, -2.5 * 9.81}));
}

TEST(NetForces, AddDragInTheWindAndSprings) {
    WorldDef def;
    def.forces.drag = DragModel::Quadratic;
    def.forces.wind = {10.0, 0.0};
    World w(def);
    const double m = 0.5, r = 0.2, cd = 0.47;
    const ParticleId p = addBall(w, {0.0, 3.0}, {}, m, r);
    // A spring to an anchor 1 m above, rest length 0.5 m: stretched by 0.5 m, pulling up.
    Spring s;
    s.a = p;
    s.anchor = {0.0, 4.0};
    s.restLength = 0.5;
    s.stiffness = 40.0;
    w.springs.push_back(s);
    const ParticleId fixed = addBall(w, {5.0, 5.0}, {}, 0.0);
    std::vector<Vec2> f;
    netForces(w, f);
    // Still air moving at +10 m/s past a particle at rest: u = v - w = (-10, 0),
    // F = -1/2 rho Cd pi r^2 |u| u = +1/2 rho Cd pi r^2 100 along +x.
    const double drag = 0.5 * kAirDensitySeaLevel * cd * std::numbers::pi * r * r * 100.0;
    EXPECT_NEAR(f[p].x, drag, 1e-12);
    EXPECT_NEAR(f[p].y, -m * 9.81 + 40.0 * 0.5, 1e-12);
    EXPECT_EQ(f[fixed], Vec2{}) << "a fixed particle has no force to show";
}

// ---- closed-form ghosts ----------------------------------------------------------------

WorldDef integrateOnly(Integrator method) {
    WorldDef def;
    def.model = ModelPolicy::Integrate;
    def.integrator = method;
    def.tickSeconds = kTick;
    return def;
}

// Explicit Euler from (p, v) under constant g: after k steps p_k = p + v k h +
// g h^2 k (k - 1)/2, while the closed form gives p + v k h + g (k h)^2 / 2: it is behind
// by |g| h^2 k / 2, straight down, and its velocity is exact.
TEST(ClosedFormGhosts, SitOnTheParabolaAndShowExplicitEulersError) {
    World w(integrateOnly(Integrator::ExplicitEuler));
    const ParticleId shell = addBall(w, {0.0, 2.0}, {30.0, 40.0}, 4.0, 0.11);
    ClosedFormGhosts ghosts;
    w.step();
    ghosts.observe(w);
    const auto launch = ghosts.launch(shell);
    ASSERT_TRUE(launch) << "an integrated shell in flight is followed";
    EXPECT_EQ(launch->position, w.particles.position(shell)) << "from the first state it is seen in";
    EXPECT_EQ(launch->time, w.time());
    const int k = 150;
    for (int i = 0; i < k; ++i) {
        w.step();
        ghosts.observe(w);
    }
    ASSERT_TRUE(ghosts.launch(shell)) << "no contact, no jump: the same launch all along";
    EXPECT_EQ(ghosts.launch(shell)->time, launch->time);
    const auto ghost = ghosts.at(shell, w.time());
    ASSERT_TRUE(ghost);
    const BallisticState exact =
        ballisticState(launch->position, launch->velocity, {0.0, -9.81}, w.time() - launch->time);
    EXPECT_NEAR(ghost->position.x, exact.position.x, 1e-12);
    EXPECT_NEAR(ghost->position.y, exact.position.y, 1e-12);
    const double error = length(w.particles.position(shell) - ghost->position);
    EXPECT_NEAR(error, 9.81 * kTick * kTick * k / 2.0, 1e-9);
    EXPECT_NEAR(ghost->velocity.y, w.particles.velocity(shell).y, 1e-9) << "Euler's v is exact";
}

TEST(ClosedFormGhosts, VelocityVerletIsExactUnderGravity) {
    World w(integrateOnly(Integrator::VelocityVerlet));
    const ParticleId shell = addBall(w, {0.0, 2.0}, {30.0, 40.0});
    ClosedFormGhosts ghosts;
    for (int i = 0; i < 200; ++i) {
        w.step();
        ghosts.observe(w);
    }
    const auto ghost = ghosts.at(shell, w.time());
    ASSERT_TRUE(ghost);
    EXPECT_LT(length(w.particles.position(shell) - ghost->position), 1e-9);
}

// Under the model policy Auto a drag-free shell is on the closed form (no ghost: it is
// exact); switching drag on hands it to the integrator from its exact state, and the
// ghost goes on along the parabola it was launched on.
TEST(ClosedFormGhosts, AHandOverKeepsTheParabolaItWasOn) {
    WorldDef def;
    def.tickSeconds = kTick;
    World w(def);
    const ParticleId shell = addBall(w, {0.0, 2.0}, {30.0, 40.0}, 4.0, 0.11);
    ClosedFormGhosts ghosts;
    for (int i = 0; i < 60; ++i) {
        w.step();
        ghosts.observe(w);
        ASSERT_FALSE(ghosts.launch(shell)) << "on the closed form it has no ghost, tick " << i;
    }
    ASSERT_TRUE(w.particles.flags[shell] & kBallistic);
    def.forces.drag = DragModel::Quadratic;
    w.setDef(def);
    for (int i = 0; i < 120; ++i) {
        w.step();
        ghosts.observe(w);
    }
    const auto launch = ghosts.launch(shell);
    ASSERT_TRUE(launch);
    EXPECT_EQ(launch->time, 0.0) << "the parabola it was launched on at t = 0";
    EXPECT_EQ(launch->position, (Vec2{0.0, 2.0}));
    EXPECT_EQ(launch->velocity, (Vec2{30.0, 40.0}));
    // Drag slows it: the integrated shell is behind and below its vacuum ghost.
    const auto ghost = ghosts.at(shell, w.time());
    EXPECT_LT(w.particles.position(shell).x, ghost->position.x - 0.1);
}

TEST(ClosedFormGhosts, ABounceRelaunchesAndTetheredOrSleepingOnesHaveNone) {
    World w(integrateOnly(Integrator::VelocityVerlet));
    w.shapes.addSegment({-50.0, 0.0}, {50.0, 0.0});
    const ParticleId ball = addBall(w, {0.0, 1.0}, {1.0, 0.0});
    const ParticleId bob = addBall(w, {5.0, 3.0});
    Spring s;
    s.a = bob;
    s.anchor = {5.0, 4.0};
    w.springs.push_back(s);
    ClosedFormGhosts ghosts;
    bool bounced = false;
    for (int i = 0; i < 120 && !bounced; ++i) {
        w.step();
        ghosts.observe(w);
        for (const ContactEvent& e : w.contacts()) bounced |= e.a == ball;
        EXPECT_FALSE(ghosts.launch(bob)) << "a particle on a spring is not in free flight";
    }
    ASSERT_TRUE(bounced);
    const auto launch = ghosts.launch(ball);
    ASSERT_TRUE(launch);
    EXPECT_EQ(launch->time, w.time()) << "relaunched at the bounce";
    EXPECT_GT(launch->velocity.y, 0.0) << "going up again";
    // Resting, then asleep: no ghost.
    for (int i = 0; i < 600; ++i) {
        w.step();
        ghosts.observe(w);
    }
    ASSERT_TRUE(w.particles.flags[ball] & kSleeping);
    EXPECT_FALSE(ghosts.launch(ball));
}

// ---- grid cells ------------------------------------------------------------------------

TEST(OccupiedCells, AKnownArrangementCoversExactlyItsCells) {
    World w;
    CollisionDef def;
    def.gridCellSize = 1.0;
    addBall(w, {0.5, 0.5});           // [0.4, 0.6]^2: cell (0, 0)
    addBall(w, {1.95, 0.5});          // x in [1.85, 2.05]: cells (1, 0) and (2, 0)
    addBall(w, {-0.5, -0.5});         // cell (-1, -1)
    addBall(w, {0.3, 0.7});           // a second particle in cell (0, 0)
    addBall(w, {0.5, 0.5}, {}, 0.0);  // fixed particles are in the grid too (resting)
    const ParticleId ghost = addBall(w, {7.5, 7.5});
    w.particles.flags[ghost] |= kNoCollide; // never in the broad phase
    const ParticleId gone = addBall(w, {9.5, 9.5});
    w.particles.remove(gone);
    OccupiedCells cells;
    occupiedCells(w.particles, def, cells);
    EXPECT_EQ(cells.cellSize, 1.0);
    const std::vector<GridCell> expected{{-1, -1, 1}, {0, 0, 3}, {1, 0, 1}, {2, 0, 1}};
    EXPECT_EQ(cells.cells, expected);
}

TEST(OccupiedCells, TheAutomaticSizeIsTwiceTheMeanExtentOfTheMovingBoxes) {
    World w;
    CollisionDef def; // gridCellSize 0: the rule
    addBall(w, {0.0, 0.0}, {}, 1.0, 0.25);
    addBall(w, {3.0, 0.0}, {}, 1.0, 0.75);
    addBall(w, {9.0, 0.0}, {}, 0.0, 5.0); // fixed: not a moving box
    // (w + h) of a box of half-size r + tol is 4 (r + tol): mean over the two moving ones.
    const double expected = 4.0 * (0.5 + def.toiTolerance);
    EXPECT_NEAR(gridCellSize(w.particles, def), expected, 1e-15);
    World empty;
    EXPECT_EQ(gridCellSize(empty.particles, def), 1.0);
    // A box spanning more cells than the grid takes (64) is kept out of it: at 0.1 m
    // cells only the 0.5 m ball is in, over 6 x 6 cells (-3..2 on each axis).
    def.gridCellSize = 0.1;
    OccupiedCells cells;
    occupiedCells(w.particles, def, cells);
    ASSERT_EQ(cells.cells.size(), 36u);
    EXPECT_EQ(cells.cells.front(), (GridCell{-3, -3, 1}));
    EXPECT_EQ(cells.cells.back(), (GridCell{2, 2, 1}));
}

// ---- contacts --------------------------------------------------------------------------

TEST(ContactMarks, AParticleRestingOnFlatGroundHasAnUpwardNormal) {
    World w;
    w.shapes.addSegment({-10.0, 0.0}, {10.0, 0.0});
    const ParticleId ball = addBall(w, {0.0, 0.1 + 0.02});
    std::vector<ContactMark> marks;
    int seen = 0;
    for (int i = 0; i < 40; ++i) {
        w.step();
        contactMarks(w, nullptr, marks);
        for (const ContactMark& m : marks) {
            ASSERT_EQ(m.kind, ContactMark::Kind::Particle);
            EXPECT_NEAR(m.normal.x, 0.0, 1e-12);
            EXPECT_NEAR(m.normal.y, 1.0, 1e-12);
            EXPECT_NEAR(m.point.y, 0.0, 1e-6) << "on the ground, under the ball";
            EXPECT_NEAR(m.point.x, w.particles.px[ball], 1e-9);
            ++seen;
        }
    }
    EXPECT_GT(seen, 0);
}

TEST(ContactMarks, Box2DBodiesRestingOnFlatGroundHaveUpwardNormals) {
    World w;
    RigidWorld rigid;
    const std::array<Vec2, 2> ground{Vec2{-20.0, 0.0}, Vec2{20.0, 0.0}};
    ASSERT_TRUE(rigid.createTerrain(ground, {}).valid());
    BodyDef bd;
    bd.type = BodyType::Dynamic;
    bd.position = {0.0, 0.5};
    const BodyId ball = rigid.createCircle(bd, 0.5, {});
    bd.position = {3.0, 0.5};
    const BodyId box = rigid.createBox(bd, {0.5, 0.5}, {});
    for (int i = 0; i < 120; ++i) rigid.step(kTick);
    std::vector<RigidContactView> pairs;
    rigid.contacts(pairs);
    int ballPoints = 0, boxPoints = 0;
    for (const RigidContactView& c : pairs) {
        EXPECT_NEAR(c.normal.x, 0.0, 1e-5);
        EXPECT_NEAR(c.normal.y, 1.0, 1e-5) << "into the body, away from the static ground";
        EXPECT_NEAR(c.point.y, 0.0, 0.02) << "within Box2D's skin of the ground";
        ballPoints += c.b == ball ? 1 : 0;
        boxPoints += c.b == box ? 1 : 0;
    }
    EXPECT_EQ(ballPoints, 1);
    EXPECT_EQ(boxPoints, 2) << "a box on the ground touches at its two corners";
    // A particle sitting on the box touches it too (the coupling's contact).
    const ParticleId p = addBall(w, rigid.state(box).position + Vec2{0.0, 0.5 + 0.1 - 1e-3});
    std::vector<ContactMark> marks;
    contactMarks(w, &rigid, marks);
    int onBody = 0, bodies = 0;
    for (const ContactMark& m : marks) {
        EXPECT_NEAR(m.normal.y, 1.0, 1e-5);
        onBody += m.kind == ContactMark::Kind::ParticleBody ? 1 : 0;
        bodies += m.kind == ContactMark::Kind::Bodies ? 1 : 0;
    }
    EXPECT_EQ(onBody, 1);
    EXPECT_EQ(bodies, 3);
    (void)p;
}

// ---- models ----------------------------------------------------------------------------

TEST(ParticleModels, FollowTheOrderTheProfileCountsIn) {
    EXPECT_EQ(modelOf(kAlive | kSleeping | kBallistic, 0.0), ParticleModel::Fixed);
    EXPECT_EQ(modelOf(kAlive | kSleeping | kBallistic, 1.0), ParticleModel::Sleeping);
    EXPECT_EQ(modelOf(kAlive | kBallistic, 1.0), ParticleModel::ClosedForm);
    EXPECT_EQ(modelOf(kAlive, 1.0), ParticleModel::Integrated);
}

} // namespace
} // namespace phys
