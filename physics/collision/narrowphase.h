// The narrow phase: of the pairs the broad phase found (pair_cache.h), those whose paths
// meet within the step, each with its time of impact (time_of_impact.h), as candidates
// in the order the passes resolve them: by time, ties in pair order.
//
// Most pairs of a pile start touching: their times need no search (simd/pair_starts.h).
#pragma once

#include "physics/collision/broadphase.h"
#include "physics/collision/paths.h"
#include "physics/collision/simd/pair_starts.h"
#include "physics/collision/substep.h"
#include "physics/collision/time_of_impact.h"

#include <cstdint>
#include <vector>

namespace phys {

/// A pair whose paths meet within the step, at `time`.
struct Candidate {
    std::uint32_t a;
    std::uint32_t b; ///< particle, or kNoParticle for a shape
    ShapeRef shape;
    double time;
    std::uint32_t proxy; ///< b, or slots + the shape's index: the pair order's key
    bool carried;        ///< a resting pair the last pass left to the solver, found again
};

/// A candidate's place in the order of resolution.
struct TimeKey {
    double time;
    std::uint32_t index; ///< the candidate's place in its list
};

/// Sorts keys given in index order by (time, index). Past kRadixSortFrom keys (a heap's
/// passes list thousands) by a stable radix sort on the times' bits, byte by byte from
/// the lowest, instead of by comparisons, most of them mispredicted: the same order, as
/// ties keep the index order they start in. `scratch` is the radix sort's other buffer.
void orderByTime(std::vector<TimeKey>& keys, std::vector<TimeKey>& scratch);

/// Below this many keys the comparison sort is as fast (a radix sort pays eight passes).
inline constexpr std::size_t kRadixSortFrom = 1024;

class NarrowPhase {
  public:
    /// The time-of-impact settings of this sub-step.
    void configure(const CollisionDef& def) {
        toi_ = {def.continuous, def.bisectionHalvings, def.toiTolerance, def.maxAdvanceIterations};
    }
    const ToiSettings& settings() const { return toi_; }
    /// candidates(): the pairs that meet within the step, in pair order.
    void findCandidates(const Substep& sub, const std::vector<ProxyPair>& pairs,
                        const SubstepPaths& paths);
    /// The carried candidates (in pair order) join the candidates, in pair order.
    void mergeCarried(const std::vector<Candidate>& carried);
    /// order(): the candidates by time, ties in pair order.
    void orderByTime();

    const std::vector<Candidate>& candidates() const { return candidates_; }
    const std::vector<TimeKey>& order() const { return order_; }

  private:
    /// A pair of the broad phase that meets within the step becomes a candidate.
    void addCandidate(const Substep& sub, ProxyPair pair, const SubstepPaths& paths);
    std::vector<Candidate> candidates_, merged_;
    std::vector<PairStart> pairStarts_; ///< what the start of each pair's path tells
    std::vector<TimeKey> order_;        ///< candidates in the order they are resolved
    std::vector<TimeKey> orderScratch_; ///< orderByTime's other buffer
    ToiSettings toi_;
};

} // namespace phys
