#include "physics/collision/pair_filter.h"

#include "physics/cpu_features.h"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>
#define ARTILLERY_PAIR_FILTER_AVX2 1
#endif

namespace phys {

namespace {

// b's box: a particle's, or a static shape's past the particles.
inline const Aabb& secondBox(const ProxyPair& p, std::span<const Aabb> particles,
                             std::span<const Aabb> statics) {
    const std::size_t n = particles.size();
    return p.second < n ? particles[p.second] : statics[p.second - n];
}

} // namespace

std::size_t keepOverlappingScalar(std::span<const ProxyPair> pairs, std::span<const Aabb> particles,
                                  std::span<const Aabb> statics, ProxyPair* out) {
    std::size_t kept = 0;
    for (const ProxyPair& p : pairs) {
        out[kept] = p;
        kept += particles[p.first].overlapsBranchless(secondBox(p, particles, statics));
    }
    return kept;
}

#if defined(ARTILLERY_PAIR_FILTER_AVX2)
#pragma GCC push_options
#pragma GCC target("avx2")
namespace {

std::size_t keepOverlappingAvx2(std::span<const ProxyPair> pairs, std::span<const Aabb> particles,
                                std::span<const Aabb> statics, ProxyPair* out) {
    static_assert(sizeof(Aabb) == 4 * sizeof(double), "lo.x, lo.y, hi.x, hi.y");
    const __m256d upperNegated = _mm256_set_pd(-0.0, -0.0, 0.0, 0.0);
    std::size_t kept = 0;
    for (const ProxyPair& p : pairs) {
        const Aabb& a = particles[p.first];
        const Aabb& b = secondBox(p, particles, statics);
        // (a.lo, a.hi) <= (b.hi, b.lo) with the upper half negated: a.lo <= b.hi, b.lo <= a.hi.
        const __m256d boxA = _mm256_xor_pd(_mm256_loadu_pd(&a.lo.x), upperNegated);
        const __m256d boxB = _mm256_xor_pd(_mm256_loadu2_m128d(&b.lo.x, &b.hi.x), upperNegated);
        const int below = _mm256_movemask_pd(_mm256_cmp_pd(boxA, boxB, _CMP_LE_OQ));
        out[kept] = p;
        kept += below == 0xF;
    }
    return kept;
}

} // namespace
#pragma GCC pop_options
#endif

std::size_t keepOverlapping(std::span<const ProxyPair> pairs, std::span<const Aabb> particles,
                            std::span<const Aabb> statics, ProxyPair* out) {
#if defined(ARTILLERY_PAIR_FILTER_AVX2)
    if (processorHasAvx2()) return keepOverlappingAvx2(pairs, particles, statics, out);
#endif
    return keepOverlappingScalar(pairs, particles, statics, out);
}

} // namespace phys
