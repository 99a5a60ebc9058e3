// The broad phase and its kept pairs: which proxies of the active particles and which
// static shapes may touch in this pass (pairs()).
//
// The broad phase proper (broadphase.h) runs on fattened boxes (FatBoxes: each
// particle's box grown by half its radius and a step of its motion) and its pairs are
// kept: a pass only filters them by the kinds of now and the exact boxes
// (simd/pair_filter.h), which gives exactly the pairs a broad phase over the exact boxes
// would. That holds while every exact box lies in its fat box, no proxy can pair with
// more than when its pairs were found, and nothing else changed (slots, shapes,
// settings). A proxy that went to rest (a particle fell asleep) or away only loses pairs,
// so a pile whose particles fall asleep a few at a time keeps its broad phase; one more
// movable than at the build, or whose box left its fat box, escaped the cache. A few
// escaped proxies are mended (patch); many, or any other change, rebuild the cache. A
// pile settling through eight passes a step, or resting for many steps, then costs one
// broad phase instead of one a pass.
//
// A pass after the first asks only for the pairs of the particles whose paths the pass
// before it changed (changedPairs): each one's kept pairs, filtered by its new box. One
// that left what the kept pairs cover is a stray until the next full detection mends the
// cache: its pairs are found by testing its box against every other.
#pragma once

#include "physics/collision/broadphase.h"
#include "physics/collision/collision_def.h"
#include "physics/collision/paths.h"
#include "physics/collision/proxies.h"
#include "physics/collision/substep.h"

#include <cstdint>
#include <span>
#include <vector>

namespace phys {

/// The fat boxes of the kept pairs, and a grid over them for the partners of one box.
class FatBoxes {
  public:
    /// Every proxy's fat box, from its exact box and its path.
    void build(const ParticleSet& set, const Proxies& proxies, const SubstepPaths& paths, double h);
    /// Proxy i's fat box anew, from its exact box (it escaped).
    void refit(const ParticleSet& set, const Proxies& proxies, const SubstepPaths& paths,
               std::uint32_t i, double h);
    /// The kinds the fat boxes pair with: those of now.
    void takeKinds(const Proxies& proxies) { kinds_ = proxies.kinds(); }
    std::size_t count() const { return boxes_.size(); }
    const std::vector<Aabb>& boxes() const { return boxes_; }
    const std::vector<ProxyKind>& kinds() const { return kinds_; }
    const Aabb& box(std::size_t i) const { return boxes_[i]; }
    ProxyKind kind(std::size_t i) const { return kinds_[i]; }
    /// Particle i's fat box holds `box`.
    bool holds(std::size_t i, const Aabb& box) const {
        return i < boxes_.size() && boxes_[i].contains(box);
    }
    /// The proxies whose fat boxes may overlap `box` (near()), or false: test them all.
    bool findNear(const Aabb& box);
    const std::vector<std::uint32_t>& near() const { return near_; }
    /// The grid is built anew when next asked (the fat boxes were rebuilt).
    void forgetGrid() { gridStale_ = true; }

  private:
    /// Particle i's box grown by kPlay radii and a step of its path's motion.
    static Aabb fatBox(const ParticleSet& set, const Proxies& proxies, const SubstepPaths& paths,
                       std::size_t i, double h);
    static constexpr double kPlay = 0.5; ///< radii of play in a fat box
    /// The grid is built when first needed after the boxes are, and again when many moved.
    static constexpr std::size_t kMostMovedInGrid = 128;
    std::vector<Aabb> boxes_;
    std::vector<ProxyKind> kinds_;
    BoxQueryGrid grid_;
    bool gridStale_ = true;
    std::vector<std::uint32_t> near_; ///< a query's answer
};

/// The kept pairs by particle: offsets into a flat list of their places in the cache.
class KeptPairIndex {
  public:
    /// For the pairs of cache `version` (n particles): once per build or mend.
    void update(std::span<const ProxyPair> pairs, std::uint32_t n, std::uint64_t version);
    /// The places in the cache of particle i's pairs (with shapes, and with particles on
    /// either side of the pair).
    std::span<const std::uint32_t> of(std::uint32_t i) const {
        return std::span<const std::uint32_t>(pairsOf_).subspan(start_[i],
                                                                start_[i + 1] - start_[i]);
    }

  private:
    std::vector<std::uint32_t> start_, pairsOf_, fill_;
    std::uint64_t version_ = ~std::uint64_t{0};
};

class PairCache {
  public:
    /// pairs(): the pairs of the proxies (and of the moving proxies with the static
    /// shapes) whose exact boxes overlap, sorted, from the kept pairs (mended or rebuilt
    /// first where they no longer cover the proxies).
    void findPairs(const Substep& sub, const std::vector<std::uint32_t>& active, Proxies& proxies,
                   const SubstepPaths& paths);
    /// pairs(): the overlapping pairs of the `changed` particles (their proxies rebuilt
    /// first), sorted, each once; false when too many left what the kept pairs cover (the
    /// full detection, findPairs, is then due).
    bool changedPairs(const Substep& sub, const std::vector<std::uint32_t>& changed,
                      Proxies& proxies, const SubstepPaths& paths);
    const std::vector<ProxyPair>& pairs() const { return pairs_; }

