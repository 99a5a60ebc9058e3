#include "game/bench/flight_reference.h"

#include "physics/cpu_features.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>
#define ARTILLERY_REFERENCE_AVX2 1
#endif

namespace game::bench {

using phys::kAlive;
using phys::kSleeping;

namespace {

// The arrays and constants of one step, read once.
struct Arrays {
    double *px, *py, *vx, *vy;
    const double *im, *r, *cd;
    const std::uint32_t* flags;
};

Arrays arraysOf(phys::ParticleSet& s) {
    return {s.px.data(),      s.py.data(),     s.vx.data(),     s.vy.data(),
            s.invMass.data(), s.radius.data(), s.dragCd.data(), s.flags.data()};
}

void scalarRange(const Arrays& a, const FlightReferenceStep& c, std::size_t i, std::size_t n) {
    for (; i < n; ++i) {
        double vx = a.vx[i], vy = a.vy[i];
        if ((a.flags[i] & (kAlive | kSleeping)) == kAlive && a.im[i] > 0.0) {
            const double ux = vx - c.wind.x, uy = vy - c.wind.y;
            const double k = c.halfRhoPi * a.cd[i] * a.r[i] * a.r[i] * std::sqrt(ux * ux + uy * uy);
            vx += c.h * (c.gravity.x - a.im[i] * k * ux);
            vy += c.h * (c.gravity.y - a.im[i] * k * uy);
            a.vx[i] = vx;
            a.vy[i] = vy;
        }
        a.px[i] += c.h * vx;
        a.py[i] += c.h * vy;
    }
}

void scalarVerletRange(const Arrays& a, const FlightReferenceStep& c, std::size_t i,
                       std::size_t n) {
    const double half = 0.5 * c.h * c.h;
    for (; i < n; ++i) {
        const double vx = a.vx[i], vy = a.vy[i];
        if ((a.flags[i] & (kAlive | kSleeping)) != kAlive || !(a.im[i] > 0.0)) {
            a.px[i] += c.h * vx;
            a.py[i] += c.h * vy;
            continue;
        }
        const double kr = c.halfRhoPi * a.cd[i] * a.r[i] * a.r[i] * a.im[i];
        double ux = vx - c.wind.x, uy = vy - c.wind.y;
        double k = kr * std::sqrt(ux * ux + uy * uy);
        const double ax = c.gravity.x - k * ux, ay = c.gravity.y - k * uy;
        a.px[i] += c.h * vx + half * ax;
        a.py[i] += c.h * vy + half * ay;
        ux = vx + c.h * ax - c.wind.x, uy = vy + c.h * ay - c.wind.y;
        k = kr * std::sqrt(ux * ux + uy * uy);
        const double bx = c.gravity.x - k * ux, by = c.gravity.y - k * uy;
        a.vx[i] = vx + 0.5 * c.h * (ax + bx);
        a.vy[i] = vy + 0.5 * c.h * (ay + by);
    }
}

#if defined(__SSE2__)
std::size_t sse2Range(const Arrays& a, const FlightReferenceStep& c, std::size_t n) {
    const __m128d h = _mm_set1_pd(c.h), gx = _mm_set1_pd(c.gravity.x),
                  gy = _mm_set1_pd(c.gravity.y), wx = _mm_set1_pd(c.wind.x),
                  wy = _mm_set1_pd(c.wind.y), hrp = _mm_set1_pd(c.halfRhoPi),
                  zero = _mm_setzero_pd();
    const __m128i want = _mm_set1_epi32(static_cast<int>(kAlive)),
                  bits = _mm_set1_epi32(static_cast<int>(kAlive | kSleeping));
    std::size_t i = 0;
    for (; i + 2 <= n; i += 2) {
        const __m128i f = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(a.flags + i));
        const __m128i awake32 = _mm_cmpeq_epi32(_mm_and_si128(f, bits), want);
        const __m128d im = _mm_loadu_pd(a.im + i);
        const __m128d on = _mm_and_pd(_mm_castsi128_pd(_mm_unpacklo_epi32(awake32, awake32)),
                                      _mm_cmpgt_pd(im, zero));
        const __m128d vx = _mm_loadu_pd(a.vx + i), vy = _mm_loadu_pd(a.vy + i);
        const __m128d r = _mm_loadu_pd(a.r + i);
        const __m128d ux = _mm_sub_pd(vx, wx), uy = _mm_sub_pd(vy, wy);
        const __m128d speed = _mm_sqrt_pd(_mm_add_pd(_mm_mul_pd(ux, ux), _mm_mul_pd(uy, uy)));
        const __m128d k = _mm_mul_pd(
            _mm_mul_pd(_mm_mul_pd(_mm_mul_pd(hrp, _mm_loadu_pd(a.cd + i)), r), r), speed);
        const __m128d imk = _mm_mul_pd(im, k);
        const __m128d dvx = _mm_and_pd(on, _mm_mul_pd(h, _mm_sub_pd(gx, _mm_mul_pd(imk, ux))));
        const __m128d dvy = _mm_and_pd(on, _mm_mul_pd(h, _mm_sub_pd(gy, _mm_mul_pd(imk, uy))));
        const __m128d nvx = _mm_add_pd(vx, dvx), nvy = _mm_add_pd(vy, dvy);
        _mm_storeu_pd(a.vx + i, nvx);
        _mm_storeu_pd(a.vy + i, nvy);
        _mm_storeu_pd(a.px + i, _mm_add_pd(_mm_loadu_pd(a.px + i), _mm_mul_pd(h, nvx)));
        _mm_storeu_pd(a.py + i, _mm_add_pd(_mm_loadu_pd(a.py + i), _mm_mul_pd(h, nvy)));
    }
    return i;
}
#endif

#if defined(ARTILLERY_REFERENCE_AVX2)
#pragma GCC push_options
#pragma GCC target("avx2")
std::size_t avx2Range(const Arrays& a, const FlightReferenceStep& c, std::size_t n) {
    const __m256d h = _mm256_set1_pd(c.h), gx = _mm256_set1_pd(c.gravity.x),
                  gy = _mm256_set1_pd(c.gravity.y), wx = _mm256_set1_pd(c.wind.x),
                  wy = _mm256_set1_pd(c.wind.y), hrp = _mm256_set1_pd(c.halfRhoPi),
                  zero = _mm256_setzero_pd();
    const __m128i want = _mm_set1_epi32(static_cast<int>(kAlive)),
                  bits = _mm_set1_epi32(static_cast<int>(kAlive | kSleeping));
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        const __m128i f = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a.flags + i));
        const __m256i awake = _mm256_cvtepi32_epi64(_mm_cmpeq_epi32(_mm_and_si128(f, bits), want));
        const __m256d im = _mm256_loadu_pd(a.im + i);
        const __m256d on =
            _mm256_and_pd(_mm256_castsi256_pd(awake), _mm256_cmp_pd(im, zero, _CMP_GT_OQ));
        const __m256d vx = _mm256_loadu_pd(a.vx + i), vy = _mm256_loadu_pd(a.vy + i);
        const __m256d r = _mm256_loadu_pd(a.r + i);
        const __m256d ux = _mm256_sub_pd(vx, wx), uy = _mm256_sub_pd(vy, wy);
        const __m256d speed =
            _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(ux, ux), _mm256_mul_pd(uy, uy)));
        const __m256d k = _mm256_mul_pd(
            _mm256_mul_pd(_mm256_mul_pd(_mm256_mul_pd(hrp, _mm256_loadu_pd(a.cd + i)), r), r),
            speed);
        const __m256d imk = _mm256_mul_pd(im, k);
        const __m256d dvx =
            _mm256_and_pd(on, _mm256_mul_pd(h, _mm256_sub_pd(gx, _mm256_mul_pd(imk, ux))));
        const __m256d dvy =
            _mm256_and_pd(on, _mm256_mul_pd(h, _mm256_sub_pd(gy, _mm256_mul_pd(imk, uy))));
        const __m256d nvx = _mm256_add_pd(vx, dvx), nvy = _mm256_add_pd(vy, dvy);
        _mm256_storeu_pd(a.vx + i, nvx);
        _mm256_storeu_pd(a.vy + i, nvy);
        _mm256_storeu_pd(a.px + i, _mm256_add_pd(_mm256_loadu_pd(a.px + i), _mm256_mul_pd(h, nvx)));
        _mm256_storeu_pd(a.py + i, _mm256_add_pd(_mm256_loadu_pd(a.py + i), _mm256_mul_pd(h, nvy)));
    }
    return i;
}
std::size_t avx2VerletRange(const Arrays& a, const FlightReferenceStep& c, std::size_t n) {
    const __m256d h = _mm256_set1_pd(c.h), half = _mm256_set1_pd(0.5 * c.h * c.h),
                  halfH = _mm256_set1_pd(0.5 * c.h), gx = _mm256_set1_pd(c.gravity.x),
                  gy = _mm256_set1_pd(c.gravity.y), wx = _mm256_set1_pd(c.wind.x),
                  wy = _mm256_set1_pd(c.wind.y), hrp = _mm256_set1_pd(c.halfRhoPi),
                  zero = _mm256_setzero_pd();
    const __m128i want = _mm_set1_epi32(static_cast<int>(kAlive)),
                  bits = _mm_set1_epi32(static_cast<int>(kAlive | kSleeping));
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        const __m128i f = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a.flags + i));
        const __m256i awake = _mm256_cvtepi32_epi64(_mm_cmpeq_epi32(_mm_and_si128(f, bits), want));
        const __m256d im = _mm256_loadu_pd(a.im + i);
        const __m256d on =
            _mm256_and_pd(_mm256_castsi256_pd(awake), _mm256_cmp_pd(im, zero, _CMP_GT_OQ));
        const __m256d vx = _mm256_loadu_pd(a.vx + i), vy = _mm256_loadu_pd(a.vy + i);
        const __m256d r = _mm256_loadu_pd(a.r + i);
        // k / |u| per unit mass: 1/2 rho pi Cd r^2 / m, once for both evaluations.
        const __m256d kr = _mm256_mul_pd(
            _mm256_mul_pd(_mm256_mul_pd(_mm256_mul_pd(hrp, _mm256_loadu_pd(a.cd + i)), r), r), im);
        __m256d ux = _mm256_sub_pd(vx, wx), uy = _mm256_sub_pd(vy, wy);
        __m256d k = _mm256_mul_pd(
            kr, _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(ux, ux), _mm256_mul_pd(uy, uy))));
        const __m256d ax = _mm256_and_pd(on, _mm256_sub_pd(gx, _mm256_mul_pd(k, ux)));
        const __m256d ay = _mm256_and_pd(on, _mm256_sub_pd(gy, _mm256_mul_pd(k, uy)));
        _mm256_storeu_pd(
            a.px + i, _mm256_add_pd(_mm256_loadu_pd(a.px + i),
                                    _mm256_add_pd(_mm256_mul_pd(h, vx), _mm256_mul_pd(half, ax))));
        _mm256_storeu_pd(
            a.py + i, _mm256_add_pd(_mm256_loadu_pd(a.py + i),
                                    _mm256_add_pd(_mm256_mul_pd(h, vy), _mm256_mul_pd(half, ay))));
        ux = _mm256_sub_pd(_mm256_add_pd(vx, _mm256_mul_pd(h, ax)), wx);
        uy = _mm256_sub_pd(_mm256_add_pd(vy, _mm256_mul_pd(h, ay)), wy);
        k = _mm256_mul_pd(
            kr, _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(ux, ux), _mm256_mul_pd(uy, uy))));
        const __m256d bx = _mm256_and_pd(on, _mm256_sub_pd(gx, _mm256_mul_pd(k, ux)));
        const __m256d by = _mm256_and_pd(on, _mm256_sub_pd(gy, _mm256_mul_pd(k, uy)));
        _mm256_storeu_pd(a.vx + i, _mm256_add_pd(vx, _mm256_mul_pd(halfH, _mm256_add_pd(ax, bx))));
        _mm256_storeu_pd(a.vy + i, _mm256_add_pd(vy, _mm256_mul_pd(halfH, _mm256_add_pd(ay, by))));
    }
    return i;
}
#pragma GCC pop_options
#endif

} // namespace

