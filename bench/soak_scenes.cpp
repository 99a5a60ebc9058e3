#include "soak_scenes.h"

#include "physics/guard.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <span>

namespace soak {

using namespace phys;

namespace {

/// The closed box a scene lives in, lower left corner at the origin, walls drawn so that
/// the solid is outside (clockwise from the top left).
std::vector<Vec2> box(double width, double height) {
    return {{0, height}, {0, 0}, {width, 0}, {width, height}, {0, height}};
}

/// Runs the game's guard after a tick and adds what it found.
void guard(World& w, Faults& faults) {
    const GuardReport r = guardWorld(w);
    faults.nonFinite += r.nonFinite;
    faults.removed += r.removed;
    if (r.tripped()) {
        faults.cause = "tick " + std::to_string(w.tick()) + ": " + std::to_string(r.nonFinite) +
                       " non-finite, " + std::to_string(r.runaway) + " runaway: " + r.cause;
        faults.newCause = true;
    }
}

/// n points at the centres of a grid of cells filling the box, so that nothing
/// overlaps at the start (an overlap resolved by projection would cost energy on day
/// one and say nothing about drift). Fills row by row from the bottom.
std::vector<Vec2> gridPoints(int n, double width, double height) {
    const int cols = std::max(1, static_cast<int>(std::ceil(std::sqrt(n * width / height))));
    const int rows = std::max(1, (n + cols - 1) / cols);
    std::vector<Vec2> points;
    for (int i = 0; i < n; ++i)
        points.push_back({(i % cols + 0.5) * width / cols, (i / cols + 0.5) * height / rows});
    return points;
}

} // namespace

// --- DriftMeter -----------------------------------------------------------------------

void DriftMeter::start(double e) {
    e0 = last = e;
    maxDeviation = 0.0;
}

void DriftMeter::sample(double e) {
    last = e;
    maxDeviation = std::max(maxDeviation, std::abs(e - e0) / std::abs(e0));
}

double DriftMeter::drift() const {
    return (last - e0) / std::abs(e0);
}

double rigidEnergy(const RigidWorld& rigid, const std::vector<BodyId>& bodies, Vec2 gravity,
                   long* nonFinite) {
    double e = 0.0;
    for (const BodyId id : bodies) {
        const RigidBodyState s = rigid.state(id);
        if (s.mass <= 0.0) continue;
        const double ei = 0.5 * s.mass * lengthSquared(s.linearVelocity) +
                          0.5 * s.inertia * s.angularVelocity * s.angularVelocity -
                          s.mass * dot(gravity, s.centerOfMass);
        if (!std::isfinite(ei)) {
            if (nonFinite) ++*nonFinite;
            continue;
        }
        e += ei;
    }
    return e;
}

// --- BusyScene: the dissipative soak --------------------------------------------------

double BusyScene::width(int particles) {
    return std::max(60.0, 0.12 * particles);
}

BusyScene::BusyScene(int particles, int crates, std::uint64_t seed) {
    const std::vector<Vec2> walls = box(width(particles), 40.0);
    world.shapes.addPolyline(walls, material::kFloor);
    // The crates stand on the walls' Box2D copy; the particles meet the walls as the
    // shapes above, so the coupling skips the copy (as a match does with its terrain).
    coupling.mirror(rigid.createTerrain(walls, RigidMaterial{0.0, 0.3, 0.0}));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> x(1.0, width(particles) - 1.0), y(5.0, 38.0),
        v(-8.0, 8.0);
    for (int i = 0; i < particles; ++i) {
        ParticleDef pd;
        pd.position = {x(rng), y(rng)};
        // The springs below join 2k and 2k + 1: start each pair at the spring's rest
        // length, not wherever the dice put it (a spring stretched across the box pulls
        // its particles to hundreds of m/s within a few ticks).
        if (i % 2 == 1 && i < 200) {
            const Vec2 a = world.particles.position(static_cast<ParticleId>(i - 1));
            pd.position = {a.x < width(particles) / 2 ? a.x + 0.5 : a.x - 0.5, a.y};
        }
        pd.velocity = {v(rng), v(rng)};
        pd.radius = 0.1;
        pd.material = material::kPerfectlyElastic;
        world.particles.add(pd);
    }
    // A soft lattice of springs among the first particles.
    for (int i = 0; i + 1 < std::min(particles, 200); i += 2) {
        Spring s;
        s.a = static_cast<ParticleId>(i);
        s.b = static_cast<ParticleId>(i + 1);
        s.restLength = 0.5;
        s.stiffness = 200.0;
        s.damping = 0.1;
        world.springs.push_back(s);
    }
    for (int i = 0; i < crates; ++i) {
        BodyDef bd;
        bd.position = {x(rng), y(rng)};
        bodies.push_back(rigid.createBox(bd, {0.4, 0.4}, RigidMaterial{50.0, 0.4, 0.5}));
    }
    energy0 = energy();
}

void BusyScene::step(Faults& faults) {
    coupling.prepare(world, rigid);
    world.step();
    coupling.exchange(world, rigid);
    rigid.step(world.def().tickSeconds);
    guard(world, faults);
    rigidEnergy(rigid, bodies, rigid.def().gravity, &faults.nonFinite);
}

double BusyScene::energy() const {
    return phys::energy(world.particles, world.springs, world.def().forces).total() +
           rigidEnergy(rigid, bodies, rigid.def().gravity);
}

// --- OscillatorBank: undamped springs, one integrator ---------------------------------

namespace {
WorldDef oscillatorDef(Integrator method) {
    WorldDef def;
    def.tickSeconds = kTick;
    def.model = ModelPolicy::Integrate;
    def.integrator = method;
    def.forces.gravity = {0.0, 0.0};
    def.collision.model = ContactModel::None;
    def.collision.sleep = false;
    return def;
}
} // namespace

OscillatorBank::OscillatorBank(Integrator m, int oscillators, std::uint64_t seed)
    : method(m), world(oscillatorDef(m)) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> logK(std::log(kMin), std::log(kMax));
    std::uniform_real_distribution<double> amplitude(0.1, 0.8), phase(0.0, 2.0 * std::numbers::pi);
    for (int i = 0; i < oscillators; ++i) {
        const double k = std::exp(logK(rng));
        const double a = amplitude(rng), ph = phase(rng), w = std::sqrt(k);
        // Anchor at the origin, the particle on the x axis: the force's y component is
        // k (L - L0) * 0 / L = 0 exactly, so it moves along x only.
        ParticleDef pd;
        pd.position = {kRestLength + a * std::cos(ph), 0.0};
        pd.velocity = {-a * w * std::sin(ph), 0.0};
        pd.mass = 1.0;
        pd.flags = kNoCollide | kNoDrag;
        Spring s;
        s.a = world.particles.add(pd);
        s.anchor = {0.0, 0.0};
        s.restLength = kRestLength;
        s.stiffness = k;
        world.springs.push_back(s);
        stiffness_.push_back(k);
    }
    double sum = 0.0;
    for (std::size_t i = 0; i < stiffness_.size(); ++i) {
        const Energy en = energyOf(i);
        e0_.push_back(en.e);
        h0_.push_back(en.h);
        sum += en.e;
    }
    total.start(sum);
}

