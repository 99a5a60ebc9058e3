#include "physics/collision/pair_cache.h"

#include "physics/collision/simd/pair_filter.h"

#include <algorithm>
#include <bit>

namespace phys {

// ---- the fat boxes ---------------------------------------------------------------------

// Room for half a radius of play (contacts push particles by up to centimetres in a pile)
// and a step of motion along the path the box was built from. Half a radius, not a whole
// one: in a packed pile the fat boxes of balls up to four radii apart overlap with a
// whole radius of play, up to three with half, so each pass filters far fewer kept pairs,
// for a few more mends while the pile still slides.
Aabb FatBoxes::fatBox(const ParticleSet& set, const Proxies& proxies, const SubstepPaths& paths,
                      std::size_t i, double h) {
    const double margin = kPlay * set.radius[i] + length(paths.path(i).v) * h;
    const Aabb& box = proxies.box(i);
    return {box.lo - Vec2{margin, margin}, box.hi + Vec2{margin, margin}};
}

void FatBoxes::build(const ParticleSet& set, const Proxies& proxies, const SubstepPaths& paths,
                     double h) {
    const std::size_t n = proxies.count();
    boxes_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        boxes_[i] = fatBox(set, proxies, paths, i, h);
    kinds_ = proxies.kinds();
    gridStale_ = true;
}

void FatBoxes::refit(const ParticleSet& set, const Proxies& proxies, const SubstepPaths& paths,
                     std::uint32_t i, double h) {
    boxes_[i] = fatBox(set, proxies, paths, i, h);
    if (!gridStale_) grid_.moved(i);
}

bool FatBoxes::findNear(const Aabb& box) {
    if (gridStale_ || grid_.movedCount() > kMostMovedInGrid) {
        grid_.build(boxes_, kinds_);
        gridStale_ = false;
    }
    near_.clear();
    return grid_.query(box, near_);
}

// ---- the kept pairs by particle -------------------------------------------------------

void KeptPairIndex::update(std::span<const ProxyPair> pairs, std::uint32_t n,
                           std::uint64_t version) {
    if (version_ == version) return;
    start_.assign(n + 1, 0u);
    for (const ProxyPair& p : pairs) {
        ++start_[p.first + 1];
        if (p.second < n) ++start_[p.second + 1];
    }
    for (std::uint32_t i = 0; i < n; ++i)
        start_[i + 1] += start_[i];
    pairsOf_.resize(start_[n]);
    fill_.assign(start_.begin(), start_.end() - 1);
    for (std::uint32_t k = 0; k < pairs.size(); ++k) {
        const ProxyPair& p = pairs[k];
        pairsOf_[fill_[p.first]++] = k;
        if (p.second < n) pairsOf_[fill_[p.second]++] = k;
    }
    version_ = version;
}

// ---- a full detection's pairs ----------------------------------------------------------

void PairCache::findPairs(const Substep& sub, const std::vector<std::uint32_t>& active,
                          Proxies& proxies, const SubstepPaths& paths) {
    staticIndex_.update(sub.shapes);
    staticHits_.reserve(sub.shapes.count()); // the most a query can return: no growth later
    for (const std::uint32_t i : strays_)    // the cache check below covers them
        strayMark_[i] = 0;
    strays_.clear();
    switch (check(sub.def, active, proxies)) {
    case CacheState::Rebuild:
        rebuild(sub, proxies, paths);
        break;
    case CacheState::Patch:
        patch(sub, proxies, paths);
        takeCachedPairsAsLive(proxies);
        break;
    case CacheState::Holds:
        break;
    }
    if (proxies.kindsChanged()) selectLivePairs(proxies);
    pairs_.resize(livePairs_.size());
    pairs_.resize(
        keepOverlapping(livePairs_, proxies.boxes(), staticIndex_.boxes(), pairs_.data()));
}

// A settled particle passes: its kind and boxes are those it passed with (or that its fat
// box was mended or rebuilt from), and the solver's box, kSpeculative radii bigger than
// the passes', stays inside a fat box grown by half a radius from either
// (Proxies::boxSettlingForSolver checks the one case where no solver did).
PairCache::CacheState PairCache::check(const CollisionDef& def,
                                       const std::vector<std::uint32_t>& active,
                                       const Proxies& proxies) {
    const std::size_t n = proxies.count();
    escaped_.clear();
    if (!valid_ || fat_.count() != n || cachedShapes_ != staticIndex_.version() ||
        cachedBroadPhase_ != def.broadPhase || cachedCellSize_ != def.gridCellSize)
        return CacheState::Rebuild;
    for (const std::uint32_t i : active) {
        const ProxyKind k = proxies.kind(i), f0 = fat_.kind(i);
        const bool fewerPairs = k == f0 || k == ProxyKind::None || f0 == ProxyKind::Moving;
        if (fewerPairs && (k == ProxyKind::None || fat_.box(i).contains(proxies.box(i)))) continue;
        if (!def.patchPairs || escaped_.size() == kMostPatched) return CacheState::Rebuild;
        escaped_.push_back(i);
    }
    return escaped_.empty() ? CacheState::Holds : CacheState::Patch;
}

void PairCache::rebuild(const Substep& sub, Proxies& proxies, const SubstepPaths& paths) {
    fat_.build(sub.set, proxies, paths, sub.h);
    findParticlePairs(sub.def);
    findStaticPairs(static_cast<std::uint32_t>(proxies.count()));
    cachedPairs_.resize(particlePairs_.size() + staticPairs_.size());
    std::merge(particlePairs_.begin(), particlePairs_.end(), staticPairs_.begin(),
               staticPairs_.end(), cachedPairs_.begin());
    takeCachedPairsAsLive(proxies);
    valid_ = true;
    cachedShapes_ = staticIndex_.version();
    cachedBroadPhase_ = sub.def.broadPhase;
    cachedCellSize_ = sub.def.gridCellSize;
    ++sub.stats.broadPhases;
}

// Particle against particle: the chosen broad phase; each gives the pairs sorted.
void PairCache::findParticlePairs(const CollisionDef& def) {
    switch (def.broadPhase) {
    case BroadPhase::Grid:
        grid_.findPairs(fat_.boxes(), fat_.kinds(), particlePairs_, def.gridCellSize);
        break;
    case BroadPhase::SortAndSweep:
        sweep_.findPairs(fat_.boxes(), fat_.kinds(), particlePairs_);
        break;
    case BroadPhase::AllPairs:
        allPairs(fat_.boxes(), fat_.kinds(), particlePairs_);
        break;
    }
}

// Particle against static shape: moving particles look up the static index. A shape's
// proxy number is slots + its index, as the narrow phase expects; these come out sorted
// too, so one merge gives the whole list in order.
void PairCache::findStaticPairs(std::uint32_t slots) {
    staticPairs_.clear();
    for (std::uint32_t i = 0; i < slots; ++i) {
        if (fat_.kind(i) != ProxyKind::Moving) continue;
        staticIndex_.query(fat_.box(i), staticHits_);
        for (const std::uint32_t s : staticHits_)
            staticPairs_.push_back({i, slots + s});
    }
}

// The cache mended where proxies escaped it: each escaped proxy gets a new fat box and
// kind, loses its kept pairs, and is tested against the fat boxes near it (or every
// proxy's if its box is too big for the grid) and looked up in the static index for new
// ones: a ball bouncing out of its box in a resting heap no longer rebuilds the heap's
// pairs, nor tests all of them. The cache stays a superset of the overlapping pairs,
// sorted, so the pairs a pass keeps, and the bits, are those a rebuild would give.
void PairCache::patch(const Substep& sub, const Proxies& proxies, const SubstepPaths& paths) {
    const auto n = static_cast<std::uint32_t>(proxies.count());
    growTo(escapedMark_, n);
    for (const std::uint32_t e : escaped_) {
        fat_.refit(sub.set, proxies, paths, e, sub.h);
        escapedMark_[e] = 1;
    }
    dropPairsOfEscaped(proxies, n);
    // Each kind went down or stayed (else the proxy escaped), and the query grid tests
    // the fat boxes' kinds at the time of the query, so it stands.
    fat_.takeKinds(proxies);
    fresh_.clear();
    for (const std::uint32_t e : escaped_)
        pairEscaped(e, n);
    for (const std::uint32_t e : escaped_)
        escapedMark_[e] = 0;
    mergePatchedPairs();
    ++sub.stats.cachePatches;
}

// The pass over every kept pair is paid anyway, so it also drops the pairs the kinds of
// now cannot make (both asleep, say), and the cache takes the kinds of now: a pile
// falling asleep otherwise drags its early pairs through every patch. A particle that
// wakes later can pair with more than its cached kind, so it escapes and is patched in
// turn.
void PairCache::dropPairsOfEscaped(const Proxies& proxies, std::uint32_t n) {
    auto dropped = [&](const ProxyPair& p) {
        const bool shape = p.second >= n;
        return escapedMark_[p.first] != 0 || (!shape && escapedMark_[p.second] != 0) ||
               !pairableAs(proxies.kinds(), p);
    };
    std::erase_if(particlePairs_, dropped);
    std::erase_if(staticPairs_, dropped);
}

// Escaped proxy e's pairs with the fat boxes near it, into fresh_, and with the shapes.
void PairCache::pairEscaped(std::uint32_t e, std::uint32_t n) {
    const ProxyKind ke = fat_.kind(e);
    if (ke == ProxyKind::None) return;
    const Aabb& box = fat_.box(e);
    // Branchless: which proxies overlap is as good as random.
    auto test = [&](std::uint32_t c, std::size_t& found) {
        unsigned hit = (c != e) & pairable(ke, fat_.kind(c));
        hit &= !(escapedMark_[c] != 0 && c < e); // a pair of two escaped ones: once
        hit &= box.overlapsBranchless(fat_.box(c));
        fresh_[found] = c < e ? ProxyPair{c, e} : ProxyPair{e, c};
        found += hit;
    };
    std::size_t found = fresh_.size();
    if (fat_.findNear(box)) {
        fresh_.resize(found + fat_.near().size());
        for (const std::uint32_t c : fat_.near())
            test(c, found);
    } else {
        fresh_.resize(found + n);
        for (std::uint32_t c = 0; c < n; ++c)
            test(c, found);
    }
    fresh_.resize(found);
    if (ke == ProxyKind::Moving) {
        staticIndex_.query(box, staticHits_);
        for (const std::uint32_t s : staticHits_)
            staticPairs_.push_back({e, n + s});
    }
}

void PairCache::mergePatchedPairs() {
    std::sort(fresh_.begin(), fresh_.end());
    // (std::inplace_merge would take a buffer from the heap each time.)
    mergedPairs_.resize(particlePairs_.size() + fresh_.size());
    std::merge(particlePairs_.begin(), particlePairs_.end(), fresh_.begin(), fresh_.end(),
               mergedPairs_.begin());
    particlePairs_.swap(mergedPairs_);
    std::sort(staticPairs_.begin(), staticPairs_.end());
    cachedPairs_.resize(particlePairs_.size() + staticPairs_.size());
    std::merge(particlePairs_.begin(), particlePairs_.end(), staticPairs_.begin(),
               staticPairs_.end(), cachedPairs_.begin());
}

// The cached pairs the proxies can make with the kinds of now (at least one moving, none
// gone; a shape pairs only with a moving particle), again only when a kind changed: once
// a tick as particles fall asleep, not once a pass. The full cache is kept, so a particle
// that falls asleep and wakes again while its box stays in its fat box gets its pairs
// back without a broad phase (until a patch drops them: it is then patched).
// While kinds only fall (particles fall asleep: Moving to Resting), a pair live now was
// live before, so the live pairs of now are those of before that the kinds still make, in
// the same order: filtered from the last live pairs, not from the whole cache. As a pile
// falls asleep, a tick then filters a shrinking list, not every kept pair each tick. Which
// pairs stay is a coin toss: each is written and the count moves on only if it stays.
void PairCache::selectLivePairs(Proxies& proxies) {
    const bool rose = proxies.kindsRose();
    proxies.takeKindsAsLive();
    const std::vector<ProxyKind>& live = proxies.liveKinds();
    const std::vector<ProxyPair>& from = rose ? cachedPairs_ : livePairs_;
    const std::size_t count = from.size();
    if (rose) livePairs_.resize(count);
    const ProxyPair* in = from.data();
    ProxyPair* out = livePairs_.data(); // in place when from is livePairs_: out never passes in
    std::size_t kept = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const ProxyPair p = in[k];
        out[kept] = p;
        kept += pairableAs(live, p) ? 1 : 0;
    }
    livePairs_.resize(kept);
}

