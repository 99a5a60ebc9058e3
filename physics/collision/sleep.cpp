#include "physics/collision/sleep.h"

#include "physics/collision/awake_set.h"
#include "physics/collision/held_sleepers.h"

namespace phys {

void Sleep::update(ParticleSet& set, const CollisionDef& def, double dt,
                   const std::vector<std::uint8_t>& tethered, AwakeSet& awake, HeldSleepers& held,
                   PairCache& cache, const Proxies& proxies, CollisionStats& stats) {
    const std::size_t n = set.slots();
    growTo(timer_, n), growTo(rested_, n), growTo(anchor_, n);
    auto restartWindow = [&](std::size_t i) {
        timer_[i] = 0.0;
        anchor_[i] = set.position(i);
    };
    if (timersStale_) { // what update would have done in the ticks without contacts
        for (std::size_t i = 0; i < n; ++i)
            if (!(set.flags[i] & kSleeping)) restartWindow(i);
        timersStale_ = false;
    }
    const double stray = def.sleepSpeed * def.sleepTime;  // m: the window's allowed drift
    int asleep = static_cast<int>(awake.settledAsleep()); // settled: asleep, and stays so
    const std::size_t holds = held.holds();
    for (const std::uint32_t i : awake.active()) {
        if (set.flags[i] & kSleeping) {
            asleep += (set.flags[i] & kAlive) ? 1 : 0;
            continue;
        }
        const bool resting =
            def.sleep && rested_[i] && !(i < tethered.size() && tethered[i]) && movable(set, i);
        rested_[i] = 0;
        const bool slow = lengthSquared(set.velocity(i)) < def.sleepSpeed * def.sleepSpeed;
        const bool stayed = lengthSquared(set.position(i) - anchor_[i]) <= stray * stray;
        if (!resting || !(slow || stayed)) {
            restartWindow(i);
            continue;
        }
        if (!stayed) anchor_[i] = set.position(i); // slow but drifting: measure anew
        timer_[i] += dt;
        if (timer_[i] >= def.sleepTime) {
            set.flags[i] = (set.flags[i] | kSleeping) & ~kHistory;
            awake.fellAsleep(i, {set.px[i], set.py[i], set.radius[i]});
            held.holdsOfNewSleeper(set, def, i, cache, proxies);
            set.vx[i] = set.vy[i] = 0.0;
            set.halfVx[i] = set.halfVy[i] = 0.0;
            restartWindow(i);
            ++asleep;
        }
    }
    if (held.holds() != holds) held.sortHolds(); // a new sleeper held up by awake particles
    held.wakeHeldSleepers(set, asleep);
    stats.sleeping = asleep;
}

} // namespace phys
