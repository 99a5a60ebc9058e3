// Sleepers wake when what holds them up moves off.
//
// A sleeper is immovable to the passes and the contact solver: it stays where it fell
// asleep, whatever holds it up. Left at that, a sleeping column stood in the air when the
// ball under it was knocked away or removed, and the sleepers of a pile hung over the
// hollows its awake part slid into. So a sleeper held up by an awake particle (a contact of
// the solver whose normal is within kSupport of vertical) wakes when the holder
//   moves     farther from where it began to hold it up than a sleeper may stray while it
//             falls asleep (sleepSpeed * sleepTime, updateSleep's rule): it slid away,
//             fell or was knocked, and the sleeper would have gone with it;
//   leaves    or is removed, so that nothing near enough holds the sleeper up.
// The holds are those of the solver's contacts (collectHold), those of a particle that
// falls asleep on awake ones (holdsOfNewSleeper: the passes alone may hold it there, with
// no solver), and those of a sleeper that wakes or is removed: from the place it slept,
// it held up the sleepers that rested on it (holdsOfWoken; asleep, the two were no
// contact of anything).
// A holder that stays put keeps the sleeper asleep, as does one that falls asleep under
// it; what rests on a sleeper never wakes it (a sleeping pile carries its top layer).
// Box2D wakes a whole island when any of it moves; this wakes only what loses its support,
// so a settled heap under a rolling ball stays asleep.
//
// The wakes take effect at the end of the tick (wakeHeldSleepers, from updateSleep), not
// where they are found: a sub-step works on the particles it selected at its start, and
// every particle sees the same sleepers until the tick ends, whichever it works on.
#include "physics/collision/simd/pair_filter.h"
#include "physics/collision/particle_collisions.h"

#include <algorithm>

namespace phys {

bool ParticleCollisions::holdsUp(const ParticleSet& set, Vec2 at, double radius, std::uint32_t s,
                                 const CollisionDef& def) const {
    const Vec2 d = set.position(s) - at;
    const double reach = radius + set.radius[s], l = length(d);
    return nearEnough(reach - l, reach, def.toiTolerance, kSpeculative) &&
           dot(d, up_) > kSupport * l;
}

void ParticleCollisions::collectHold(const ParticleSet& set, const RelaxContact& c) {
    if (c.support == 0) return;
    const std::uint32_t held = c.support == 1 ? c.a : c.b;
    const std::uint32_t holder = c.support == 1 ? c.b : c.a;
    if (asleep(set, held) && moving(set, holder))
        heldNow_.push_back({holder, held, {x0_[holder], y0_[holder]}});
}

void ParticleCollisions::holdsOfNewSleeper(const ParticleSet& set, const CollisionDef& def,
                                           std::uint32_t s) {
    auto collect = [&](std::uint32_t a) {
        if (a != s && moving(set, a) && holdsUp(set, set.position(a), set.radius[a], s, def))
            held_.push_back({a, s, set.position(a)});
    };
    // Awake until now, it pairs in the kept pairs with everything near it.
    const auto n = static_cast<std::uint32_t>(set.slots());
    if (cacheValid_ && boxes_.size() == n) {
        indexCachedPairs();
        for (std::uint32_t k = pairStart_[s]; k < pairStart_[s + 1]; ++k) {
            const ProxyPair p = cachedPairs_[pairsOf_[k]];
            const std::uint32_t other = p.first == s ? p.second : p.first;
            if (other < n) collect(other);
        }
    } else {
        for (std::uint32_t a = 0; a < n; ++a)
            collect(a);
    }
}

void ParticleCollisions::sortHolds() {
    std::sort(held_.begin(), held_.end(),
              [](const Hold& x, const Hold& y) { return x.key() < y.key(); });
    held_.erase(std::unique(held_.begin(), held_.end(),
                            [](const Hold& x, const Hold& y) { return x.key() == y.key(); }),
                held_.end());
}

void ParticleCollisions::holdsOfWoken(const ParticleSet& set, const CollisionDef& def) {
    if (wokeOrGone_.empty()) return;
    const std::size_t before = held_.size();
    for (const std::uint32_t a : wokeOrGone_) {
        const Place at = sleptAt_[a];
        sleptAt_[a].radius = 0.0;
        const Vec2 place{at.x, at.y};
        auto collect = [&](std::uint32_t s) {
            if (s != a && (set.flags[s] & kAlive) && asleep(set, s) &&
                holdsUp(set, place, at.radius, s, def))
                held_.push_back({a, s, place});
        };
        // The fat box of a sleeper it held meets its place grown by what the solver
        // reaches on its own side: a fat box is half its particle's radius wider than the
        // particle, more than the tenth the solver reaches on the sleeper's side. (Every
        // particle, if the grid cannot say.)
        const double reach = (1.0 + kSpeculative) * at.radius + def.toiTolerance;
        if (cacheValid_ && nearFatBoxes({place - Vec2{reach, reach}, place + Vec2{reach, reach}})) {
            for (const std::uint32_t s : near_)
                collect(s);
        } else {
            for (std::uint32_t s = 0; s < set.slots(); ++s)
                collect(s);
        }
    }
    wokeOrGone_.clear();
    if (held_.size() != before) sortHolds();
}

void ParticleCollisions::wakeWhereHoldersMoved(const ParticleSet& set, const CollisionDef& def) {
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
            if (asleep(set, heldNow_[j].held)) goOn(heldNow_[j]);
            ++j;
            continue;
        }
        const Hold h = held_[i++];
        const bool contact = now && heldNow_[j].key() == h.key(); // held still
        if (contact) ++j;
        if (h.held >= set.slots() || !(set.flags[h.held] & kAlive) || !asleep(set, h.held))
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

void ParticleCollisions::wakeHeldSleepers(ParticleSet& set, int& asleepCount) {
    for (const std::uint32_t s : toWake_) {
        if (!(set.flags[s] & kSleeping)) continue; // listed twice
        set.flags[s] &= ~kSleeping;
        asleepCount -= (set.flags[s] & kAlive) ? 1 : 0;
    }
    toWake_.clear();
}

} // namespace phys
