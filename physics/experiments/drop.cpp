#include "physics/experiments/drop.h"

#include "physics/world.h"

#include <cmath>
#include <span>

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
    wd.model = ModelPolicy::Integrate; // the experiment is about the integrator
    wd.tickSeconds = def.dt;
    wd.integrator = def.integrator;
    wd.forces.gravity = {0.0, -def.gravity};
    wd.collision = def.collision;
    World world(wd);
    // A thick floor (a box, not a segment): a penalty contact lets the ball sink, and
    // the box keeps pushing it up where a two-sided segment would push it through.
    world.shapes.addBox({-1e3, -10.0}, {1e3, 0.0}, material::kFloor);
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
        b.relativeError =
            b.expected > 0.0 ? (b.apex - b.expected) / b.expected : b.apex - b.expected;
        out.bounces.push_back(b);
    };

    const bool penalty = def.collision.model == ContactModel::Penalty;
    bool rising = false; // between a bounce and its apex
    const long long maxSteps = std::llround(def.maxTime / def.dt);
    while (static_cast<int>(out.bounces.size()) < def.bounces && out.steps < maxSteps) {
        const double y0 = world.particles.py[ball], v0 = world.particles.vy[ball];
        world.step();
        ++out.steps;
        out.maxPenetration = std::max(out.maxPenetration, def.radius - world.particles.py[ball]);
        // The rising part of this tick starts at the start of the tick or at its last bounce.
        double ys = y0, vs = v0, ts = 0.0;
        if (penalty) {
            // A spring contact has no instant of impact: the ball rises once its velocity
            // turns upward, and rests once the spring holds it below the resting speed.
            if (!rising && v0 <= 0.0 && world.particles.vy[ball] > 0.0) {
                rising = true;
                ys = world.particles.py[ball];
                vs = world.particles.vy[ball];
                ts = def.dt;
            }
        }
        const auto events = penalty ? std::span<const ContactEvent>{}
                                    : std::span<const ContactEvent>(world.contacts());
        for (const ContactEvent& c : events) {
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
            // A spring contact always turns the velocity through zero, however softly
            // it lands: the ball is at rest once it no longer leaves the floor by more
            // than a resting-speed hop, v^2 / 2g.
            const double hop =
                def.collision.restingSpeed * def.collision.restingSpeed / (2.0 * def.gravity);
            if (penalty && out.bounces.back().apex < hop) out.cameToRest = true;
        }
    }
    // At rest on the floor: every later apex is the floor.
    if (out.cameToRest || (e == 0.0 && !out.bounces.empty()))
        while (static_cast<int>(out.bounces.size()) < def.bounces)
            record(def.radius);
    return out;
}

} // namespace phys