int flightReferenceLanes() {
#if defined(ARTILLERY_REFERENCE_AVX2)
    if (phys::processorHasAvx2()) return 4;
#endif
#if defined(__SSE2__)
    return 2;
#else
    return 1;
#endif
}

void flightReferenceStep(phys::ParticleSet& s, const FlightReferenceStep& step, int lanes) {
    const Arrays a = arraysOf(s);
    const std::size_t n = s.slots();
    std::size_t i = 0;
    lanes = std::min(lanes, flightReferenceLanes());
#if defined(ARTILLERY_REFERENCE_AVX2)
    if (lanes >= 4) i = avx2Range(a, step, n);
#endif
#if defined(__SSE2__)
    if (lanes == 2) i = sse2Range(a, step, n);
#endif
    scalarRange(a, step, i, n);
}

int flightReferenceVerletLanes() {
    return flightReferenceLanes() >= 4 ? 4 : 1;
}

void flightReferenceVerletStep(phys::ParticleSet& s, const FlightReferenceStep& step, int lanes) {
    const Arrays a = arraysOf(s);
    const std::size_t n = s.slots();
    std::size_t i = 0;
#if defined(ARTILLERY_REFERENCE_AVX2)
    if (std::min(lanes, flightReferenceVerletLanes()) >= 4) i = avx2VerletRange(a, step, n);
#else
    (void)lanes;
#endif
    scalarVerletRange(a, step, i, n);
}

void copyBytes(void* to, const void* from, std::size_t bytes) {
    std::memcpy(to, from, bytes);
}

} // namespace game::bench