    /// The kept pairs cover `proxies` (the passes may detect only changes).
    bool covers(const Proxies& proxies, std::size_t slots) const {
        return valid_ && proxies.count() == slots && proxies.liveKinds().size() == slots;
    }
    /// Calls f(other) for each particle that particle s pairs with in the kept pairs;
    /// false (nothing called) when the cache does not cover `proxies`.
    template <class F>
    bool forEachKeptPartner(std::uint32_t s, const Proxies& proxies, std::size_t slots, F&& f) {
        if (!(valid_ && proxies.count() == slots)) return false;
        indexCachedPairs(static_cast<std::uint32_t>(slots));
        for (const std::uint32_t k : index_.of(s)) {
            const ProxyPair p = cachedPairs_[k];
            const std::uint32_t other = p.first == s ? p.second : p.first;
            if (other < slots) f(other);
        }
        return true;
    }
    /// The proxies whose fat boxes may meet `box` (then near()); false when the cache is
    /// empty or the box too big for its grid.
    bool findNear(const Aabb& box) { return valid_ && fat_.findNear(box); }
    const std::vector<std::uint32_t>& near() const { return fat_.near(); }
    const FatBoxes& fat() const { return fat_; }

  private:
    enum class CacheState { Holds, Patch, Rebuild };
    CacheState check(const CollisionDef& def, const std::vector<std::uint32_t>& active,
                     const Proxies& proxies);
    void rebuild(const Substep& sub, Proxies& proxies, const SubstepPaths& paths);
    void findParticlePairs(const CollisionDef& def);
    void findStaticPairs(std::uint32_t slots);
    void patch(const Substep& sub, const Proxies& proxies, const SubstepPaths& paths);
    void dropPairsOfEscaped(const Proxies& proxies, std::uint32_t n);
    void pairEscaped(std::uint32_t e, std::uint32_t n);
    void mergePatchedPairs();
    void selectLivePairs(Proxies& proxies);
    void takeCachedPairsAsLive(Proxies& proxies);
    void indexCachedPairs(std::uint32_t n) { index_.update(cachedPairs_, n, cachedPairsVersion_); }
    // The later passes' pairs (changedPairs).
    bool noteStrays(const Substep& sub, const std::vector<std::uint32_t>& changed, Proxies& proxies,
                    const SubstepPaths& paths);
    bool markKeptPairs(const std::vector<std::uint32_t>& changed, const Proxies& proxies);
    void pairsOfChanged(std::uint32_t i, const Proxies& proxies);
    void pairsOfStray(std::uint32_t i, const Proxies& proxies);
    bool keptPairMeets(std::uint32_t i, const ProxyPair& p, const Proxies& proxies) const;
    static bool overlapping(std::uint32_t i, std::uint32_t j, const Proxies& proxies);
    /// Pair p can pair with these kinds of the particles (a shape is Resting).
    static bool pairableAs(const std::vector<ProxyKind>& kinds, const ProxyPair& p) {
        const std::size_t n = kinds.size();
        return pairable(kinds[p.first], p.second < n ? kinds[p.second] : ProxyKind::Resting);
    }

    // The kept pairs, over fat boxes: of particles, with shapes, and both merged.
    FatBoxes fat_;
    std::vector<ProxyPair> cachedPairs_, particlePairs_, staticPairs_;
    std::uint64_t cachedPairsVersion_ = 0; ///< counts the builds and mends
    KeptPairIndex index_;                  ///< for cachedPairsVersion_, when asked
    // What the cache was built for: anything else rebuilds it.
    bool valid_ = false;
    std::uint64_t cachedShapes_ = 0;
    BroadPhase cachedBroadPhase_ = BroadPhase::Grid;
    double cachedCellSize_ = 0.0;
    // The broad phases.
    UniformGrid grid_;
    SortAndSweep sweep_;
    StaticShapeIndex staticIndex_;
    std::vector<std::uint32_t> staticHits_;
    // Proxies that escaped the cache this pass (check), at most kMostPatched: more
    // rebuild it.
    static constexpr std::size_t kMostPatched = 64;
    std::vector<std::uint32_t> escaped_;
    std::vector<std::uint8_t> escapedMark_;
    std::vector<ProxyPair> fresh_, mergedPairs_; ///< the escaped proxies' new pairs; scratch
    /// The cached pairs that can pair with the live kinds (selectLivePairs).
    std::vector<ProxyPair> livePairs_;
    std::vector<ProxyPair> pairs_; ///< this pass's
    // Particles a later pass changed beyond what the live pairs cover (their boxes left
    // their fat boxes, or they woke), until the next full detection mends the cache: at
    // most kMostStrays, more run the full detection.
    static constexpr std::size_t kMostStrays = 32;
    std::vector<std::uint32_t> strays_;
    std::vector<std::uint8_t> strayMark_;
    std::vector<std::uint64_t> keptMarks_; ///< a bit a kept pair (markKeptPairs)
};

} // namespace phys
