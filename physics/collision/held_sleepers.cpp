#include "physics/collision/held_sleepers.h"

#include "physics/collision/awake_set.h"
#include "physics/collision/pair_cache.h"
#include "physics/collision/proxies.h"
#include "physics/collision/simd/pair_filter.h"

#include <algorithm>

namespace phys {

bool HeldSleepers::holdsUp(const ParticleSet& set, Vec2 at, double radius, std::uint32_t s,
                           const CollisionDef& def) const {
    const Vec2 d = set.position(s) - at;
    const double reach = radius + set.radius[s], l = length(d);
    return nearEnough(reach - l, reach, def.toiTolerance, kSpeculative) &&
           dot(d, up_) > kSupport * l;
}

void HeldSleepers::noteSolverContact(const ParticleSet& set, const SolverContact& c,
                                     const SubstepPaths& paths) {
    if (c.support == 0) return;
    const std::uint32_t held = c.support == 1 ? c.a : c.b;
    const std::uint32_t holder = c.support == 1 ? c.b : c.a;
    if (wakeableSleeper(set, held) && movable(set, holder))
        heldNow_.push_back({holder, held, paths.start(holder)});
}

void HeldSleepers::holdsOfNewSleeper(const ParticleSet& set, const CollisionDef& def,
                                     std::uint32_t s, PairCache& cache, const Proxies& proxies) {
    auto collect = [&](std::uint32_t a) {
        if (a != s && movable(set, a) && holdsUp(set, set.position(a), set.radius[a], s, def))
            held_.push_back({a, s, set.position(a)});
    };
    // Awake until now, it pairs in the kept pairs with everything near it.
    const auto n = static_cast<std::uint32_t>(set.slots());
    if (!cache.forEachKeptPartner(s, proxies, n, collect))
        for (std::uint32_t a = 0; a < n; ++a)
            collect(a);
}

void HeldSleepers::sortHolds() {
    std::sort(held_.begin(), held_.end(),
              [](const Hold& x, const Hold& y) { return x.key() < y.key(); });
    held_.erase(std::unique(held_.begin(), held_.end(),
                            [](const Hold& x, const Hold& y) { return x.key() == y.key(); }),
                held_.end());
}

void HeldSleepers::holdsOfWoken(const ParticleSet& set, const CollisionDef& def, AwakeSet& awake,
                                PairCache& cache) {
    if (awake.wokeOrGone().empty()) return;
    const std::size_t before = held_.size();
    for (const std::uint32_t a : awake.wokeOrGone()) {
        const AwakeSet::Place at = awake.sleptAt(a);
        const Vec2 place{at.x, at.y};
        auto collect = [&](std::uint32_t s) {
            if (s != a && (set.flags[s] & kAlive) && wakeableSleeper(set, s) &&
                holdsUp(set, place, at.radius, s, def))
                held_.push_back({a, s, place});
        };
        // The fat box of a sleeper it held meets its place grown by what the solver
        // reaches on its own side: a fat box is half its particle's radius wider than the
        // particle, more than the tenth the solver reaches on the sleeper's side. (Every
        // particle, if the grid cannot say.)
        const double reach = (1.0 + kSpeculative) * at.radius + def.toiTolerance;
        if (cache.findNear({place - Vec2{reach, reach}, place + Vec2{reach, reach}})) {
            for (const std::uint32_t s : cache.near())
                collect(s);
        } else {
            for (std::uint32_t s = 0; s < set.slots(); ++s)
                collect(s);
        }
    }
    awake.forgetWoken();
    if (held_.size() != before) sortHolds();
}

void HeldSleepers::wakeWhereHoldersMoved(const ParticleSet& set, const CollisionDef& def) {
    const double stray = def.sleepSpeed * def.sleepTime;
    // A hold goes on while its holder stays within the stray of where it began to hold.
    auto goOn = [&](const Hold& h) {
        if (lengthSquared(set.position(h.holder) - h.holderAt) > stray * stray)
            toWake_.push_back(h.held);
        else
            heldOn_.push_back(h);
    };
    heldOn_.clear();
    std::size_t i = 0, j = 0;
    while (i < held_.size() || j < heldNow_.size()) {
        const bool before = i < held_.size(), now = j < heldNow_.size();
        if (now && (!before || heldNow_[j].key() < held_[i].key())) { // a contact's new hold
            if (wakeableSleeper(set, heldNow_[j].held)) goOn(heldNow_[j]);
            ++j;
            continue;
        }
        const Hold h = held_[i++];
        const bool contact = now && heldNow_[j].key() == h.key(); // held still
        if (contact) ++j;
        if (h.held >= set.slots() || !(set.flags[h.held] & kAlive) || !wakeableSleeper(set, h.held))
            continue; // woke, or the set was cleared since
        if (!contact) {
            const bool gone = h.holder >= set.slots() || !(set.flags[h.holder] & kAlive);
            if (!gone && (set.flags[h.holder] & kSleeping)) continue; // asleep under it
            if (gone || !holdsUp(set, set.position(h.holder), set.radius[h.holder], h.held, def)) {
                toWake_.push_back(h.held); // removed, or left within the step
                continue;
            }
        }
        goOn(h); // from where it began to hold
    }
    held_.swap(heldOn_);
    heldNow_.clear();
}

void HeldSleepers::wakeHeldSleepers(ParticleSet& set, int& asleepCount) {
    for (const std::uint32_t s : toWake_) {
        if (!(set.flags[s] & kSleeping)) continue; // listed twice
        set.flags[s] &= ~kSleeping;
        asleepCount -= (set.flags[s] & kAlive) ? 1 : 0;
    }
    toWake_.clear();
}

} // namespace phys
