// Selecting the awake: the particles a sub-step works on (the active ones).
//
// Every particle is active but the settled ones: a sleeper still as it was when a
// sub-step last worked on it (or an empty slot). A sleeper does not move, so its path,
// boxes and the rest are still what that sub-step made them, and a heap whose balls
// mostly sleep costs its awake balls and their contacts, not its size. (A sleeper's state
// changes only as it wakes: ParticleSet::setPosition and setVelocity wake it, as contacts
// and blasts do.) A particle that a contact reaches during the sub-step is worked on from
// then on (workOn).
//
// The set also knows the sleepers: where each fell asleep, and which woke or went since
// the last sub-step (what they held up may have to wake, held_sleepers.h).
#pragma once

#include "physics/collision/collision_def.h"
#include "physics/collision/substep.h"
#include "physics/particles.h"

#include <cstdint>
#include <vector>

namespace phys {

class AwakeSet {
  public:
    /// Chooses the active particles of this sub-step; `all`: every particle (the penalty
    /// model, which keeps no settled state, or skipSettled off).
    void select(const ParticleSet& set, const CollisionDef& def, bool all, CollisionStats& stats);

    const std::vector<std::uint32_t>& active() const { return active_; }
    /// Particle i, settled at the sub-step's start, is worked on from here on, and is not
    /// settled in the next sub-step. Returns whether it was settled until now.
    bool workOn(std::size_t i) {
        const bool wasSettled = !activeMark_[i];
        if (wasSettled) {
            activeMark_[i] = 1;
            active_.push_back(static_cast<std::uint32_t>(i));
            if (settledFlags_[i] & kAlive) --settledAsleep_;
        }
        settledFlags_[i] = kUnsettled;
        return wasSettled;
    }
    /// Active particle i was at rest where the sub-step started it (asleep, or an empty
    /// slot), and may be settled in the next sub-step.
    bool mayStaySettled(std::size_t i) const { return settledFlags_[i] != kUnsettled; }
    /// It may not after all (its solver box left its fat box).
    void unsettle(std::size_t i) { settledFlags_[i] = kUnsettled; }
    /// Alive particles settled (so asleep) at the sub-step's start.
    std::size_t settledAsleep() const { return settledAsleep_; }

    /// Where a sleeper fell asleep (radius 0: awake since, or never asleep).
    struct Place {
        double x, y, radius;
    };
    void fellAsleep(std::size_t i, Place at) { sleptAt_[i] = at; }
    /// The sleepers that woke or went since the last sub-step (the list is kept until
    /// forgetWoken), and where each slept (forgotten by forgetWoken too).
    const std::vector<std::uint32_t>& wokeOrGone() const { return wokeOrGone_; }
    Place sleptAt(std::size_t i) const { return sleptAt_[i]; }
    void forgetWoken();

  private:
    static constexpr std::uint32_t kUnsettled = 0xffffffffu;
    // The active particles, marked in activeMark_. A particle's settledFlags_ and
    // settledX_, settledY_, settledRadius_ are its flags and place when a sub-step last
    // worked on it asleep (or on its empty slot), or the flags are kUnsettled: it is
    // settled while its state stays that one bit for bit, at rest, and no contact
    // changes its path.
    std::vector<std::uint32_t> active_;
    std::vector<std::uint8_t> activeMark_;
    std::vector<std::uint32_t> settledFlags_;
    std::vector<double> settledX_, settledY_, settledRadius_; ///< the places, by slot
    std::size_t settledAsleep_ = 0;
    double settledTolerance_ = 0.0; ///< what the settled boxes were built with
    std::vector<Place> sleptAt_;
    std::vector<std::uint32_t> wokeOrGone_;
};

} // namespace phys
