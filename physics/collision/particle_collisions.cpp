#include "physics/collision/particle_collisions.h"

#include "physics/collision/penalty.h"

namespace phys {

// One sub-step, after the integrator has moved every particle from S0 to S1.
void ParticleCollisions::impulsePhase(ParticleSet& set, const StaticShapes& shapes,
                                      const MaterialTable& mats, const CollisionDef& def, double h,
                                      double tickTime, Vec2 up) {
    const Substep sub{set, shapes, mats, def, h, tickTime, up, events_, stats_, detect_};
    narrow_.configure(def);
    held_.setUp(up);
    sleep_.prepare(set.slots());
    // The awake: the particles this sub-step works on; the settled sleepers are skipped.
    awake_.select(set, def, !def.skipSettled, stats_);
    // Paths: each one's parabola from where it started to where the integrator put it.
    paths_.build(set, awake_.active(), h);
    // Passes: detect, then resolve each impact at its time of impact, in time order,
    // until a pass resolves nothing or maxPasses ran.
    const bool converged = passes_.run(sub, stages());
    // Finish: a particle a contact changed takes the end of its new path as its state.
    paths_.finish(set, awake_.active(), h);
    // Solve: the resting contacts the passes left (all, if they ran out), at once.
    solveRestingContacts(sub, converged);
    // Wake: the sleepers whose holders moved off or went wake when the tick ends.
    held_.findWhatWakes(set, def, awake_, cache_);
}

void ParticleCollisions::solveRestingContacts(const Substep& sub, bool converged) {
    if (!converged || !passes_.deferred().empty()) {
        solver_.solve(sub, stages());
        solver_.reportDeferred(passes_.deferred(), sub.set, events_);
    } else {
        solver_.forgetWarmStart(); // nothing to carry over to the next sub-step
        proxies_.boxSettlingForSolver(sub.set, sub.def, awake_, paths_, cache_.fat());
    }
}

// Every particle is worked on (the penalty model keeps no settled state); the pairs are
// those of the end positions.
void ParticleCollisions::penaltyPhase(ParticleSet& set, const StaticShapes& shapes,
                                      const MaterialTable& mats, const CollisionDef& def, double h,
                                      double tickTime) {
    const Substep sub{set, shapes, mats, def, h, tickTime, {}, events_, stats_, detect_};
    const auto t0 = detect_.clock.now(); // profile only
    awake_.select(set, def, true, stats_);
    paths_.build(set, awake_.active(), h);
    proxies_.build(set, awake_.active(), paths_, def, h, true);
    cache_.findPairs(sub, awake_.active(), proxies_, paths_);
    stats_.pairs += static_cast<int>(cache_.pairs().size());
    ++stats_.passes;
    detect_.micros += detect_.clock.microsSince(t0);
    resolvePenaltyContacts(sub, cache_.pairs());
}

} // namespace phys
