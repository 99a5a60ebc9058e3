#include "physics/world.h"

#include "physics/ballistics.h"

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

const char* modelPolicyName(ModelPolicy p) {
    return p == ModelPolicy::Auto ? "auto" : "integrate";
}

void World::markTethered() {
    tethered_.assign(particles.slots(), 0);
    for (const Spring& sp : springs)
        if (!sp.broken)
            for (const ParticleId id : {sp.a, sp.b})
                if (id < tethered_.size()) tethered_[id] = 1;
    for (const DistanceConstraint& c : constraints)
        for (const ParticleId id : {c.a, c.b})
            if (id < tethered_.size()) tethered_[id] = 1;
}

// Which particles may follow the closed form this tick: alive, free, awake, and acted on
// by uniform gravity alone (no drag reaching them, no springs or rods, no point gravity,
// no water within reach this tick).
void World::chooseModels() {
    const ForceDef& f = def_.forces;
    const bool airDrag = (f.drag == DragModel::Quadratic && f.airDensity > 0.0) ||
                         (f.drag == DragModel::Linear && f.linearDrag > 0.0);
    const double g = length(f.gravity);
    for (std::size_t i = 0; i < particles.slots(); ++i) {
        std::uint32_t& fl = particles.flags[i];
        bool closed = def_.model == ModelPolicy::Auto && (fl & kAlive) &&
                      !(fl & kSleeping) && particles.invMass[i] > 0.0 && !tethered_[i] &&
                      !(airDrag && !(fl & kNoDrag)) && !(f.pointGravity && (fl & kAttractor)) &&
                      !(fl & kNoGravity);
        if (closed && f.water) {
            // Stay clear of the water for the whole tick: the farthest it can fall.
            const double reach = std::abs(particles.vy[i]) * def_.tickSeconds +
                                 g * def_.tickSeconds * def_.tickSeconds + particles.radius[i];
            closed = particles.py[i] - reach > f.waterLevel;
        }
        if (closed) {
            if (!(fl & kBallistic)) {
                fl |= kBallistic;
                particles.launchT[i] = NAN; // launched at the first sub-step
            }
        } else if (fl & kBallistic) {
            // Promoted to the integrator from its exact state; history from before the
            // closed form would be stale.
            fl &= ~(kBallistic | kVerletPrimed | kLeapfrogPrimed);
        }
    }
}

// (Re)launch every closed-form particle whose state is not on its parabola any more (new,
// bounced, pushed by a blast or a command): the parabola starts from where it is now.
void World::launchBallistic(double now) {
    const Vec2 g = def_.forces.gravity;
    ParticleSet& s = particles;
    for (std::size_t i = 0; i < s.slots(); ++i) {
        if (!(s.flags[i] & kBallistic)) continue;
        bool on = std::isfinite(s.launchT[i]);
        if (on) {
            const double t = now - s.launchT[i];
            const BallisticState e = ballisticState({s.launchX[i], s.launchY[i]},
                                                    {s.launchVx[i], s.launchVy[i]}, g, t);
            on = e.position.x == s.px[i] && e.position.y == s.py[i] && e.velocity.x == s.vx[i] &&
                 e.velocity.y == s.vy[i];
        }
        if (!on) {
            s.launchX[i] = s.px[i];
            s.launchY[i] = s.py[i];
            s.launchVx[i] = s.vx[i];
            s.launchVy[i] = s.vy[i];
            s.launchT[i] = now;
        }
    }
}

// The closed form at the end of the sub-step: exact, whatever h.
void World::advanceBallistic(double now) {
    const Vec2 g = def_.forces.gravity;
    ParticleSet& s = particles;
    for (std::size_t i = 0; i < s.slots(); ++i) {
        if (!(s.flags[i] & kBallistic)) continue;
        const BallisticState e = ballisticState({s.launchX[i], s.launchY[i]},
                                                {s.launchVx[i], s.launchVy[i]}, g, now - s.launchT[i]);
        s.px[i] = e.position.x;
        s.py[i] = e.position.y;
        s.vx[i] = e.velocity.x;
        s.vy[i] = e.velocity.y;
    }
}

void World::step() {
    const auto t0 = ProfileClock::now();
    const double h = def_.tickSeconds / def_.substeps;
    const Dynamics dynamics(def_.forces, springs, particles);
    const bool colliding = def_.collision.model != ContactModel::None;
    profile_ = {};
    collisions_.clearEvents();

    // 0. Models: the closed form for what only gravity acts on, the integrator for the rest.
    auto t = ProfileClock::now();
    markTethered();
    chooseModels();
    profile_.integrateUs += microsSince(t);

    for (int s = 0; s < def_.substeps; ++s) {
        // 1-2. Forces and integration: the integrator evaluates the force generators at
        // every stage it needs; closed-form particles are set from their parabola. The
        // start of the sub-step is kept for the collide phase.
        t = ProfileClock::now();
        const double start = time_ + s * h, end = time_ + (s + 1) * h;
        if (colliding) collisions_.beginSubstep(particles);
        launchBallistic(start);
        integrate(def_.integrator, dynamics, particles, h, scratch_, def_.implicit);
        advanceBallistic(end);
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
    t = ProfileClock::now();
    collisions_.updateSleep(particles, def_.collision, def_.tickSeconds, tethered_);
    profile_.resolveUs += microsSince(t);

    // 6. Springs yield and break once per tick, from the state the tick ended in.
    t = ProfileClock::now();
    brokenSprings_ += updateSprings(springs, particles, def_.tickSeconds);
    profile_.springsUs = microsSince(t);

    // What each model cost this tick is in the phases above; how many were in each:
    for (std::size_t i = 0; i < particles.slots(); ++i) {
        const std::uint32_t fl = particles.flags[i];
        if (!(fl & kAlive)) continue;
        if (particles.invMass[i] <= 0.0) ++profile_.fixed;
        else if (fl & kSleeping) ++profile_.sleeping;
        else if (fl & kBallistic) ++profile_.closedForm;
        else ++profile_.integrated;
    }

    ++tick_;
    time_ += def_.tickSeconds;
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

void World::wakeAll() {
    for (auto& f : particles.flags) f &= ~kSleeping;
}

std::uint64_t World::hash() const {
    std::uint64_t h = hashBytes(0xcbf29ce484222325ull, &tick_, sizeof tick_);
    return stateHash(particles, h);
}

} // namespace phys
