// The proxies of the broad phase: each active particle's kind (moving, resting or gone,
// broadphase.h) and the box of its path over the sub-step (simd/path_boxes.h). A settled
// particle keeps the proxy a sub-step last made for it.
//
// Two sets of boxes: those of the passes (the path's box), and those of the contact
// solver, which reach kSpeculative radii further (swapForSolver puts them in place while
// the solver detects). The kinds are also held against the live kinds, those the pair
// cache last selected its live pairs with: a kind that changed asks for a new selection,
// and one that may pair with more than before (it woke, or came back) for the whole
// cache to be looked at again (pair_cache.h).
#pragma once

#include "physics/collision/broadphase.h"
#include "physics/collision/collision_def.h"
#include "physics/collision/paths.h"
#include "physics/particles.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace phys {

class AwakeSet;
class FatBoxes;

class Proxies {
  public:
    /// The proxies of the `active` particles: their kinds, and the boxes of their paths
    /// (or of the paths' ends), radii grown by `grow` of themselves.
    void build(const ParticleSet& set, const std::vector<std::uint32_t>& active,
               const SubstepPaths& paths, const CollisionDef& def, double h, bool atEndOnly,
               double grow = 0.0);
    /// Particle i's proxy alone: its kind and the box of its whole path.
    void rebuild(const ParticleSet& set, const SubstepPaths& paths, const CollisionDef& def,
                 std::size_t i, double h);
    /// The solver's boxes of the particles that may be settled in the next sub-step, when
    /// this one ran no solver; one whose box is not inside its fat box is not settled.
    void boxSettlingForSolver(const ParticleSet& set, const CollisionDef& def, AwakeSet& awake,
                              const SubstepPaths& paths, const FatBoxes& fat);
    /// The solver's boxes in place of the passes' (and back).
    void swapForSolver() { std::swap(boxes_, solverBoxes_); }

    const std::vector<Aabb>& boxes() const { return boxes_; }
    const std::vector<ProxyKind>& kinds() const { return kinds_; }
    ProxyKind kind(std::size_t i) const { return kinds_[i]; }
    const Aabb& box(std::size_t i) const { return boxes_[i]; }
    std::size_t count() const { return boxes_.size(); }

    /// The kinds the live pairs were selected with.
    const std::vector<ProxyKind>& liveKinds() const { return liveKinds_; }
    /// Some kind may differ from its live kind; some may pair with more than it.
    bool kindsChanged() const { return kindsChanged_; }
    bool kindsRose() const { return kindsRose_; }
    /// The kinds of now become the live kinds.
    void takeKindsAsLive() {
        liveKinds_ = kinds_;
        kindsChanged_ = kindsRose_ = false;
    }

  private:
    ProxyKind setKind(const ParticleSet& set, std::size_t i);
    /// A proxy of kind `now` may pair with more than it could as `before`: it came back
    /// (from None), or it moves again (Resting to Moving). pairable() only loses pairs
    /// otherwise.
    static bool pairsWithMore(ProxyKind now, ProxyKind before) {
        return (before == ProxyKind::None && now != ProxyKind::None) ||
               (before == ProxyKind::Resting && now == ProxyKind::Moving);
    }
    std::vector<Aabb> boxes_, solverBoxes_; ///< each keeps a settled particle's
    std::vector<ProxyKind> kinds_, liveKinds_;
    std::vector<std::uint32_t> boxed_; ///< the active particles with a proxy
    bool kindsChanged_ = true;         ///< a kind may differ from liveKinds_
    bool kindsRose_ = true;            ///< a kind may pair with more than in liveKinds_
};

} // namespace phys
