// Nothing leaks out of a level: a particle is never pushed through a thin static shape (a
// segment has two sides, and a centre pushed across one is pushed out of the far side
// and falls for ever). Two pushes did it (found by the busy soak, bench/bench_soak):
// a crate landing on a ball that rests on the ground, and a pile whose passes ran out
// while a ball was driven through the floor.
#include "physics/coupling.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace phys;

namespace {

const std::vector<Vec2> kBox = {{0.0, 20.0}, {0.0, 0.0}, {20.0, 0.0}, {20.0, 20.0}};

// A crate of 32 kg dropped from 10, 20 and 40 m (up to 28 m/s, a quarter metre a tick)
// onto a 0.1 m ball on the floor, resting, moving into it, or just bounced off it (4 cm
// up), at the crate's middle or near its edge: the crate's push must not move the ball
// through the floor; the ground carries the crate through it. (Before, each of these
// cases dropped the ball out of the level.)
TEST(Leak, ACrateLandingOnABallDoesNotPushItThroughTheGround) {
    struct Case {
        double height, dx, y, vy;
    };
    const Case cases[] = {{10, 0.0, 0.10, -3}, {10, 0.0, 0.14, 0}, {20, 0.0, 0.10, -3},
                          {20, 0.0, 0.14, 0},  {40, 0.0, 0.14, 0}, {40, 0.35, 0.14, 0}};
    for (const Case& c : cases) {
        World world;
        RigidWorld rigid;
        ParticleBodyCoupling coupling;
        const std::vector<Vec2> box = {{0.0, 50.0}, {0.0, 0.0}, {20.0, 0.0}, {20.0, 50.0}};
        world.shapes.addPolyline(box, material::kFloor);
        coupling.mirror(rigid.createTerrain(box, RigidMaterial{0.0, 0.3, 0.0}));
        ParticleDef pd;
        pd.position = {10.0 + c.dx, c.y};
        pd.velocity = {0.0, c.vy};
        pd.radius = 0.1;
        pd.material = material::kPerfectlyElastic;
        const ParticleId ball = world.particles.add(pd);
        BodyDef bd;
        bd.position = {10.0, c.height};
        const BodyId crate = rigid.createBox(bd, {0.4, 0.4}, RigidMaterial{50.0, 0.4, 0.5});
        double lowest = 1e9;
        for (int t = 0; t < 480; ++t) {
            coupling.prepare(world, rigid);
            world.step();
            coupling.exchange(world, rigid);
            rigid.step(world.def().tickSeconds);
            lowest = std::min(lowest, world.particles.py[ball]);
        }
        EXPECT_GT(lowest, 0.0) << "from " << c.height << " m, ball at " << c.y
                               << " m: its centre went below the floor";
        EXPECT_GT(rigid.state(crate).centerOfMass.y, 0.0) << c.height;
    }
}

// Passes limited to one: a ball falling at 20 m/s hits a ball that rests on the floor,
// and the lower ball, driven down, would cross the floor later in the same step with no
// pass left to see it. The contact solver finds the floor from where the ball started
// the step and puts it back on its side.
TEST(Leak, ABallDrivenThroughTheFloorWhenThePassesRunOutIsPutBack) {
    WorldDef def;
    def.collision.maxPasses = 1;
    World world(def);
    world.shapes.addPolyline(kBox, material::kFloor);
    ParticleDef low;
    low.position = {10.0, 0.1};
    low.radius = 0.1;
    low.material = material::kPerfectlyElastic;
    const ParticleId lower = world.particles.add(low);
    ParticleDef high = low;
    high.position = {10.0, 0.35};
    high.velocity = {0.0, -20.0};
    world.particles.add(high);
    double lowest = 1e9;
    for (int t = 0; t < 120; ++t) {
        world.step();
        lowest = std::min(lowest, world.particles.py[lower]);
    }
    EXPECT_GT(lowest, 0.0) << "the lower ball's centre went below the floor";
}

} // namespace