bool OscillatorBank::hasInvariant() const {
    return method == Integrator::SymplecticEuler || method == Integrator::VelocityVerlet;
}

// Energy E = 1/2 m v^2 + 1/2 k x^2 of oscillator i (x = L - L0, m = 1 kg, w^2 = k), and
// the quantity H its integrator conserves exactly on x'' = -w^2 x, with h = dt:
//   symplectic Euler  H = E - (k h / 2) x v; |x v| <= E / w, so
//                     E / H lies in [1 / (1 + w h / 2), 1 / (1 - w h / 2)]
//   velocity Verlet   H = E - (k x^2 / 2) (w h)^2 / 4, so E / H lies in [1, 1 / (1 - (w h)^2 / 4)]
// (H is found by asking which quadratic form the one-step map preserves.) Other
// methods: H = E and the band is [1, 1].
OscillatorBank::Energy OscillatorBank::energyOf(std::size_t i) const {
    const ParticleSet& s = world.particles;
    const double k = stiffness_[i], h = world.def().tickSeconds, wh = std::sqrt(k) * h;
    // The particle stays on the positive x axis (amplitude < L0): L = px, v = vx.
    const double x = s.px[i] - kRestLength, v = s.vx[i];
    Energy r;
    r.e = 0.5 * (v * v + s.vy[i] * s.vy[i]) + 0.5 * k * x * x;
    r.h = r.e;
    if (method == Integrator::SymplecticEuler) {
        r.h = r.e - 0.5 * k * h * x * v;
        r.lo = 1.0 / (1.0 + 0.5 * wh);
        r.hi = 1.0 / (1.0 - 0.5 * wh);
    } else if (method == Integrator::VelocityVerlet) {
        r.h = r.e - 0.125 * k * x * x * wh * wh;
        r.hi = 1.0 / (1.0 - 0.25 * wh * wh);
    }
    return r;
}

