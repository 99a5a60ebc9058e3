#include "physics/collision/simd/path_boxes.h"

#include "physics/cpu_features.h"

#include <algorithm>
#include <bit>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>
#define ARTILLERY_PATH_BOXES_AVX2 1
#endif

namespace phys {

Aabb pathBox(const PathMotion& m, double radius, const PathBoxing& b) {
    // How far the box reaches past the path: the radius, grown by `grow` of itself, and
    // the tolerance.
    const double r = radius * (1.0 + b.grow) + b.tolerance;
    const bool atRest =
        (std::bit_cast<std::uint64_t>(m.v.x) | std::bit_cast<std::uint64_t>(m.v.y) |
         std::bit_cast<std::uint64_t>(m.a.x) | std::bit_cast<std::uint64_t>(m.a.y)) == 0;
    // A path at rest (a sleeper's): the box of where it is. The same bits as below, where
    // the path's points differ from m.p at most in the sign of a zero.
    if (atRest) return {m.p - Vec2{r, r}, m.p + Vec2{r, r}};
    const Vec2 end = m.position(b.h);
    const Vec2 mid = m.p + m.v * (0.5 * (b.h - m.t0));
    Vec2 lo = end, hi = end;
    if (!b.atEndOnly)
        for (const Vec2 q : {m.p, mid}) {
            lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
            hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
        }
    return {lo - Vec2{r, r}, hi + Vec2{r, r}};
}

void pathBoxesScalar(std::span<const std::uint32_t> which, std::span<const PathMotion> paths,
                     std::span<const double> radius, const PathBoxing& b, Aabb* boxes) {
    for (const std::uint32_t i : which)
        boxes[i] = pathBox(paths[i], radius[i], b);
}

#if defined(ARTILLERY_PATH_BOXES_AVX2)
#pragma GCC push_options
#pragma GCC target("avx2")
namespace {

#include "physics/collision/simd/avx2_loads.inc"

void pathBoxesAvx2(std::span<const std::uint32_t> which, std::span<const PathMotion> paths,
                   std::span<const double> radius, const PathBoxing& b, Aabb* boxes) {
    static_assert(sizeof(Aabb) == 4 * sizeof(double), "lo.x, lo.y, hi.x, hi.y");
    const __m256d h = _mm256_set1_pd(b.h), half = _mm256_set1_pd(0.5);
    const __m256d grown = _mm256_set1_pd(1.0 + b.grow), tolerance = _mm256_set1_pd(b.tolerance);
    std::size_t k = 0;
    for (; k + 4 <= which.size(); k += 4) {
        const std::uint32_t* at = which.data() + k;
        const PathLanes m = loadPaths(paths.data(), at);
        const __m128i slots = _mm_loadu_si128(reinterpret_cast<const __m128i*>(at));
        const __m256d r =
            _mm256_add_pd(_mm256_mul_pd(gatherAt(radius.data(), slots), grown), tolerance);
        const __m256i moves =
            _mm256_or_si256(_mm256_or_si256(_mm256_castpd_si256(m.vx), _mm256_castpd_si256(m.vy)),
                            _mm256_or_si256(_mm256_castpd_si256(m.ax), _mm256_castpd_si256(m.ay)));
        const __m256d atRest =
            _mm256_castsi256_pd(_mm256_cmpeq_epi64(moves, _mm256_setzero_si256()));
        // PathMotion::position(h), and the middle control point.
        const __m256d s = _mm256_sub_pd(h, m.t0);
        const __m256d bend = _mm256_mul_pd(_mm256_mul_pd(half, s), s);
        __m256d loX =
            _mm256_add_pd(_mm256_add_pd(m.px, _mm256_mul_pd(m.vx, s)), _mm256_mul_pd(m.ax, bend));
        __m256d loY =
            _mm256_add_pd(_mm256_add_pd(m.py, _mm256_mul_pd(m.vy, s)), _mm256_mul_pd(m.ay, bend));
        __m256d hiX = loX, hiY = loY;
        if (!b.atEndOnly) {
            const __m256d halfT = _mm256_mul_pd(half, s); // 0.5 * (h - t0)
            const __m256d midX = _mm256_add_pd(m.px, _mm256_mul_pd(m.vx, halfT));
            const __m256d midY = _mm256_add_pd(m.py, _mm256_mul_pd(m.vy, halfT));
            // std::min(lo, q) is (q < lo ? q : lo), min_pd(q, lo); std::max(hi, q) is
            // (hi < q ? q : hi), max_pd(q, hi).
            for (const auto& [qx, qy] : {std::pair{m.px, m.py}, std::pair{midX, midY}}) {
                loX = _mm256_min_pd(qx, loX), loY = _mm256_min_pd(qy, loY);
                hiX = _mm256_max_pd(qx, hiX), hiY = _mm256_max_pd(qy, hiY);
            }
        }
        loX = _mm256_blendv_pd(loX, m.px, atRest), loY = _mm256_blendv_pd(loY, m.py, atRest);
        hiX = _mm256_blendv_pd(hiX, m.px, atRest), hiY = _mm256_blendv_pd(hiY, m.py, atRest);
        loX = _mm256_sub_pd(loX, r), loY = _mm256_sub_pd(loY, r);
        hiX = _mm256_add_pd(hiX, r), hiY = _mm256_add_pd(hiY, r);
        // (lo.x, lo.y, hi.x, hi.y) of each lane, transposed back into its box: lanes 0
        // and 2 from the even halves, 1 and 3 from the odd.
        const __m256d lo02 = _mm256_unpacklo_pd(loX, loY), lo13 = _mm256_unpackhi_pd(loX, loY);
        const __m256d hi02 = _mm256_unpacklo_pd(hiX, hiY), hi13 = _mm256_unpackhi_pd(hiX, hiY);
        _mm256_storeu_pd(&boxes[at[0]].lo.x, _mm256_permute2f128_pd(lo02, hi02, 0x20));
        _mm256_storeu_pd(&boxes[at[1]].lo.x, _mm256_permute2f128_pd(lo13, hi13, 0x20));
        _mm256_storeu_pd(&boxes[at[2]].lo.x, _mm256_permute2f128_pd(lo02, hi02, 0x31));
        _mm256_storeu_pd(&boxes[at[3]].lo.x, _mm256_permute2f128_pd(lo13, hi13, 0x31));
    }
    pathBoxesScalar(which.subspan(k), paths, radius, b, boxes);
}

} // namespace
#pragma GCC pop_options
#endif

void pathBoxes(std::span<const std::uint32_t> which, std::span<const PathMotion> paths,
               std::span<const double> radius, const PathBoxing& b, Aabb* boxes) {
#if defined(ARTILLERY_PATH_BOXES_AVX2)
    if (processorHasAvx2()) return pathBoxesAvx2(which, paths, radius, b, boxes);
#endif
    pathBoxesScalar(which, paths, radius, b, boxes);
}

} // namespace phys
