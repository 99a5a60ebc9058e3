#include "physics/collision/simd/pair_starts.h"

#include "physics/cpu_features.h"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>
#define ARTILLERY_PAIR_STARTS_AVX2 1
#endif

namespace phys {

namespace {

// One pair, as timeOfImpact begins it.
PairStart pairStart(const ProxyPair& p, const PathDiscs& discs, double tEnd, const ToiSettings& s) {
    if (p.second >= discs.paths.size()) return {PairStart::Search, 0.0};
    const PathMotion m = discs.paths[p.first].relativeTo(discs.paths[p.second]);
    if (!(tEnd > m.t0)) return {PairStart::None, 0.0};
    const double ra = discs.radius[p.first];
    const SurfacePoint start = closestPoint(Circle{{0.0, 0.0}, discs.radius[p.second]}, m.p);
    const double g0 = start.distance - ra;
    if (!(g0 <= s.tolerance)) return {PairStart::Search, 0.0};
    const std::optional<double> t = touchingTime(g0, start.normal, ra, m, tEnd, s);
    return t ? PairStart{PairStart::Contact, *t} : PairStart{PairStart::None, 0.0};
}

} // namespace

void classifyPairStartsScalar(std::span<const ProxyPair> pairs, const PathDiscs& discs, double tEnd,
                              const ToiSettings& s, PairStart* out) {
    for (std::size_t k = 0; k < pairs.size(); ++k)
        out[k] = pairStart(pairs[k], discs, tEnd, s);
}

#if defined(ARTILLERY_PAIR_STARTS_AVX2)
#pragma GCC push_options
#pragma GCC target("avx2")
namespace {

#include "physics/collision/simd/avx2_loads.inc"

// PathMotion::position(t) and velocity(t) from the later t0, as relativeTo takes them.
void advanceTo(const PathLanes& m, __m256d t, __m256d& x, __m256d& y, __m256d& vx, __m256d& vy) {
    const __m256d half = _mm256_set1_pd(0.5);
    const __m256d s = _mm256_sub_pd(t, m.t0);
    const __m256d bend = _mm256_mul_pd(_mm256_mul_pd(half, s), s);
    x = _mm256_add_pd(_mm256_add_pd(m.px, _mm256_mul_pd(m.vx, s)), _mm256_mul_pd(m.ax, bend));
    y = _mm256_add_pd(_mm256_add_pd(m.py, _mm256_mul_pd(m.vy, s)), _mm256_mul_pd(m.ay, bend));
    vx = _mm256_add_pd(m.vx, _mm256_mul_pd(m.ax, s));
    vy = _mm256_add_pd(m.vy, _mm256_mul_pd(m.ay, s));
}

__m256d lengthOf(__m256d x, __m256d y) {
    return _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(x, x), _mm256_mul_pd(y, y)));
}

// atLeastOne: 1 where |v|^2 <= 1, else std::max(1, |v|) (max_pd(|v|, 1) picks the same,
// 1 for a NaN).
__m256d atLeastOne(__m256d x, __m256d y) {
    const __m256d one = _mm256_set1_pd(1.0);
    const __m256d squared = _mm256_add_pd(_mm256_mul_pd(x, x), _mm256_mul_pd(y, y));
    const __m256d small = _mm256_cmp_pd(squared, one, _CMP_LE_OQ);
    return _mm256_blendv_pd(_mm256_max_pd(_mm256_sqrt_pd(squared), one), one, small);
}

// The paths of four pairs relative to each other (relativeTo: both from the later t0).
struct RelativeLanes {
    __m256d t0, x, y, vx, vy, ax, ay;
};

inline RelativeLanes relativePaths(const PathDiscs& discs, const std::uint32_t* first,
                                   const std::uint32_t* second) {
    const PathLanes a = loadPaths(discs.paths.data(), first);
    const PathLanes b = loadPaths(discs.paths.data(), second);
    RelativeLanes m;
    m.t0 = _mm256_max_pd(b.t0, a.t0); // std::max(a.t0, b.t0)
    __m256d xa, ya, vxa, vya, xb, yb, vxb, vyb;
    advanceTo(a, m.t0, xa, ya, vxa, vya);
    advanceTo(b, m.t0, xb, yb, vxb, vyb);
    m.x = _mm256_sub_pd(xa, xb), m.y = _mm256_sub_pd(ya, yb);
    m.vx = _mm256_sub_pd(vxa, vxb), m.vy = _mm256_sub_pd(vya, vyb);
    m.ax = _mm256_sub_pd(a.ax, b.ax), m.ay = _mm256_sub_pd(a.ay, b.ay);
    return m;
}

// What four pairs' starts tell: which are live (the step not over at t0), which start
// touching, which of those are contacts, and at what time.
struct StartLanes {
    __m256d live, touching, contact, time;
};

