#include "physics/experiments/drop.h"

#include "physics/world.h"

#include <algorithm>
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

// The world of the experiment: the floor, the pair's restitution, gravity, the integrator.
World dropWorld(const DropDef& def) {
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
    return world;
}

// The apexes of the ball, found tick by tick from where it was and what it touched.
class ApexFinder {
  public:
    ApexFinder(const DropDef& def, double e, DropResult& out) : def_(def), e_(e), out_(out) {}

    void record(double apexCentre) {
        const int k = static_cast<int>(out_.bounces.size()) + 1;
        DropBounce b;
        b.apex = apexCentre - def_.radius;
        b.expected = std::pow(e_, 2 * k) * def_.height;
        b.relativeError =
            b.expected > 0.0 ? (b.apex - b.expected) / b.expected : b.apex - b.expected;
        out_.bounces.push_back(b);
    }

    /// The tick that took the ball from height y0 at velocity v0 to where it is now.
    void tick(const World& world, ParticleId ball, double y0, double v0) {
        // The rising part of this tick starts at the start of the tick or at its last bounce.
        Rise rise{y0, v0, 0.0};
        if (penalty()) riseOnSpring(world, ball, v0, rise);
        else riseFromContacts(world, ball, rise);
        if (out_.cameToRest) return;
        const double y1 = world.particles.py[ball], v1 = world.particles.vy[ball];
        if (rising_ && v1 <= 0.0) {
            record(pathTop(rise.y, rise.v, y1, def_.dt - rise.t));
            rising_ = false;
            // A spring contact always turns the velocity through zero, however softly
            // it lands: the ball is at rest once it no longer leaves the floor by more
            // than a resting-speed hop, v^2 / 2g.
            const double hop =
                def_.collision.restingSpeed * def_.collision.restingSpeed / (2.0 * def_.gravity);
            if (penalty() && out_.bounces.back().apex < hop) out_.cameToRest = true;
        }
    }

  private:
    struct Rise {
        double y, v, t; ///< height, velocity and time in the tick the rise starts from
    };
    bool penalty() const { return def_.collision.model == ContactModel::Penalty; }
    // A spring contact has no instant of impact: the ball rises once its velocity turns
    // upward, and rests once the spring holds it below the resting speed.
    void riseOnSpring(const World& world, ParticleId ball, double v0, Rise& rise) {
        if (!rising_ && v0 <= 0.0 && world.particles.vy[ball] > 0.0) {
            rising_ = true;
            rise = {world.particles.py[ball], world.particles.vy[ball], def_.dt};
        }
    }
    void riseFromContacts(const World& world, ParticleId ball, Rise& rise) {
        for (const ContactEvent& c : world.contacts()) {
            if (c.a != ball) continue;
            if (c.resting) {
                out_.cameToRest = true;
                rising_ = false;
                continue;
            }
            if (rising_) record(std::max(rise.y, c.position.y)); // bounced again before the top
            rise = {c.position.y, c.velocity.y, c.time};
            rising_ = rise.v > 0.0;
            if (!rising_ && static_cast<int>(out_.bounces.size()) < def_.bounces)
                record(c.position.y); // no rebound (e = 0): the apex is the floor
        }
    }
    const DropDef& def_;
    double e_;
    DropResult& out_;
    bool rising_ = false; ///< between a bounce and its apex
};

} // namespace

DropResult simulateDrop(const DropDef& def) {
    World world = dropWorld(def);
    DropResult out;
    const double e = world.materials.pair(def.material, material::kFloor).restitution;
    out.restitution = e;
    ParticleDef pd;
    pd.position = {0.0, def.height + def.radius};
    pd.mass = def.mass;
    pd.radius = def.radius;
    pd.material = def.material;
    const ParticleId ball = world.particles.add(pd);

    ApexFinder apexes(def, e, out);
    const long long maxSteps = std::llround(def.maxTime / def.dt);
    while (static_cast<int>(out.bounces.size()) < def.bounces && out.steps < maxSteps) {
        const double y0 = world.particles.py[ball], v0 = world.particles.vy[ball];
        world.step();
        ++out.steps;
        out.maxPenetration = std::max(out.maxPenetration, def.radius - world.particles.py[ball]);
        apexes.tick(world, ball, y0, v0);
        if (out.cameToRest) break;
    }
    // At rest on the floor: every later apex is the floor.
    if (out.cameToRest || (e == 0.0 && !out.bounces.empty()))
        while (static_cast<int>(out.bounces.size()) < def.bounces)
            apexes.record(def.radius);
    return out;
}

} // namespace phys
