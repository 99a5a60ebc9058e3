// The collide and resolve phases of the world step for particles, as a pipeline of
// stages, each a class that owns its state:
//
//   awake_set.h      selecting the awake: the particles a sub-step works on (the
//                    settled sleepers cost nothing)
//   paths.h          each particle's path over the sub-step, the parabola through where
//                    it started and where the integrator put it
//   proxies.h        the broad phase's proxies: each particle's kind and box
//   pair_cache.h     the broad phase over fat boxes and its kept pairs
//   narrowphase.h    the pairs that meet within the step, with their times of impact
//   toi_passes.h     the passes: detect, then resolve each impact at its time of impact
//   contact_solver.h the resting contacts the passes leave, by sequential impulses and
//                    projection (its sweep order in sweep_order.h)
//   sleep.h          falling asleep; held_sleepers.h: waking what loses its support
// with the vectorized kernels of the hot loops in simd/, beside their scalar twins.
//
// The penalty model (penalty.h) uses the first four stages and its own response.
#pragma once

#include "physics/collision/awake_set.h"
#include "physics/collision/collision_def.h"
#include "physics/collision/contact_solver.h"
#include "physics/collision/held_sleepers.h"
#include "physics/collision/narrowphase.h"
#include "physics/collision/pair_cache.h"
#include "physics/collision/paths.h"
#include "physics/collision/proxies.h"
#include "physics/collision/shapes.h"
#include "physics/collision/sleep.h"
#include "physics/collision/substep.h"
#include "physics/collision/toi_passes.h"
#include "physics/materials.h"
#include "physics/particles.h"

#include <cstdint>
#include <vector>

namespace phys {

class ParticleCollisions {
  public:
    /// Saves the state the sub-step starts from (call before integrating).
    void beginSubstep(const ParticleSet& set) { paths_.begin(set); }
    /// Collide and resolve with the impulse model over a sub-step of h seconds that
    /// starts tickTime seconds into the tick (for event times). `up` is the unit vector
    /// against gravity (zero without gravity): what holds what up in a pile.
    void impulsePhase(ParticleSet& set, const StaticShapes& shapes, const MaterialTable& mats,
                      const CollisionDef& def, double h, double tickTime, Vec2 up = {});
    /// Collide and resolve with the penalty model (overlaps at the end of the step).
    void penaltyPhase(ParticleSet& set, const StaticShapes& shapes, const MaterialTable& mats,
                      const CollisionDef& def, double h, double tickTime);
    /// Puts resting particles to sleep after dt of rest; `tethered[i]` != 0 never sleeps.
    void updateSleep(ParticleSet& set, const CollisionDef& def, double dt,
                     const std::vector<std::uint8_t>& tethered) {
        sleep_.update(set, def, dt, tethered, awake_, held_, cache_, proxies_, stats_);
    }
    /// In place of updateSleep for a tick without collisions: nothing rested, so nothing
    /// falls asleep and every awake particle's rest timer restarts (done on the next
    /// updateSleep). `asleep` is the number of sleeping particles, for the stats.
    void noContactsThisTick(int asleep) {
        stats_.sleeping = asleep;
        sleep_.noContactsThisTick();
    }

    /// Contacts of the last tick (cleared by clearEvents, which World::step calls).
    const std::vector<ContactEvent>& events() const { return events_; }
    void clearEvents() {
        events_.clear();
        stats_ = {};
    }
    const CollisionStats& stats() const { return stats_; }
    /// Microseconds spent detecting (broad + narrow phase) since construction, a running
    /// total the world differences to split its profile (profile only).
    double detectMicros() const { return detect_.micros; }
    /// Whether detectMicros() is timed (World::setProfiling).
    void setProfiling(bool on) { detect_.clock.on = on; }

  private:
    void solveRestingContacts(const Substep& sub, bool converged);
    SubstepStages stages() { return {awake_, paths_, proxies_, cache_, narrow_, sleep_, held_}; }

    AwakeSet awake_;
    SubstepPaths paths_;
    Proxies proxies_;
    PairCache cache_;
    NarrowPhase narrow_;
    ToiPasses passes_;
    ContactSolver solver_;
    Sleep sleep_;
    HeldSleepers held_;
    std::vector<ContactEvent> events_;
    CollisionStats stats_;
    DetectClock detect_;
};

} // namespace phys