// Right after a build or a patch every cached pair can pair with the kinds of the cache.
void PairCache::takeCachedPairsAsLive(Proxies& proxies) {
    livePairs_ = cachedPairs_;
    proxies.takeKindsAsLive();
    ++cachedPairsVersion_;
}

// ---- a later pass's pairs --------------------------------------------------------------

bool PairCache::changedPairs(const Substep& sub, const std::vector<std::uint32_t>& changed,
                             Proxies& proxies, const SubstepPaths& paths) {
    if (!noteStrays(sub, changed, proxies, paths)) return false;
    indexCachedPairs(static_cast<std::uint32_t>(proxies.count()));
    // The pairs of each changed particle whose exact boxes overlap, from its kept pairs
    // and the strays, or, for a stray, from every proxy.
    pairs_.clear();
    if (strays_.empty() && markKeptPairs(changed, proxies)) return true;
    for (const std::uint32_t i : changed) {
        if (proxies.kind(i) == ProxyKind::None) continue;
        if (strayMark_[i])
            pairsOfStray(i, proxies);
        else
            pairsOfChanged(i, proxies);
    }
    // A pair of two changed particles, or found from both sides, once.
    std::sort(pairs_.begin(), pairs_.end());
    pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
    return true;
}

// The kept pairs cover a changed particle while its box stays inside its fat box and it
// can pair with no more than when they were selected. One that left them (it bounced out
// of its fat box, or woke) is a stray: its pairs are found by testing its box against
// every other, and a changed particle tests its box against the strays as well as its kept
// pairs. More than kMostStrays run the full detection instead (false).
bool PairCache::noteStrays(const Substep& sub, const std::vector<std::uint32_t>& changed,
                           Proxies& proxies, const SubstepPaths& paths) {
    const std::size_t n = sub.set.slots();
    if (strayMark_.size() < n) strayMark_.resize(n, 0);
    for (const std::uint32_t i : changed) {
        proxies.rebuild(sub.set, paths, sub.def, i, sub.h);
        const ProxyKind kind = proxies.kind(i);
        const bool covered = kind == proxies.liveKinds()[i] &&
                             (kind == ProxyKind::None || fat_.box(i).contains(proxies.box(i)));
        if (covered || strayMark_[i]) continue;
        if (strays_.size() == kMostStrays) return false;
        strays_.push_back(i);
        strayMark_[i] = 1;
    }
    return true;
}

