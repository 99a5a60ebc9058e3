#include "physics/collision/awake_set.h"

#include "physics/collision/simd/settled_scan.h"

namespace phys {

// One pass over the flags a sub-step (and over a sleeper's position and radius) finds the
// particles to work on, where a dozen passes over every particle did the work. A particle
// is settled when it is asleep at rest (velocity +0, as falling asleep leaves it) or its
// slot is empty, and its state is the one a sub-step worked on last, bit for bit, with
// the same tolerance (its boxes reach that far; at rest, they do not depend on the step),
// and no contact has changed its path since (workOn). A sleeper the last sub-step worked
// on awake, or one that woke, has other flags than its record, so it is active.
void AwakeSet::select(const ParticleSet& set, const CollisionDef& def, bool all,
                      CollisionStats& stats) {
    const std::size_t n = set.slots();
    settledFlags_.resize(n, kUnsettled);
    settledX_.resize(n), settledY_.resize(n), settledRadius_.resize(n);
    activeMark_.resize(n);
    const bool sameTolerance = sameBits(def.toiTolerance, settledTolerance_);
    settledTolerance_ = def.toiTolerance;
    active_.resize(n);
    std::uint32_t* const active = active_.data();
    std::size_t count = 0;
    settledAsleep_ = 0;
    growTo(sleptAt_, n);
    wokeOrGone_.clear();
    // A sleeper that woke or went since the last sub-step (so one that is not settled).
    auto noteWaking = [&](std::size_t i, std::uint32_t f) {
        if (sleptAt_[i].radius > 0.0 && (f & (kAlive | kSleeping)) != (kAlive | kSleeping))
            wokeOrGone_.push_back(static_cast<std::uint32_t>(i));
    };
    const SettledRecords records{set.flags.data(),     set.vx.data(),    set.vy.data(),
                                 set.px.data(),        set.py.data(),    set.radius.data(),
                                 settledFlags_.data(), settledX_.data(), settledY_.data(),
                                 settledRadius_.data()};
    // Where a scan stops at once, the slots are likely awake: the next four one at a time.
    std::size_t scanFrom = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!all && sameTolerance && i >= scanFrom) {
            const std::size_t from = i;
            i = skipSettled(records, i, n, kAlive, kSleeping, activeMark_.data(), settledAsleep_);
            if (i == n) break;
            scanFrom = i == from ? i + 4 : i + 1;
        }
        const std::uint32_t f = set.flags[i];
        const bool rests =
            !all && (!(f & kAlive) || ((f & kSleeping) && isPositiveZero({set.vx[i], set.vy[i]})));
        active[count] = static_cast<std::uint32_t>(i);
        if (!rests) { // awake (or every particle): active, and not settled after
            noteWaking(i, f);
            activeMark_[i] = 1;
            ++count;
            settledFlags_[i] = kUnsettled;
            continue;
        }
        const bool settled =
            sameTolerance && f == settledFlags_[i] && sameBits(set.px[i], settledX_[i]) &&
            sameBits(set.py[i], settledY_[i]) && sameBits(set.radius[i], settledRadius_[i]);
        activeMark_[i] = settled ? 0 : 1;
        if (settled) {
            settledAsleep_ += (f & kAlive) ? 1 : 0;
            continue;
        }
        noteWaking(i, f);
        ++count;
        settledFlags_[i] = f;
        settledX_[i] = set.px[i], settledY_[i] = set.py[i], settledRadius_[i] = set.radius[i];
    }
    active_.resize(count);
    stats.active += static_cast<int>(count);
}

void AwakeSet::forgetWoken() {
    for (const std::uint32_t a : wokeOrGone_)
        sleptAt_[a].radius = 0.0;
    wokeOrGone_.clear();
}

} // namespace phys
