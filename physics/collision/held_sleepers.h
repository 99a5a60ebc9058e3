// Sleepers wake when what holds them up moves off.
//
// A sleeper is immovable to the passes and the contact solver: it stays where it fell
// asleep, whatever holds it up. Left at that, a sleeping column stood in the air when the
// ball under it was knocked away or removed, and the sleepers of a pile hung over the
// hollows its awake part slid into. So a sleeper held up by an awake particle (a contact of
// the solver whose normal is within kSupport of vertical) wakes when the holder
//   moves     farther from where it began to hold it up than a sleeper may stray while it
//             falls asleep (sleepSpeed * sleepTime, sleep.h's rule): it slid away, fell or
//             was knocked, and the sleeper would have gone with it;
//   leaves    or is removed, so that nothing near enough holds the sleeper up.
// The holds are those of the solver's contacts (noteSolverContact), those of a particle
// that falls asleep on awake ones (holdsOfNewSleeper: the passes alone may hold it there,
// with no solver), and those of a sleeper that wakes or is removed: from the place it
// slept, it held up the sleepers that rested on it (holdsOfWoken; asleep, the two were no
// contact of anything).
// A holder that stays put keeps the sleeper asleep, as does one that falls asleep under
// it; what rests on a sleeper never wakes it (a sleeping pile carries its top layer).
// Box2D wakes a whole island when any of it moves; this wakes only what loses its support,
// so a settled heap under a rolling ball stays asleep.
//
// The wakes take effect at the end of the tick (wakeHeldSleepers, from Sleep::update),
// not where they are found: a sub-step works on the particles it selected at its start,
// and every particle sees the same sleepers until the tick ends, whichever it works on.
#pragma once

#include "physics/collision/collision_def.h"
#include "physics/collision/paths.h"
#include "physics/collision/solver_contact.h"
#include "physics/particles.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace phys {

class AwakeSet;
class PairCache;
class Proxies;

class HeldSleepers {
  public:
    /// The up of this sub-step (against gravity): what holds what up.
    void setUp(Vec2 up) { up_ = up; }
    /// The hold of a contact of the solver between two particles, one of them immovable,
    /// if it holds a sleeper up.
    void noteSolverContact(const ParticleSet& set, const SolverContact& c,
                           const SubstepPaths& paths);
    /// The awake particles that hold up s, which falls asleep now (unsorted: sortHolds).
    void holdsOfNewSleeper(const ParticleSet& set, const CollisionDef& def, std::uint32_t s,
                           PairCache& cache, const Proxies& proxies);
    std::size_t holds() const { return held_.size(); }
    void sortHolds(); ///< in pair order, each pair once
    /// At a sub-step's end: the sleepers whose holders moved too far or are gone (and
    /// those the sleepers that woke or went held up) wake when the tick ends.
    void findWhatWakes(const ParticleSet& set, const CollisionDef& def, AwakeSet& awake,
                       PairCache& cache) {
        holdsOfWoken(set, def, awake, cache);
        wakeWhereHoldersMoved(set, def);
    }
    /// At the tick's end: those found wake (asleepCount: the sleepers, less those that woke).
    void wakeHeldSleepers(ParticleSet& set, int& asleepCount);

  private:
    /// What the sleepers that woke or went since the last sub-step held up where they
    /// slept.
    void holdsOfWoken(const ParticleSet& set, const CollisionDef& def, AwakeSet& awake,
                      PairCache& cache);
    /// The holds of now and of before, one list: a sleeper whose holder moved too far or
    /// is gone wakes when the tick ends.
    void wakeWhereHoldersMoved(const ParticleSet& set, const CollisionDef& def);
    struct Hold {
        std::uint32_t holder, held; ///< an awake particle and the sleeper it holds up
        Vec2 holderAt;              ///< where the holder was when it began to
        std::uint64_t key() const {
            return (std::uint64_t{std::min(holder, held)} << 32) | std::max(holder, held);
        }
    };
    /// A particle of `radius` at `at` holds sleeper s up: near enough for the solver, and
    /// s above it within kSupport of vertical.
    bool holdsUp(const ParticleSet& set, Vec2 at, double radius, std::uint32_t s,
                 const CollisionDef& def) const;
    /// The holds of this sub-step's contacts, and those kept from the last sub-step, in
    /// pair order; the sleepers that wake when the tick ends.
    std::vector<Hold> heldNow_, held_, heldOn_;
    std::vector<std::uint32_t> toWake_;
    Vec2 up_; ///< the up of the last impulse sub-step
};

} // namespace phys
