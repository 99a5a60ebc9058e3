// Falling asleep: a particle that spends sleepTime in resting contact, still, sleeps
// (kSleeping) until an impulse, a blast or a command wakes it, or what holds it up moves
// off or goes (held_sleepers.h). Sleepers are immovable to the others, and cost nearly
// nothing (awake_set.h). Particles tied to springs or constraints do not sleep.
//
// A particle in resting contact is still when its velocity is below sleepSpeed, or when
// its motion is: it has strayed less than sleepSpeed * sleepTime from where its rest
// window started, a mean velocity below sleepSpeed. Either alone misses a kind of rest.
// The velocity misses a particle wedged between sleepers, or a cluster the contact solver
// leaves with a residual velocity that the position projection undoes every step: they
// report centimetres per second and go nowhere. The motion misses a particle the
// projection nudges a fraction of a millimetre a step while it has no velocity at all.
// After sleepTime still, it sleeps. A steady slide at sleepSpeed or faster fails both;
// so does any tick without a resting contact.
#pragma once

#include "physics/collision/collision_def.h"
#include "physics/collision/substep.h"
#include "physics/particles.h"

#include <cstdint>
#include <vector>

namespace phys {

class AwakeSet;
class HeldSleepers;
class PairCache;
class Proxies;

class Sleep {
  public:
    /// Room for n particles' rest flags (call before the sub-step's contacts).
    void prepare(std::size_t n) { growTo(rested_, n); }
    /// A contact of this tick touched particle i, at rest or not.
    void noteContact(std::size_t i, bool resting) { rested_[i] = rested_[i] || resting; }
    /// Puts resting particles to sleep after dt of rest; `tethered[i]` != 0 never sleeps.
    /// The sleepers held up by particles that moved off wake (HeldSleepers).
    void update(ParticleSet& set, const CollisionDef& def, double dt,
                const std::vector<std::uint8_t>& tethered, AwakeSet& awake, HeldSleepers& held,
                PairCache& cache, const Proxies& proxies, CollisionStats& stats);
    /// In place of update for a tick without collisions: nothing rested, so nothing falls
    /// asleep and every awake particle's rest timer restarts (done on the next update).
    void noContactsThisTick() { timersStale_ = true; }

  private:
    std::vector<std::uint8_t> rested_; ///< a resting contact this tick
    std::vector<double> timer_;        ///< s in resting contact within the rest window
    std::vector<Vec2> anchor_;         ///< where the rest window started
    bool timersStale_ = false;         ///< ticks without contacts passed since update
};

} // namespace phys