// With no strays every pair a later pass tests is a kept pair, and the kept pairs are in
// pair order: marking each by its place in the cache, and reading the marks in order,
// gives the pairs sorted and each once, where a sort of a pile's few hundred pairs waited
// on its mispredicted comparisons. Which pairs overlap is a coin toss, so a pair's mark is
// set without a branch on it. The marks cost a pass over a bit a kept pair: with few
// changed particles among many kept pairs, the sort is the cheaper and this returns false.
bool PairCache::markKeptPairs(const std::vector<std::uint32_t>& changed, const Proxies& proxies) {
    if (cachedPairs_.size() > 256 * changed.size()) return false;
    keptMarks_.assign((cachedPairs_.size() + 63) / 64, 0);
    std::uint64_t* const marks = keptMarks_.data();
    for (const std::uint32_t i : changed) {
        if (proxies.kind(i) == ProxyKind::None) continue;
        for (const std::uint32_t at : index_.of(i)) {
            const std::uint64_t keep = keptPairMeets(i, cachedPairs_[at], proxies) ? 1 : 0;
            marks[at / 64] |= keep << (at % 64);
        }
    }
    for (std::size_t word = 0; word < keptMarks_.size(); ++word)
        for (std::uint64_t bits = marks[word]; bits != 0; bits &= bits - 1)
            pairs_.push_back(
                cachedPairs_[64 * word + static_cast<std::size_t>(std::countr_zero(bits))]);
    return true;
}

