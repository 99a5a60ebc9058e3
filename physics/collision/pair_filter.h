// The kept pairs whose exact boxes overlap: what every pass and the contact solver ask of
// the pair cache (ParticleCollisions::findPairs), thousands of pairs at a time.
//
// Which pairs pass is a coin toss, so neither way branches on it: each pair is written
// and the count moves on only if it passes. Where the processor has AVX2 the test of
// one pair is one comparison of four lanes: a's box (lo.x, lo.y, hi.x, hi.y) against
// b's with its halves swapped (hi.x, hi.y, lo.x, lo.y), the upper two lanes negated so
// that "lo <= hi" and "hi >= lo" are both "<=". Negating is exact and an ordered
// comparison is false with a NaN either way, so both give the same pairs.
#pragma once

#include "physics/collision/broadphase.h"

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

} // namespace phys
