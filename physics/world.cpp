#include "physics/world.h"

#include <chrono>
#include <cmath>

namespace phys {

namespace {
using ProfileClock = std::chrono::steady_clock;
double microsSince(ProfileClock::time_point t0) {
    return std::chrono::duration<double, std::micro>(ProfileClock::now() - t0).count();
}
} // namespace

std::string validate(const WorldDef& d) {
    if (!(d.tickSeconds > 0.0) || !(d.tickSeconds <= 1.0))
        return "tick must be in (0, 1] s";
    if (d.substeps < 1 || d.substeps > 1000) return "substeps must be in 1..1000";
    const ForceDef& f = d.forces;
    if (!std::isfinite(f.gravity.x) || !std::isfinite(f.gravity.y))
        return "gravity must be finite";
    if (!(f.airDensity >= 0.0) || !std::isfinite(f.airDensity))
        return "air density must be >= 0 kg/m^3";
    if (!(f.linearDrag >= 0.0) || !std::isfinite(f.linearDrag))
        return "linear drag must be >= 0 kg/s";
    if (!std::isfinite(f.wind.x) || !std::isfinite(f.wind.y)) return "wind must be finite";
    if (!(f.waterDensity >= 0.0) || !std::isfinite(f.waterDensity))
        return "water density must be >= 0 kg/m^3";
    if (auto e = validate(d.collision); !e.empty()) return e;
    return {};
}

World::World(const WorldDef& def) : def_(def) {}

void World::setDef(const WorldDef& def) {
    if (def.tickSeconds != def_.tickSeconds || def.substeps != def_.substeps ||
        def.integrator != def_.integrator)
        particles.resetHistory();
    def_ = def;
}

void World::step() {
    const auto t0 = ProfileClock::now();
    const double h = def_.tickSeconds / def_.substeps;
    const Dynamics dynamics(def_.forces, springs, particles);
    const bool colliding = def_.collision.model != ContactModel::None;
    profile_ = {};
    collisions_.clearEvents();

    for (int s = 0; s < def_.substeps; ++s) {
        // 1-2. Forces and integration: the integrator evaluates the force generators at
        // every stage it needs. The start of the sub-step is kept for the collide phase.
        auto t = ProfileClock::now();
        if (colliding) collisions_.beginSubstep(particles);
        integrate(def_.integrator, dynamics, particles, h, scratch_, def_.implicit);
        profile_.integrateUs += microsSince(t);

        // 3-4. Collide and resolve: impacts at their time of impact, resting contact.
        if (colliding) collideAndResolve(h, s * h);

        // 4b. Constraints: rods and cables, by projection.
        t = ProfileClock::now();
        constraintError_ =
            solveConstraints(constraints, particles, constraintScratch_,
                             def_.collision.constraintIterations, def_.collision.constraintTolerance);
        profile_.constraintsUs += microsSince(t);
    }

    // 5. Sleep: resting particles fall asleep; anything tied to a spring or constraint
    // stays awake (the other end may move).
    auto t = ProfileClock::now();
    tethered_.assign(particles.slots(), 0);
    for (const Spring& sp : springs)
        for (const ParticleId id : {sp.a, sp.b})
            if (id < tethered_.size()) tethered_[id] = 1;
    for (const DistanceConstraint& c : constraints)
        for (const ParticleId id : {c.a, c.b})
            if (id < tethered_.size()) tethered_[id] = 1;
    collisions_.updateSleep(particles, def_.collision, def_.tickSeconds, tethered_);
    profile_.resolveUs += microsSince(t);

    // 6. Springs yield and break once per tick, from the state the tick ended in.
    t = ProfileClock::now();
    brokenSprings_ += updateSprings(springs, particles, def_.tickSeconds);
    profile_.springsUs = microsSince(t);

    ++tick_;
    profile_.totalUs = microsSince(t0);
}

// Detection and response interleave (each pass detects what the previous pass's bounces
// lead to), so the profile splits the phase by the detector's own timing.
void World::collideAndResolve(double h, double tickTime) {
    const auto t = ProfileClock::now();
    const double detectBefore = collisions_.detectMicros();
    if (def_.collision.model == ContactModel::Penalty)
        collisions_.penaltyPhase(particles, shapes, materials, def_.collision, h, tickTime);
    else
        collisions_.impulsePhase(particles, shapes, materials, def_.collision, h, tickTime);
    const double detect = collisions_.detectMicros() - detectBefore;
    profile_.collideUs += detect;
    profile_.resolveUs += microsSince(t) - detect;
}

std::uint64_t World::hash() const {
    std::uint64_t h = hashBytes(0xcbf29ce484222325ull, &tick_, sizeof tick_);
    return stateHash(particles, h);
}

} // namespace phys
