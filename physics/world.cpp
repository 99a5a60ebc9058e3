#include "physics/world.h"

#include <cmath>

namespace phys {

namespace {
// The unit vector against gravity, or zero without gravity.
Vec2 upward(Vec2 g) {
    const double l = length(g);
    return l > 0.0 ? g / -l : Vec2{};
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

// Which particles are tied to a spring or a rod: they stay on the integrator and never
// sleep. Without springs and rods nothing is, and no sweep is needed to say so.
void World::markTethered() {
    tethered_.clear();
    if (springs.empty() && constraints.empty()) return;
    tethered_.assign(particles.slots(), 0);
    for (const SpringTerms::Term& sp : springTerms_.terms) // the unbroken springs
        for (const ParticleId id : {sp.a, sp.b})
            if (id < tethered_.size()) tethered_[id] = 1;
    for (const DistanceConstraint& c : constraints)
        for (const ParticleId id : {c.a, c.b})
            if (id < tethered_.size()) tethered_[id] = 1;
}

// Which particles may follow the closed form this tick: alive, free, awake, and acted on
// by uniform gravity alone (no drag reaching them, no springs or rods, no point gravity,
// no water within reach this tick). Counts the models on the way.
ModelCounts World::chooseModels(const ModelRule& rule) {
    ModelCounts counts;
    for (std::size_t i = 0; i < particles.slots(); ++i)
        countModel(counts, chooseModel(particles, i, rule), particles.invMass[i]);
    return counts;
}

// (Re)launch every closed-form particle whose state is not on its parabola any more (new,
// bounced, pushed by a blast or a command): the parabola starts from where it is now.
void World::launchBallistic(double now) {
    for (std::size_t i = 0; i < particles.slots(); ++i)
        if (particles.flags[i] & kBallistic)
            phys::launchBallistic(particles, i, def_.forces.gravity, now);
}

// The closed form at the end of the sub-step: exact, whatever h.
void World::advanceBallistic(double now) {
    for (std::size_t i = 0; i < particles.slots(); ++i)
        if (particles.flags[i] & kBallistic)
            phys::advanceBallistic(particles, i, def_.forces.gravity, now);
}

ModelCounts World::countModels() const {
    ModelCounts counts;
    for (std::size_t i = 0; i < particles.slots(); ++i)
        countModel(counts, particles.flags[i], particles.invMass[i]);
    return counts;
}

void World::step() {
    const auto t0 = clock_.now();
    springTerms_.build(springs); // before markTethered, which reads it
    const Dynamics dynamics(def_.forces, springs, particles, &springTerms_);
    const TickPlan plan = planTick(dynamics);
    profile_ = {};
    collisions_.clearEvents();

    // 0. Models: the closed form for what only gravity acts on, the integrator for the rest.
    auto t = clock_.now();
    markTethered();
    const ModelRule rule(def_.forces, def_.model == ModelPolicy::Auto, def_.tickSeconds,
                         tethered_.empty() ? nullptr : tethered_.data());
    ModelCounts counts;
    if (!plan.fused) counts = chooseModels(rule);
    profile_.integrateUs += clock_.microsSince(t);

    // 1-4. The sub-steps: forces, integration, collisions, rods and cables.
    for (int s = 0; s < def_.substeps; ++s)
        substep(s, dynamics, rule, plan, counts);

    // 5. Sleep: resting particles fall asleep; anything tied to a spring or constraint
    // stays awake (the other end may move). Without contacts nothing rests, so nothing
    // falls asleep and the sweep is skipped.
    t = clock_.now();
    if (plan.colliding)
        collisions_.updateSleep(particles, def_.collision, def_.tickSeconds, tethered_);
    else
        collisions_.noContactsThisTick(counts.asleep);
    profile_.resolveUs += clock_.microsSince(t);

    // 6. Springs yield and break once per tick, from the state the tick ended in.
    t = clock_.now();
    brokenSprings_ += updateSprings(springs, particles, def_.tickSeconds);
    profile_.springsUs = clock_.microsSince(t);

    // What each model cost this tick is in the phases above; how many were in each (the
    // model sweep counted them, unless contacts woke or put particles to sleep since):
    if (plan.colliding) counts = countModels();
    profile_.closedForm = counts.closedForm;
    profile_.integrated = counts.integrated;
    profile_.sleeping = counts.sleeping;
    profile_.fixed = counts.fixed;

    ++tick_;
    time_ += def_.tickSeconds;
    profile_.totalUs = clock_.microsSince(t0);
}

// Symplectic Euler or velocity Verlet with forces that act on each particle alone (a sky
// full of shells under drag): model choice, closed form, integration and the model count
// are one sweep per sub-step (model_pass.h) instead of five.
World::TickPlan World::planTick(const Dynamics& dynamics) const {
    TickPlan plan;
    plan.colliding = def_.collision.model != ContactModel::None;
    plan.fused = (def_.integrator == Integrator::SymplecticEuler ||
                  def_.integrator == Integrator::VelocityVerlet) &&
                 dynamics.onlyLocalForces();
    plan.scheme = def_.integrator == Integrator::VelocityVerlet ? FlightScheme::VelocityVerlet
                                                               : FlightScheme::SymplecticEuler;
    return plan;
}

// Sub-step s of the tick: forces and integration (the integrator evaluates the force
// generators at every stage it needs; closed-form particles are set from their parabola),
// then collisions and rods and cables.
void World::substep(int s, const Dynamics& dynamics, const ModelRule& rule, const TickPlan& plan,
                    ModelCounts& counts) {
    const double h = def_.tickSeconds / def_.substeps;
    auto t = clock_.now();
    const double start = time_ + s * h, end = time_ + (s + 1) * h;
    if (plan.colliding) collisions_.beginSubstep(particles); // the start, for the collide phase
    if (plan.fused) {
        counts = flightPass(particles, def_.forces, s == 0 ? &rule : nullptr, h, start, end,
                            plan.scheme);
    } else {
        const bool closedForm = counts.closedForm > 0; // else no kBallistic this tick
        if (closedForm) launchBallistic(start);
        integrate(def_.integrator, dynamics, particles, h, scratch_, def_.implicit);
        if (closedForm) advanceBallistic(end);
    }
    profile_.integrateUs += clock_.microsSince(t);

    // 3-4. Collide and resolve: impacts at their time of impact, resting contact.
    if (plan.colliding) collideAndResolve(h, s * h);

    // 4b. Constraints: rods and cables, by projection.
    t = clock_.now();
    constraintError_ =
        solveConstraints(constraints, particles, constraintScratch_,
                         def_.collision.constraintIterations, def_.collision.constraintTolerance);
    profile_.constraintsUs += clock_.microsSince(t);
}

// Detection and response interleave (each pass detects what the previous pass's bounces
// lead to), so the profile splits the phase by the detector's own timing.
void World::collideAndResolve(double h, double tickTime) {
    const auto t = clock_.now();
    const double detectBefore = collisions_.detectMicros();
    if (def_.collision.model == ContactModel::Penalty)
        collisions_.penaltyPhase(particles, shapes, materials, def_.collision, h, tickTime);
    else
        collisions_.impulsePhase(particles, shapes, materials, def_.collision, h, tickTime,
                                 upward(def_.forces.gravity));
    const double detect = collisions_.detectMicros() - detectBefore;
    profile_.collideUs += detect;
    profile_.resolveUs += clock_.microsSince(t) - detect;
}

void World::setProfiling(bool on) {
    clock_.on = on;
    collisions_.setProfiling(on);
}

void World::wakeAll() {
    for (auto& f : particles.flags) f &= ~kSleeping;
}

std::uint64_t World::hash() const {
    std::uint64_t h = hashBytes(0xcbf29ce484222325ull, &tick_, sizeof tick_);
    return stateHash(particles, h);
}

} // namespace phys