// Changed particle i's kept pairs that meet, and its pairs with the strays.
void PairCache::pairsOfChanged(std::uint32_t i, const Proxies& proxies) {
    for (const std::uint32_t k : index_.of(i)) {
        const ProxyPair p = cachedPairs_[k];
        if (keptPairMeets(i, p, proxies)) pairs_.push_back(p);
    }
    for (const std::uint32_t e : strays_)
        if (e != i && overlapping(i, e, proxies))
            pairs_.push_back(i < e ? ProxyPair{i, e} : ProxyPair{e, i});
}

// As patch tests an escaped proxy, by the exact box, branchless (which proxies overlap is
// as good as random). Every other proxy that is not a stray has its exact box inside its
// fat box, so its pair with i is among the fat boxes near i's box; the other strays are
// tested as well (a pair found twice is kept once by changedPairs).
void PairCache::pairsOfStray(std::uint32_t i, const Proxies& proxies) {
    const auto n = static_cast<std::uint32_t>(proxies.count());
    std::size_t found = pairs_.size();
    auto test = [&](std::uint32_t c) {
        pairs_[found] = c < i ? ProxyPair{c, i} : ProxyPair{i, c};
        found += (c != i) & overlapping(i, c, proxies);
    };
    if (fat_.findNear(proxies.box(i))) {
        pairs_.resize(found + fat_.near().size() + strays_.size());
        for (const std::uint32_t c : fat_.near())
            test(c);
        for (const std::uint32_t c : strays_)
            test(c);
    } else {
        pairs_.resize(found + n);
        for (std::uint32_t c = 0; c < n; ++c)
            test(c);
    }
    pairs_.resize(found);
    if (proxies.kind(i) != ProxyKind::Moving) return; // a shape pairs only with a moving one
    staticIndex_.query(proxies.box(i), staticHits_);
    for (const std::uint32_t s : staticHits_)
        pairs_.push_back({i, n + s});
}

// Kept pair p of changed particle i is one of this pass: live, and its exact boxes (i's
// and the other particle's or the shape's) overlap.
bool PairCache::keptPairMeets(std::uint32_t i, const ProxyPair& p, const Proxies& proxies) const {
    const auto n = static_cast<std::uint32_t>(proxies.count());
    if (!pairableAs(proxies.liveKinds(), p)) return false;
    return p.second >= n ? proxies.box(i).overlapsBranchless(staticIndex_.box(p.second - n))
                         : overlapping(p.first, p.second, proxies);
}

// Proxies i and j (particles) may pair, by their kinds and exact boxes: both tests, with
// no branch between them (which pairs overlap is a coin toss).
bool PairCache::overlapping(std::uint32_t i, std::uint32_t j, const Proxies& proxies) {
    const unsigned kinds = pairable(proxies.kind(i), proxies.kind(j));
    const unsigned boxes = proxies.box(i).overlapsBranchless(proxies.box(j));
    return (kinds & boxes) != 0;
}

} // namespace phys
