// The passes after the first of a sub-step (ParticleCollisions::impulsePhase) detect
// again only what the pass before them changed.
//
// A pass resolves its candidates in time order, and all it changes is the paths of the
// particles it bounced, stopped or put to rest (markChanged): their kinds, boxes and
// times of impact. So the next pass's candidates are of two kinds:
//   changed    pairs with a particle whose path changed: tested again, the kept pairs of
//              each such particle filtered by its new box, then the time of impact;
//   carried    pairs of two unchanged particles: their paths, boxes and time of impact
//              are those of the last pass, so such a pair is a candidate again exactly
//              when it was one then and its resolution changed neither path. That is a
//              resting pair the pass left to the contact solver: a static contact, an
//              impact or a resting contact always changes a path, and a candidate that
//              came to nothing did so because a path had changed.
// These are the candidates a detection over every particle finds, at the same times;
// listed in pair order they keep its tie order too, so the passes resolve the same
// contacts in the same order, to the bit. A pass then costs what the pass before it
// changed, not the world: in a heap of 4,000 balls whose last awake ones bounce for all
// eight passes of a step, a later pass re-tests the pairs of about 15 particles and
// carries some 460 resting pairs, where a full detection boxed 4,000 particles and
// filtered 18,000 kept pairs.
// The kept pairs cover a changed particle while its box stays inside its fat box and it
// can pair with no more than when they were selected. One that left them (it bounced
// out of its fat box, or woke) is a stray until the next full detection mends the cache:
// its pairs are found by testing its box against every other, and a changed particle
// tests its box against the strays as well as its kept pairs. More than kMostStrays run
// the full detection instead.
#include "physics/collision/particle_collisions.h"

#include <algorithm>
#include <bit>