// closestPoint on the circle of b's radius about the origin, then touchingTime, for four
// relative paths.
inline StartLanes touchingTimes(const RelativeLanes& m, __m256d ra, __m256d rb, __m256d end,
                                __m256d tolerance) {
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    const __m256d tiny = _mm256_set1_pd(1e-300), two = _mm256_set1_pd(2.0);
    const __m256d minusTwo = _mm256_set1_pd(-2.0), signBit = _mm256_set1_pd(-0.0);
    StartLanes s;
    s.live = _mm256_cmp_pd(end, m.t0, _CMP_GT_OQ);
    // m.p - {0, 0} is m.p to the bit (x - 0 is x, and -0 - 0 is -0), so the relative
    // position is the offset from the circle's centre.
    const __m256d l = lengthOf(m.x, m.y);
    // A lane divides only by a number that is not zero: by 1 where the one-pair
    // arithmetic would not divide, so no 0 / 0 or x / 0 is born in a lane whose result
    // is not taken (the physics tests trap them).
    const __m256d apart = _mm256_cmp_pd(l, tiny, _CMP_GT_OQ);
    const __m256d byLength = _mm256_blendv_pd(one, l, apart);
    const __m256d nx = _mm256_blendv_pd(zero, _mm256_div_pd(m.x, byLength), apart);
    const __m256d ny = _mm256_blendv_pd(one, _mm256_div_pd(m.y, byLength), apart);
    const __m256d g0 = _mm256_sub_pd(_mm256_sub_pd(l, rb), ra);
    s.touching = _mm256_cmp_pd(g0, tolerance, _CMP_LE_OQ);
    // touchingTime.
    const __m256d vn = _mm256_add_pd(_mm256_mul_pd(nx, m.vx), _mm256_mul_pd(ny, m.vy));
    const __m256d an = _mm256_add_pd(_mm256_mul_pd(nx, m.ax), _mm256_mul_pd(ny, m.ay));
    const __m256d vEps = _mm256_mul_pd(_mm256_set1_pd(kVelocityRounding), atLeastOne(m.vx, m.vy));
    const __m256d aEps = _mm256_mul_pd(_mm256_set1_pd(kAccelRounding), atLeastOne(m.ax, m.ay));
    const __m256d slop = _mm256_max_pd(_mm256_mul_pd(_mm256_set1_pd(kOverlapSlop), ra), tolerance);
    const __m256d minusVEps = _mm256_xor_pd(vEps, signBit);
    const __m256d minusAEps = _mm256_xor_pd(aEps, signBit);
    const __m256d pulledIn = _mm256_cmp_pd(an, minusAEps, _CMP_LT_OQ);
    const __m256d now =
        _mm256_or_pd(_mm256_or_pd(_mm256_cmp_pd(g0, _mm256_xor_pd(slop, signBit), _CMP_LT_OQ),
                                  _mm256_cmp_pd(vn, minusVEps, _CMP_LT_OQ)),
                     _mm256_and_pd(_mm256_cmp_pd(vn, vEps, _CMP_LE_OQ), pulledIn));
    const __m256d byAn = _mm256_blendv_pd(one, an, pulledIn); // an < 0 where taken
    const __m256d returns =
        _mm256_and_pd(pulledIn, _mm256_cmp_pd(_mm256_div_pd(_mm256_mul_pd(minusTwo, vn), byAn),
                                              _mm256_sub_pd(end, m.t0), _CMP_LE_OQ));
    const __m256d back = _mm256_sub_pd(m.t0, _mm256_div_pd(_mm256_mul_pd(two, vn), byAn));
    s.time = _mm256_blendv_pd(back, m.t0, now);
    s.contact = _mm256_or_pd(now, returns);
    return s;
}

inline void writeStarts(const StartLanes& s, PairStart* out) {
    alignas(32) double time[4];
    _mm256_store_pd(time, s.time);
    const int isLive = _mm256_movemask_pd(s.live), isTouching = _mm256_movemask_pd(s.touching);
    const int isContact = _mm256_movemask_pd(s.contact);
    for (int lane = 0; lane < 4; ++lane) {
        const int bit = 1 << lane;
        const PairStart::Kind kind = !(isLive & bit)       ? PairStart::None
                                     : !(isTouching & bit) ? PairStart::Search
                                     : (isContact & bit)   ? PairStart::Contact
                                                           : PairStart::None;
        out[lane] = {kind, kind == PairStart::Contact ? time[lane] : 0.0};
    }
}

void classifyPairStartsAvx2(std::span<const ProxyPair> pairs, const PathDiscs& discs, double tEnd,
                            const ToiSettings& s, PairStart* out) {
    const std::size_t n = discs.paths.size();
    const __m256d end = _mm256_set1_pd(tEnd), tolerance = _mm256_set1_pd(s.tolerance);
    std::size_t k = 0;
    alignas(32) std::uint32_t first[4], second[4];
    for (; k + 4 <= pairs.size(); k += 4) {
        bool shape = false;
        for (int lane = 0; lane < 4; ++lane) {
            first[lane] = pairs[k + lane].first, second[lane] = pairs[k + lane].second;
            shape |= second[lane] >= n;
        }
        if (shape) { // rare: a pile's pairs with the ground come a few to a particle
            classifyPairStartsScalar(pairs.subspan(k, 4), discs, tEnd, s, out + k);
            continue;
        }
        const RelativeLanes m = relativePaths(discs, first, second);
        const __m128i slotsA = _mm_load_si128(reinterpret_cast<const __m128i*>(first));
        const __m128i slotsB = _mm_load_si128(reinterpret_cast<const __m128i*>(second));
        const __m256d ra = gatherAt(discs.radius.data(), slotsA);
        const __m256d rb = gatherAt(discs.radius.data(), slotsB);
        writeStarts(touchingTimes(m, ra, rb, end, tolerance), out + k);
    }
    classifyPairStartsScalar(pairs.subspan(k), discs, tEnd, s, out + k);
}

} // namespace
#pragma GCC pop_options
#endif

void classifyPairStarts(std::span<const ProxyPair> pairs, const PathDiscs& discs, double tEnd,
                        const ToiSettings& s, PairStart* out) {
#if defined(ARTILLERY_PAIR_STARTS_AVX2)
    if (processorHasAvx2()) return classifyPairStartsAvx2(pairs, discs, tEnd, s, out);
#endif
    classifyPairStartsScalar(pairs, discs, tEnd, s, out);
}

} // namespace phys
