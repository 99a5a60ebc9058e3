#include "physics/rigid/rigid_drop.h"

#include "physics/rigid/rigid_world.h"

#include <box2d/b2_common.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace phys {

std::vector<double> rigidDropApexes(const RigidDropDef& def) {
    std::vector<double> apexes;
    if (!(def.height > 0.0) || def.bounces < 1 || !(def.tickSeconds > 0.0)) return apexes;

    RigidWorldDef wd;
    wd.gravity = {0.0, -def.gravity};
    wd.substeps = std::max(1, def.substeps);
    wd.restitutionThreshold = def.restitutionThreshold;
    wd.allowSleeping = false; // a ball at its apex must not be put to sleep
    RigidWorld world(wd);

    // Put the floor line below y = 0 by the depth at which Box2D leaves a resting body in
    // its skin, so a ball at rest has its bottom at y = 0 and heights read directly.
    const double skin = static_cast<double>(b2_polygonRadius) - static_cast<double>(b2_linearSlop);
    const std::array<Vec2, 2> floor{Vec2{-10.0, -skin}, Vec2{10.0, -skin}};
    RigidMaterial floorMaterial;
    floorMaterial.restitution = 0.0; // Box2D mixes by max: the ball's e alone decides
    floorMaterial.friction = 0.0;
    world.createTerrain(floor, floorMaterial);

    const double r = static_cast<double>(static_cast<float>(def.radius));
    BodyDef bd;
    bd.position = {0.0, r + def.height};
    bd.allowSleep = false;
    RigidMaterial ball;
    ball.restitution = def.restitution;
    ball.friction = 0.0;
    const BodyId id = world.createCircle(bd, r, ball);
    if (!id.valid()) return apexes;

    const auto maxTicks = static_cast<long>(def.maxSeconds / def.tickSeconds);
    bool rising = false;
    double top = 0.0;
    for (long t = 0; t < maxTicks && static_cast<int>(apexes.size()) < def.bounces; ++t) {
        world.step(def.tickSeconds);
        const RigidBodyState s = world.state(id);
        const double y = s.position.y - r;
        // A ball lying on the floor creeps up by the position correction with a velocity
        // of ~0; only a rebound faster than Box2D's own "at rest" speed is a bounce.
        if (!rising && s.linearVelocity.y > b2_linearSleepTolerance) {
            rising = true; // the floor has just turned the ball round
            top = y;
        }
        if (rising) {
            top = std::max(top, y);
            if (s.linearVelocity.y <= 0.0) {
                apexes.push_back(top);
                rising = false;
            }
        }
    }
    return apexes;
}

std::vector<double> rigidDropApexes(double height, double restitution, int bounces, double dt,
                                    int substeps) {
    RigidDropDef def;
    def.height = height;
    def.restitution = restitution;
    def.bounces = bounces;
    def.tickSeconds = dt;
    def.substeps = substeps;
    return rigidDropApexes(def);
}

} // namespace phys
