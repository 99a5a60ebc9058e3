// The kept pairs whose exact boxes overlap: what every pass and the contact solver ask of
// the pair cache (PairCache::findPairs), thousands of pairs at a time.
//
// Which pairs pass is a coin toss, so neither way branches on it: each pair is written
// and the count moves on only if it passes. Where the processor has AVX2 the test of
// one pair is one comparison of four lanes: a's box (lo.x, lo.y, hi.x, hi.y) against
// b's with its halves swapped (hi.x, hi.y, lo.x, lo.y), the upper two lanes negated so
// that "lo <= hi" and "hi >= lo" are both "<=". Negating is exact and an ordered
// comparison is false with a NaN either way, so both give the same pairs.
//
// The contact solver filters once more: of the pairs of particles whose boxes overlap,
// those whose centres are near enough to be a contact (keepNear), with the normal and the
// depth it needs. Its square root and division, four pairs at a time, come off the
// solver's build of its contacts, which waited on them and then branched on the depth.
#pragma once

#include "physics/collision/broadphase.h"
#include "physics/vec2.h"

#include <cstddef>
#include <span>

namespace phys {

/// Writes to `out`, in their order, the pairs whose boxes overlap, and returns how many.
/// A pair's first is a particle (`particles[first]`); its second a particle below
/// particles.size() or the static shape statics[second - particles.size()]. `out` has
/// room for every pair.
std::size_t keepOverlapping(std::span<const ProxyPair> pairs, std::span<const Aabb> particles,
                            std::span<const Aabb> statics, ProxyPair* out);

/// keepOverlapping one pair at a time without AVX2 (the reference the tests compare with).
std::size_t keepOverlappingScalar(std::span<const ProxyPair> pairs, std::span<const Aabb> particles,
                                  std::span<const Aabb> statics, ProxyPair* out);

/// A pair that may be a contact of the solver. For two particles, the normal from b's
/// centre to a's ({0, 1} when they coincide) and the depth: their radii summed less the
/// distance between the centres (negative: a gap). For a particle and a shape both are
/// left to the caller.
struct NearPair {
    ProxyPair pair;
    Vec2 normal;
    double depth;
};

/// Whether a contact of `depth` (negative: a gap) between discs whose radii sum to
/// `reach` is near enough to be one of the solver's: a gap below `tolerance` plus
/// `speculative` of the reach may close in one step.
inline bool nearEnough(double depth, double reach, double tolerance, double speculative) {
    return depth > -tolerance - speculative * reach;
}

/// The particles' positions and radii, by slot.
struct Discs {
    std::span<const double> x, y, radius;
};

/// Writes to `out`, in their order, every pair with a shape (its second at or past
/// discs.x.size()) and every pair of particles nearEnough with reach ra + rb, and
/// returns how many. `out` has room for every
/// pair. The normal and the depth are those of the solver's one-pair arithmetic, bit for
/// bit.
std::size_t keepNear(std::span<const ProxyPair> pairs, const Discs& discs, double tolerance,
                     double speculative, NearPair* out);

/// keepNear one pair at a time without AVX2 (the reference the tests compare with).
std::size_t keepNearScalar(std::span<const ProxyPair> pairs, const Discs& discs, double tolerance,
                           double speculative, NearPair* out);

} // namespace phys