void OscillatorBank::sample() {
    double sum = 0.0;
    for (std::size_t i = 0; i < stiffness_.size(); ++i) {
        if (!world.particles.alive(static_cast<ParticleId>(i))) continue;
        const Energy en = energyOf(i);
        sum += en.e;
        worstSingle = std::max(worstSingle, std::abs(en.e / e0_[i] - 1.0));
        invariantDrift = std::max(invariantDrift, std::abs(en.h / h0_[i] - 1.0));
        // Where E/H sits in its band: 1 at the edge; outside it, the excess.
        const double ratio = en.e / en.h;
        bandExcess = std::max({bandExcess, en.lo - ratio, ratio - en.hi});
        if (ratio > 1.0 && en.hi > 1.0)
            bandUsed = std::max(bandUsed, (ratio - 1.0) / (en.hi - 1.0));
        if (ratio < 1.0 && en.lo < 1.0)
            bandUsed = std::max(bandUsed, (1.0 - ratio) / (1.0 - en.lo));
    }
    total.sample(sum);
}

void OscillatorBank::step(Faults& faults) {
    world.step();
    guard(world, faults);
    sample();
}

// --- ElasticGas: e = 1, frictionless, zero gravity ------------------------------------

namespace {
WorldDef gasDef() {
    WorldDef def;
    def.tickSeconds = kTick;
    def.forces.gravity = {0.0, 0.0};
    def.collision.sleep = false;
    def.collision.restingSpeed = 0.0; // with no gravity, only a closing speed of 0 rests
    return def;
}
} // namespace

ElasticGas::ElasticGas(int particles, std::uint64_t seed) : world(gasDef()) {
    // e = 1 and no friction against everything: the walls are the reference floor
    // (e = 1), and the pair rule gives e = 1 * 1 and mu = sqrt(0 * mu) = 0.
    const MaterialId frictionless =
        *world.materials.add(Material{"frictionless-elastic", 1.0, 0.0, 0.0});
    world.shapes.addPolyline(box(60.0, 40.0), material::kFloor);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> v(-8.0, 8.0);
    for (const Vec2 p : gridPoints(particles, 60.0, 40.0)) {
        ParticleDef pd;
        pd.position = p;
        pd.velocity = {v(rng), v(rng)};
        pd.radius = 0.1;
        pd.material = frictionless;
        world.particles.add(pd);
    }
    drift.start(energy());
}

void ElasticGas::step(Faults& faults) {
    world.step();
    guard(world, faults);
    drift.sample(energy());
}

double ElasticGas::energy() const {
    return phys::energy(world.particles, world.springs, world.def().forces).total();
}

// --- ElasticBodies: Box2D, e = 1, frictionless, zero gravity --------------------------

namespace {
RigidWorldDef elasticRigidDef() {
    RigidWorldDef def;
    def.gravity = {0.0, 0.0};
    def.allowSleeping = false;
    def.restitutionThreshold = 1e-4; // m/s: every approach bounces (> 0, see validate)
    return def;
}
} // namespace

ElasticBodies::ElasticBodies(int count, std::uint64_t seed) : rigid(elasticRigidDef()) {
    // Box2D mixes restitution by max and friction by sqrt(f1 f2): e = 1 and mu = 0
    // everywhere.
    const RigidMaterial wall{0.0, 0.0, 1.0};
    const std::vector<Vec2> walls = box(60.0, 40.0);
    rigid.createTerrain(std::span(walls).first(4), wall, /*loop=*/true);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> v(-5.0, 5.0), spin(-2.0, 2.0);
    const std::vector<Vec2> at = gridPoints(count, 60.0, 40.0);
    for (int i = 0; i < count; ++i) {
        BodyDef bd;
        bd.position = at[i];
        bd.linearVelocity = {v(rng), v(rng)};
        bd.angularVelocity = spin(rng);
        const RigidMaterial m{100.0, 0.0, 1.0};
        bodies.push_back(i % 2 ? rigid.createBox(bd, {0.25, 0.25}, m)
                               : rigid.createCircle(bd, 0.25, m));
    }
    drift.start(energy());
}

void ElasticBodies::step(Faults& faults) {
    rigid.step(kTick);
    drift.sample(rigidEnergy(rigid, bodies, rigid.def().gravity, &faults.nonFinite));
}

double ElasticBodies::energy() const {
    return rigidEnergy(rigid, bodies, rigid.def().gravity);
}

} // namespace soak