namespace phys {

bool ParticleCollisions::detectChanges(const ParticleSet& set, const StaticShapes& shapes,
                                       const CollisionDef& def, double h) {
    const auto t0 = clock_.now(); // profile only
    const auto n = static_cast<std::uint32_t>(set.slots());
    if (!cacheValid_ || boxes_.size() != n || liveKinds_.size() != n) return false;
    // Carried: the resting pairs left to the solver that no contact changed since, in
    // the pair order of the last pass's candidates.
    carried_.clear();
    for (std::size_t k = 0; k < candidates_.size(); ++k) {
        const Candidate& c = candidates_[k];
        if (leftToSolver_[k] && pathChanged_[c.a] != pass_ && pathChanged_[c.b] != pass_) {
            carried_.push_back(c);
            carried_.back().carried = true;
        }
    }
    if (strayMark_.size() < n) strayMark_.resize(n, 0);
    for (const std::uint32_t i : changed_) {
        buildProxy(set, def, i, h, false, 0.0);
        const bool covered = kinds_[i] == liveKinds_[i] &&
                             (kinds_[i] == ProxyKind::None || fatBoxes_[i].contains(boxes_[i]));
        if (covered || strayMark_[i]) continue;
        if (strays_.size() == kMostStrays) return false;
        strays_.push_back(i);
        strayMark_[i] = 1;
    }
    indexCachedPairs();

    // Changed: the pairs of each changed particle whose exact boxes overlap, from its
    // kept pairs and the strays, or, for a stray, from every proxy.
    pairs_.clear();
    if (strays_.empty() && markKeptPairs()) return finishLaterPass(set, shapes, def, h, t0);
    for (const std::uint32_t i : changed_) {
        if (kinds_[i] == ProxyKind::None) continue;
        if (strayMark_[i]) {
            pairsOfStray(i);
            continue;
        }
        for (std::uint32_t k = pairStart_[i]; k < pairStart_[i + 1]; ++k) {
            const ProxyPair p = cachedPairs_[pairsOf_[k]];
            if (keptPairMeets(i, p)) pairs_.push_back(p);
        }
        for (const std::uint32_t e : strays_)
            if (e != i && overlapping(i, e))
                pairs_.push_back(i < e ? ProxyPair{i, e} : ProxyPair{e, i});
    }
    // A pair of two changed particles, or found from both sides, once.
    std::sort(pairs_.begin(), pairs_.end());
    pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
    return finishLaterPass(set, shapes, def, h, t0);
}

// With no strays every pair a later pass tests is a kept pair, and the kept pairs are
// in pair order: marking each by its place in the cache, and reading the marks in
// order, gives the pairs sorted and each once, where a sort of a pile's 200-odd pairs
// waited on its mispredicted comparisons (a tick's later passes took 44 us once the
// 2,000-ball pile began to fall asleep, 14 us before). Which pairs overlap is a coin toss,
// so a pair's mark is set without a branch on it. The marks cost a pass over a bit a kept
// pair: with few changed particles among many kept pairs, the sort is the cheaper and
// this returns false.
bool ParticleCollisions::markKeptPairs() {
    if (cachedPairs_.size() > 256 * changed_.size()) return false;
    keptMarks_.assign((cachedPairs_.size() + 63) / 64, 0);
    std::uint64_t* const marks = keptMarks_.data();
    for (const std::uint32_t i : changed_) {
        if (kinds_[i] == ProxyKind::None) continue;
        for (std::uint32_t k = pairStart_[i]; k < pairStart_[i + 1]; ++k) {
            const std::uint32_t at = pairsOf_[k];
            const std::uint64_t keep = keptPairMeets(i, cachedPairs_[at]) ? 1 : 0;
            marks[at / 64] |= keep << (at % 64);
        }
    }
    for (std::size_t word = 0; word < keptMarks_.size(); ++word)
        for (std::uint64_t bits = marks[word]; bits != 0; bits &= bits - 1)
            pairs_.push_back(
                cachedPairs_[64 * word + static_cast<std::size_t>(std::countr_zero(bits))]);
    return true;
}

// The rest of a later pass: the candidates of the changed pairs, merged with those
// carried, in the order they are resolved.
bool ParticleCollisions::finishLaterPass(const ParticleSet& set, const StaticShapes& shapes,
                                         const CollisionDef& def, double h,
                                         PhaseClock::TimePoint t0) {
    stats_.pairs += static_cast<int>(pairs_.size());
    addCandidates(set, shapes, def, h);

    auto pairOrder = [](const Candidate& x, const Candidate& y) {
        return x.a < y.a || (x.a == y.a && x.proxy < y.proxy);
    };
    mergedCandidates_.resize(candidates_.size() + carried_.size());
    std::merge(candidates_.begin(), candidates_.end(), carried_.begin(), carried_.end(),
               mergedCandidates_.begin(), pairOrder);
    candidates_.swap(mergedCandidates_);

    orderCandidates();
    ++pass_;
    ++stats_.changesOnly;
    detectMicros_ += clock_.microsSince(t0);
    return true;
}

bool ParticleCollisions::keptPairMeets(std::uint32_t i, const ProxyPair& p) const {
    const auto n = static_cast<std::uint32_t>(boxes_.size());
    if (!isLive(p)) return false;
    return p.second >= n ? boxes_[i].overlapsBranchless(staticIndex_.box(p.second - n))
                         : overlapping(p.first, p.second);
}

bool ParticleCollisions::overlapping(std::uint32_t i, std::uint32_t j) const {
    // Both tests, with no branch between them (which pairs overlap is a coin toss).
    const unsigned kinds = pairable(kinds_[i], kinds_[j]);
    const unsigned boxes = boxes_[i].overlapsBranchless(boxes_[j]);
    return (kinds & boxes) != 0;
}

// As patchPairCache tests an escaped proxy, by the exact box, branchless (which proxies
// overlap is as good as random). Every other proxy that is not a stray has its exact box
// inside its fat box, so its pair with i is among the fat boxes near i's box; the other
// strays are tested as well (a pair found twice is kept once by detectChanges).
void ParticleCollisions::pairsOfStray(std::uint32_t i) {
    const auto n = static_cast<std::uint32_t>(boxes_.size());
    std::size_t found = pairs_.size();
    auto test = [&](std::uint32_t c) {
        pairs_[found] = c < i ? ProxyPair{c, i} : ProxyPair{i, c};
        found += (c != i) & overlapping(i, c);
    };
    if (nearFatBoxes(boxes_[i])) {
        pairs_.resize(found + near_.size() + strays_.size());
        for (const std::uint32_t c : near_)
            test(c);
        for (const std::uint32_t c : strays_)
            test(c);
    } else {
        pairs_.resize(found + n);
        for (std::uint32_t c = 0; c < n; ++c)
            test(c);
    }
    pairs_.resize(found);
    if (kinds_[i] != ProxyKind::Moving) return; // a shape pairs only with a moving particle
    staticIndex_.query(boxes_[i], staticHits_);
    for (const std::uint32_t s : staticHits_)
        pairs_.push_back({i, n + s});
}

// The cached pairs by particle, as offsets into a flat list of pair indices: a particle's
// pairs with the shapes and with the particles on either side of the pair. A particle's
// live pairs are those of its cached pairs that the live kinds can make (isLive).
void ParticleCollisions::indexCachedPairs() {
    if (indexedVersion_ == cachedPairsVersion_) return;
    const auto n = static_cast<std::uint32_t>(boxes_.size());
    pairStart_.assign(n + 1, 0u);
    for (const ProxyPair& p : cachedPairs_) {
        ++pairStart_[p.first + 1];
        if (p.second < n) ++pairStart_[p.second + 1];
    }
    for (std::uint32_t i = 0; i < n; ++i)
        pairStart_[i + 1] += pairStart_[i];
    pairsOf_.resize(pairStart_[n]);
    pairFill_.assign(pairStart_.begin(), pairStart_.end() - 1);
    for (std::uint32_t k = 0; k < cachedPairs_.size(); ++k) {
        const ProxyPair& p = cachedPairs_[k];
        pairsOf_[pairFill_[p.first]++] = k;
        if (p.second < n) pairsOf_[pairFill_[p.second]++] = k;
    }
    indexedVersion_ = cachedPairsVersion_;
}

} // namespace phys
