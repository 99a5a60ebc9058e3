// Where the first pass's times of impact need no search. In a resting pile nearly every
// pair the first pass tests starts touching, and
// timeOfImpact then answers from the start of the path alone (touchingTime): a contact
// now, one when the pair falls back together, or none. That answer is worked out here
// for pairs of particles four at a time, where the processor has AVX2; the pairs that
// start apart, and those with a shape, are left to timeOfImpact's search.
//
// The lanes do the one-pair arithmetic in the same order (path_[a].relativeTo(path_[b]),
// closestPoint on the circle of b's radius, touchingTime; no fused multiply-add; max as
// std::max picks, signed zeros and NaNs included), so the times are the same bits.
#pragma once

#include "physics/collision/broadphase.h"
#include "physics/collision/time_of_impact.h"

#include <cstdint>
#include <span>

namespace phys {

/// What a pair's time of impact comes to, as far as the start of its path tells.
struct PairStart {
    enum Kind : std::uint8_t {
        None,    ///< no contact in the step
        Contact, ///< a contact at `time`
        Search,  ///< apart at the start, or with a shape: timeOfImpact's search decides
    };
    Kind kind;
    double time;
};

/// The particles' paths and radii, by slot, for the pairs' starts.
struct PathDiscs {
    std::span<const PathMotion> paths;
    std::span<const double> radius;
};

/// For each pair, out[k]: for two particles (second below paths.size()), what
/// timeOfImpact(Circle{{0, 0}, rb}, ra, paths[a].relativeTo(paths[b]), tEnd, s) gives
/// when the relative path starts touching (Contact or None, to the bit), None when the
/// step is already over at its start, Search otherwise; Search for a shape.
void classifyPairStarts(std::span<const ProxyPair> pairs, const PathDiscs& discs, double tEnd,
                        const ToiSettings& s, PairStart* out);

/// classifyPairStarts one pair at a time without AVX2 (the reference the tests compare
/// with).
void classifyPairStartsScalar(std::span<const ProxyPair> pairs, const PathDiscs& discs, double tEnd,
                              const ToiSettings& s, PairStart* out);

} // namespace phys
