#include "physics/collision/proxies.h"

#include "physics/collision/awake_set.h"
#include "physics/collision/pair_cache.h"
#include "physics/collision/simd/path_boxes.h"
#include "physics/collision/substep.h"

namespace phys {

void Proxies::build(const ParticleSet& set, const std::vector<std::uint32_t>& active,
                    const SubstepPaths& paths, const CollisionDef& def, double h, bool atEndOnly,
                    double grow) {
    const std::size_t n = set.slots();
    boxes_.resize(n);
    kinds_.resize(n);
    // New slots: the live pairs are selected again before what these hold is read.
    if (liveKinds_.size() != n) {
        liveKinds_.resize(n, ProxyKind::None);
        kindsChanged_ = kindsRose_ = true;
    }
    boxed_.clear();
    for (const std::uint32_t i : active)
        if (setKind(set, i) != ProxyKind::None) boxed_.push_back(i);
    pathBoxes(boxed_, paths.paths(n), set.radius, {h, grow, def.toiTolerance, atEndOnly},
              boxes_.data());
}

void Proxies::rebuild(const ParticleSet& set, const SubstepPaths& paths, const CollisionDef& def,
                      std::size_t i, double h) {
    if (setKind(set, i) != ProxyKind::None)
        boxes_[i] = pathBox(paths.path(i), set.radius[i], {h, 0.0, def.toiTolerance, false});
}

void Proxies::boxSettlingForSolver(const ParticleSet& set, const CollisionDef& def, AwakeSet& awake,
                                   const SubstepPaths& paths, const FatBoxes& fat) {
    solverBoxes_.resize(set.slots());
    for (const std::uint32_t i : awake.active()) {
        if (!awake.mayStaySettled(i) || kinds_[i] == ProxyKind::None) continue;
        // At rest, and no contact changed its path: the solver's box of a path at rest
        // where it is.
        const PathMotion atRest{paths.path(i).p, {}, {}, 0.0};
        const Aabb box =
            pathBox(atRest, set.radius[i], {0.0, kSpeculative, def.toiTolerance, false});
        solverBoxes_[i] = box;
        // No solver checked this box against its fat box: one outside is checked (and the
        // cache mended) in the next sub-step, which works on it again.
        if (!fat.holds(i, box)) awake.unsettle(i);
    }
}

ProxyKind Proxies::setKind(const ParticleSet& set, std::size_t i) {
    const ProxyKind kind = (set.flags[i] & (kAlive | kNoCollide)) != kAlive ? ProxyKind::None
                           : movable(set, i)                                ? ProxyKind::Moving
                                                                            : ProxyKind::Resting;
    kindsChanged_ |= kind != liveKinds_[i];
    kindsRose_ |= pairsWithMore(kind, liveKinds_[i]);
    kinds_[i] = kind;
    return kind;
}

} // namespace phys
