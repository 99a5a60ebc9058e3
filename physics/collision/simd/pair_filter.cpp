#include "physics/collision/simd/pair_filter.h"

#include "physics/collision/time_of_impact.h"
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

// One pair of particles, as the solver builds a contact: d = pa - pb, |d|, d / |d|.
inline NearPair nearPair(const ProxyPair& p, const Discs& discs) {
    const Vec2 d =
        Vec2{discs.x[p.first], discs.y[p.first]} - Vec2{discs.x[p.second], discs.y[p.second]};
    const double L = length(d);
    return {p, L > 0.0 ? d / L : Vec2{0.0, 1.0},
            discs.radius[p.first] + discs.radius[p.second] - L};
}

} // namespace

std::size_t keepNearScalar(std::span<const ProxyPair> pairs, const Discs& discs, double tolerance,
                           double speculative, NearPair* out) {
    const std::size_t n = discs.x.size();
    std::size_t kept = 0;
    for (const ProxyPair& p : pairs) {
        if (p.second >= n) {
            out[kept++] = {p, {}, 0.0};
            continue;
        }
        out[kept] = nearPair(p, discs);
        const double reach = discs.radius[p.first] + discs.radius[p.second];
        kept += nearEnough(out[kept].depth, reach, tolerance, speculative);
    }
    return kept;
}

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

#include "physics/collision/simd/avx2_loads.inc"

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

// Four pairs at a time: their slots gathered, the arithmetic of nearPair and nearEnough
// in lanes (no fused multiply-add; a square root and a division are correctly rounded
// either way). A shape's lane reads a's disc twice and is kept whatever it gives.
std::size_t keepNearAvx2(std::span<const ProxyPair> pairs, const Discs& discs, double tolerance,
                         double speculative, NearPair* out) {
    static_assert(sizeof(ProxyPair) == 2 * sizeof(std::uint32_t), "first, second");
    const std::size_t n = discs.x.size();
    const __m256i firstsThenSeconds = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);
    // The slots are below 2^31 (a ParticleSet's index), so a signed comparison serves.
    const __m128i lastSlot = _mm_set1_epi32(static_cast<int>(n) - 1);
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    const __m256d minusTolerance = _mm256_set1_pd(-tolerance);
    const __m256d spec = _mm256_set1_pd(speculative);
    std::size_t kept = 0, k = 0;
    alignas(32) double nx[4], ny[4], depth[4];
    for (; k + 4 <= pairs.size(); k += 4) {
        const __m256i ab = _mm256_permutevar8x32_epi32(
            _mm256_loadu_si256(reinterpret_cast<const __m256i*>(&pairs[k])), firstsThenSeconds);
        const __m128i a = _mm256_castsi256_si128(ab);
        const __m128i second = _mm256_extracti128_si256(ab, 1);
        const __m128i shape = _mm_cmpgt_epi32(second, lastSlot);
        const __m128i b = _mm_blendv_epi8(second, a, shape);
        const __m256d xa = gatherAt(discs.x.data(), a);
        const __m256d ya = gatherAt(discs.y.data(), a);
        const __m256d ra = gatherAt(discs.radius.data(), a);
        const __m256d xb = gatherAt(discs.x.data(), b);
        const __m256d yb = gatherAt(discs.y.data(), b);
        const __m256d rb = gatherAt(discs.radius.data(), b);
        const __m256d dx = _mm256_sub_pd(xa, xb), dy = _mm256_sub_pd(ya, yb);
        const __m256d L =
            _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)));
        const __m256d apart = _mm256_cmp_pd(L, zero, _CMP_GT_OQ);
        // Divided by 1 where the centres coincide, whose normal is {0, 1}: no 0 / 0 is
        // born in a lane the pair's own arithmetic would not divide in.
        const __m256d divisor = _mm256_blendv_pd(one, L, apart);
        _mm256_store_pd(nx, _mm256_blendv_pd(zero, _mm256_div_pd(dx, divisor), apart));
        _mm256_store_pd(ny, _mm256_blendv_pd(one, _mm256_div_pd(dy, divisor), apart));
        const __m256d reach = _mm256_add_pd(ra, rb);
        const __m256d d = _mm256_sub_pd(reach, L);
        _mm256_store_pd(depth, d);
        const __m256d limit = _mm256_sub_pd(minusTolerance, _mm256_mul_pd(spec, reach));
        const int near = _mm256_movemask_pd(_mm256_cmp_pd(d, limit, _CMP_GT_OQ)) |
                         _mm_movemask_ps(_mm_castsi128_ps(shape));
        for (int lane = 0; lane < 4; ++lane) {
            out[kept] = {pairs[k + lane], {nx[lane], ny[lane]}, depth[lane]};
            kept += (near >> lane) & 1;
        }
    }
    return kept + keepNearScalar(pairs.subspan(k), discs, tolerance, speculative, out + kept);
}

} // namespace
#pragma GCC pop_options
#endif

std::size_t keepNear(std::span<const ProxyPair> pairs, const Discs& discs, double tolerance,
                     double speculative, NearPair* out) {
#if defined(ARTILLERY_PAIR_FILTER_AVX2)
    if (processorHasAvx2()) return keepNearAvx2(pairs, discs, tolerance, speculative, out);
#endif
    return keepNearScalar(pairs, discs, tolerance, speculative, out);
}

std::size_t keepOverlapping(std::span<const ProxyPair> pairs, std::span<const Aabb> particles,
                            std::span<const Aabb> statics, ProxyPair* out) {
#if defined(ARTILLERY_PAIR_FILTER_AVX2)
    if (processorHasAvx2()) return keepOverlappingAvx2(pairs, particles, statics, out);
#endif
    return keepOverlappingScalar(pairs, particles, statics, out);
}

} // namespace phys
