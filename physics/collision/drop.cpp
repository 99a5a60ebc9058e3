#include "physics/collision/drop.h"

#include "physics/world.h"

#include <cmath>

namespace phys {

namespace {

// Highest point of the vertical path y(t) = y + v t + a t^2 / 2 over [0, T] whose end
// y(T) = y1 fixes a. Only called when the path rises at its start.
double pathTop(double y, double v, double y1, double T) {
    if (!(T > 0.0)) return std::max(y, y1);
    const double a = 2.0 * (y1 - y - v * T) / (T * T);
    if (a < 0.0 && -v / a <= T) return y - v * v / (2.0 * a);
    return std::max(y, y1);
}

} // namespace

DropResult simulateDrop(const DropDef& def) {
    WorldDef wd;
    wd.tickSeconds = def.dt;
    wd.integrator = def.integrator;
    wd.forces.gravity = {0.0, -def.gravity};
    wd.collision = def.collision;
    World world(wd);
    world.shapes.addSegment({-1e3, 0.0}, {1e3, 0.0}, material::kFloor);
    if (def.restitution) {
        const PairProperties base = world.materials.pair(def.material, material::kFloor);
        world.materials.setPair(def.material, material::kFloor,
                                {*def.restitution, base.staticFriction, base.dynamicFriction});
    }
    DropResult out;
    const double e = world.materials.pair(def.material, material::kFloor).restitution;
    out.restitution = e;

    ParticleDef pd;
    pd.position = {0.0, def.height + def.radius};
    pd.mass = def.mass;
    pd.radius = def.radius;
    pd.material = def.material;
    const ParticleId ball = world.particles.add(pd);

    auto record = [&](double apexCentre) {
        const int k = static_cast<int>(out.bounces.size()) + 1;
        DropBounce b;
        b.apex = apexCentre - def.radius;
        b.expected = std::pow(e, 2 * k) * def.height;
        b.relativeError = b.expected > 0.0 ? (b.apex - b.expected) / b.expected : b.apex - b.expected;
        out.bounces.push_back(b);
    };

    bool rising = false; // between a bounce and its apex
    const long long maxSteps = std::llround(def.maxTime / def.dt);
    while (static_cast<int>(out.bounces.size()) < def.bounces && out.steps < maxSteps) {
        const double y0 = world.particles.py[ball], v0 = world.particles.vy[ball];
        world.step();
        ++out.steps;
        // The rising part of this tick starts at the start of the tick or at its last bounce.
        double ys = y0, vs = v0, ts = 0.0;
        for (const ContactEvent& c : world.contacts()) {
            if (c.a != ball) continue;
            if (c.resting) {
                out.cameToRest = true;
                rising = false;
                continue;
            }
            if (rising) record(std::max(ys, c.position.y)); // bounced again before the top
            ys = c.position.y, vs = c.velocity.y, ts = c.time;
            rising = vs > 0.0;
            if (!rising && static_cast<int>(out.bounces.size()) < def.bounces)
                record(c.position.y); // no rebound (e = 0): the apex is the floor
        }
        if (out.cameToRest) break;
        const double y1 = world.particles.py[ball], v1 = world.particles.vy[ball];
        if (rising && v1 <= 0.0) {
            record(pathTop(ys, vs, y1, def.dt - ts));
            rising = false;
        }
    }
    // At rest on the floor: every later apex is the floor.
    if (out.cameToRest || (e == 0.0 && !out.bounces.empty()))
        while (static_cast<int>(out.bounces.size()) < def.bounces) record(def.radius);
    return out;
}

} // namespace phys
