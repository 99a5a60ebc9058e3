#include "physics/collision/simd/contact_rows.h"

#include "physics/cpu_features.h"

#include <algorithm>
#include <cmath>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>
#define ARTILLERY_CONTACT_AVX2 1
#endif

namespace phys {

void ContactRows::resize(std::size_t n) {
    for (auto* c : {&a, &readB, &contact, &all.pushB, &band.pushB})
        c->resize(n);
    shape.resize(n);
    for (auto* c : {&nx, &ny, &closing, &friction, &reach, &cap, &normalImpulse, &tangentImpulse})
        c->resize(n);
    for (Masses* m : {&all, &band})
        for (auto* c : {&m->wa, &m->wb, &m->mass, &m->fa, &m->fb})
            c->resize(n);
    changed.resize(n, 0);
}

namespace {

// One velocity row: the reference the lanes reproduce.
inline void impulseRow(ContactRows& r, const ContactRows::Masses& m, std::size_t k, Vec2* v,
                       std::uint8_t* touched) {
    const double mass = m.mass[k];
    if (!(mass > 0.0)) return;
    const std::uint32_t a = r.a[k], pushB = m.pushB[k];
    const Vec2 vrel = v[a] - v[r.readB[k]];
    const Vec2 normal{r.nx[k], r.ny[k]}, t = perp(normal);
    const double normalImpulse = r.normalImpulse[k], tangentImpulse = r.tangentImpulse[k];
    const double total = std::max(normalImpulse - (dot(vrel, normal) + r.closing[k]) * mass, 0.0);
    const double jn = total - normalImpulse;
    r.normalImpulse[k] = total;
    const double limit = r.friction[k] * total;
    const double tangential = std::clamp(tangentImpulse - dot(vrel, t) * mass, -limit, limit);
    const double jt = tangential - tangentImpulse;
    r.tangentImpulse[k] = tangential;
    if (jn == 0.0 && jt == 0.0) return;
    const Vec2 J = normal * jn + t * jt;
    v[a] += J * m.wa[k];
    v[pushB] -= J * m.wb[k];
    touched[a] = 1;
    touched[pushB] = 1;
}

} // namespace

namespace detail {

bool projectPair(const ContactRows& r, const ContactRows::Masses& m, std::size_t k, Vec2* p,
                 std::uint8_t* touched, double deepShare) {
    if (!(m.mass[k] > 0.0)) return false;
    const std::uint32_t a = r.a[k], pushB = m.pushB[k];
    const double reach = r.reach[k];
    const Vec2 d = p[a] - p[r.readB[k]];
    const double distanceSquared = dot(d, d);
    if (distanceSquared >= reach * reach) return false;
    const double L = std::sqrt(distanceSquared);
    const Vec2 normal = L > 0.0 ? Vec2{d.x / L, d.y / L} : Vec2{0.0, 1.0};
    const double depth = std::min(reach - L, r.cap[k]);
    if (!(depth > 0.0)) return false;
    const Vec2 move = normal * depth;
    p[a] += move * m.fa[k];
    p[pushB] -= move * m.fb[k];
    touched[a] = 1;
    touched[pushB] = 1;
    return depth > deepShare * r.cap[k];
}

} // namespace detail

#if defined(ARTILLERY_CONTACT_AVX2)
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {

// Four (x, y) pairs, at the slots idx[0..3], as four x and four y.
inline void gather(const Vec2* v, const std::uint32_t* idx, __m256d& x, __m256d& y) {
    const __m128d p0 = _mm_loadu_pd(&v[idx[0]].x), p1 = _mm_loadu_pd(&v[idx[1]].x);
    const __m128d p2 = _mm_loadu_pd(&v[idx[2]].x), p3 = _mm_loadu_pd(&v[idx[3]].x);
    const __m256d even = _mm256_insertf128_pd(_mm256_castpd128_pd256(p0), p2, 1);
    const __m256d odd = _mm256_insertf128_pd(_mm256_castpd128_pd256(p1), p3, 1);
    x = _mm256_unpacklo_pd(even, odd);
    y = _mm256_unpackhi_pd(even, odd);
}

// The inverse of gather, lane 0 first.
inline void scatter(Vec2* v, const std::uint32_t* idx, __m256d x, __m256d y) {
    const __m256d even = _mm256_unpacklo_pd(x, y), odd = _mm256_unpackhi_pd(x, y);
    _mm_storeu_pd(&v[idx[0]].x, _mm256_castpd256_pd128(even));
    _mm_storeu_pd(&v[idx[1]].x, _mm256_castpd256_pd128(odd));
    _mm_storeu_pd(&v[idx[2]].x, _mm256_extractf128_pd(even, 1));
    _mm_storeu_pd(&v[idx[3]].x, _mm256_extractf128_pd(odd, 1));
}

// Keeps the lanes a step changed, for markTouched.
inline void keepChanged(std::uint64_t* changed, std::size_t k, __m256d mask) {
    auto* at = reinterpret_cast<__m256i*>(changed + k);
    _mm256_storeu_si256(at, _mm256_or_si256(_mm256_loadu_si256(at), _mm256_castpd_si256(mask)));
}

// std::max(x, y) is (x < y) ? y : x; MAXPD(s1, s2) is s1 > s2 ? s1 : s2: so (y, x).
inline __m256d maxOf(__m256d x, __m256d y) {
    return _mm256_max_pd(y, x);
}
// std::min(x, y) is (y < x) ? y : x; MINPD(s1, s2) is s1 < s2 ? s1 : s2: so (y, x).
inline __m256d minOf(__m256d x, __m256d y) {
    return _mm256_min_pd(y, x);
}
inline __m256d negate(__m256d x) {
    return _mm256_xor_pd(x, _mm256_set1_pd(-0.0));
}
inline __m256d load(const double* c, std::size_t k) {
    return _mm256_loadu_pd(c + k);
}
// a where m, else b.
inline __m256d where(__m256d m, __m256d a, __m256d b) {
    return _mm256_blendv_pd(b, a, m);
}

// The columns a sweep reads with one set of masses, as plain pointers: taken once a sweep,
// not once every four rows (after each store through a vector's data, the compiler would
// load them all again: an __m256i store may alias anything).
struct Lanes {
    const std::uint32_t *a, *readB, *pushB;
    const std::uint8_t* shape;
    const double *nx, *ny, *closing, *friction, *reach, *cap;
    const double *wa, *wb, *mass, *fa, *fb;
    double *normalImpulse, *tangentImpulse;
    std::uint64_t* changed;
    Lanes(ContactRows& r, const ContactRows::Masses& m)
        : a(r.a.data()), readB(r.readB.data()), pushB(m.pushB.data()), shape(r.shape.data()),
          nx(r.nx.data()), ny(r.ny.data()), closing(r.closing.data()), friction(r.friction.data()),
          reach(r.reach.data()), cap(r.cap.data()), wa(m.wa.data()), wb(m.wb.data()),
          mass(m.mass.data()), fa(m.fa.data()), fb(m.fb.data()),
          normalImpulse(r.normalImpulse.data()), tangentImpulse(r.tangentImpulse.data()),
          changed(r.changed.data()) {}
};

// What a lane step read of its two sides: a, and b (at b, or still).
struct Sides {
    __m256d ax, ay, bx, by;
};

// a += (x, y) ka and, where b's push goes (b itself, or the sink), b -= (x, y) kb, in the
// lanes that changed; the others write back what they read. Every lane writes: no two
// lanes of a wavefront share a particle, and the shared sink's value is never read.
inline void push(Vec2* s, const std::uint32_t* a, const std::uint32_t* pushB, __m256d changed,
                 const Sides& read, __m256d x, __m256d y, __m256d ka, __m256d kb) {
    scatter(s, a, where(changed, _mm256_add_pd(read.ax, _mm256_mul_pd(x, ka)), read.ax),
            where(changed, _mm256_add_pd(read.ay, _mm256_mul_pd(y, ka)), read.ay));
    scatter(s, pushB, where(changed, _mm256_sub_pd(read.bx, _mm256_mul_pd(x, kb)), read.bx),
            where(changed, _mm256_sub_pd(read.by, _mm256_mul_pd(y, kb)), read.by));
}

inline void impulseRows4(const Lanes& r, std::size_t k, Vec2* v) {
    const __m256d zero = _mm256_setzero_pd();
    const __m256d mass = load(r.mass, k);
    const __m256d active = _mm256_cmp_pd(mass, zero, _CMP_GT_OQ);
    if (_mm256_testz_pd(active, active)) return;
    __m256d vax, vay, vbx, vby;
    gather(v, r.a + k, vax, vay);
    gather(v, r.readB + k, vbx, vby);
    const __m256d vrx = _mm256_sub_pd(vax, vbx), vry = _mm256_sub_pd(vay, vby);
    const __m256d nx = load(r.nx, k), ny = load(r.ny, k);
    const __m256d tx = negate(ny), ty = nx; // perp(normal)
    const __m256d normalImpulse = load(r.normalImpulse, k);
    const __m256d tangentImpulse = load(r.tangentImpulse, k);
    const __m256d vn = _mm256_add_pd(_mm256_mul_pd(vrx, nx), _mm256_mul_pd(vry, ny));
    const __m256d total = maxOf(
        _mm256_sub_pd(normalImpulse, _mm256_mul_pd(_mm256_add_pd(vn, load(r.closing, k)), mass)),
        zero);
    const __m256d jn = _mm256_sub_pd(total, normalImpulse);
    const __m256d limit = _mm256_mul_pd(load(r.friction, k), total);
    const __m256d vt = _mm256_add_pd(_mm256_mul_pd(vrx, tx), _mm256_mul_pd(vry, ty));
    // std::clamp(x, lo, hi) with lo <= hi: max(lo, min(hi, x)), as chosen above.
    const __m256d tangential =
        maxOf(minOf(_mm256_sub_pd(tangentImpulse, _mm256_mul_pd(vt, mass)), limit), negate(limit));
    const __m256d jt = _mm256_sub_pd(tangential, tangentImpulse);
    _mm256_storeu_pd(r.normalImpulse + k, where(active, total, normalImpulse));
    _mm256_storeu_pd(r.tangentImpulse + k, where(active, tangential, tangentImpulse));
    const __m256d still =
        _mm256_and_pd(_mm256_cmp_pd(jn, zero, _CMP_EQ_OQ), _mm256_cmp_pd(jt, zero, _CMP_EQ_OQ));
    const __m256d changed = _mm256_andnot_pd(still, active);
    if (_mm256_testz_pd(changed, changed)) return;
    const __m256d jx = _mm256_add_pd(_mm256_mul_pd(nx, jn), _mm256_mul_pd(tx, jt));
    const __m256d jy = _mm256_add_pd(_mm256_mul_pd(ny, jn), _mm256_mul_pd(ty, jt));
    push(v, r.a + k, r.pushB + k, changed, {vax, vay, vbx, vby}, jx, jy, load(r.wa, k),
         load(r.wb, k));
    keepChanged(r.changed, k, changed);
}

void impulseSweep(ContactRows& rows, const ContactRows::Masses& m, std::size_t from,
                  std::size_t to, Vec2* v) {
    const Lanes r(rows, m);
    for (std::size_t k = from; k < to; k += 4)
        impulseRows4(r, k, v);
}

// Returns the lanes whose push was deep (deeper than deepShare of its cap).
inline __m256d projectPairs4(const Lanes& r, std::size_t k, Vec2* p, __m256d deepShare) {
    const __m256d zero = _mm256_setzero_pd();
    const __m256d active = _mm256_cmp_pd(load(r.mass, k), zero, _CMP_GT_OQ);
    if (_mm256_testz_pd(active, active)) return zero;
    __m256d pax, pay, pbx, pby;
    gather(p, r.a + k, pax, pay);
    gather(p, r.readB + k, pbx, pby);
    const __m256d dx = _mm256_sub_pd(pax, pbx), dy = _mm256_sub_pd(pay, pby);
    const __m256d distanceSquared = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
    const __m256d reach = load(r.reach, k);
    // The one-row step returns when it has no mass, or when distanceSquared >= reach^2 (so
    // NaN goes on).
    const __m256d near = _mm256_and_pd(
        active, _mm256_cmp_pd(distanceSquared, _mm256_mul_pd(reach, reach), _CMP_NGE_UQ));
    if (_mm256_testz_pd(near, near)) return zero;
    const __m256d L = _mm256_sqrt_pd(distanceSquared);
    const __m256d apart = _mm256_cmp_pd(L, zero, _CMP_GT_OQ);
    const __m256d nx = where(apart, _mm256_div_pd(dx, L), zero);
    const __m256d ny = where(apart, _mm256_div_pd(dy, L), _mm256_set1_pd(1.0));
    const __m256d cap = load(r.cap, k);
    const __m256d depth = minOf(_mm256_sub_pd(reach, L), cap);
    const __m256d changed = _mm256_and_pd(near, _mm256_cmp_pd(depth, zero, _CMP_GT_OQ));
    if (_mm256_testz_pd(changed, changed)) return zero;
    const __m256d mx = _mm256_mul_pd(nx, depth), my = _mm256_mul_pd(ny, depth);
    push(p, r.a + k, r.pushB + k, changed, {pax, pay, pbx, pby}, mx, my, load(r.fa, k),
         load(r.fb, k));
    keepChanged(r.changed, k, changed);
    return _mm256_and_pd(changed, _mm256_cmp_pd(depth, _mm256_mul_pd(deepShare, cap), _CMP_GT_OQ));
}

std::size_t projectPairRuns(ContactRows& rows, const ContactRows::Masses& m, std::size_t from,
                            std::size_t to, Vec2* p, double deepShare, bool& deep) {
    const Lanes r(rows, m);
    const __m256d share = _mm256_set1_pd(deepShare);
    __m256d deepLanes = _mm256_setzero_pd();
    std::size_t k = from;
    for (; k < to && !r.shape[k]; k += 4)
        deepLanes = _mm256_or_pd(deepLanes, projectPairs4(r, k, p, share));
    deep = deep || !_mm256_testz_pd(deepLanes, deepLanes);
    return k;
}

} // namespace avx2
#pragma GCC pop_options
#endif

bool contactLanesAvailable() {
#if defined(ARTILLERY_CONTACT_AVX2)
    return processorHasAvx2();
#else
    return false;
#endif
}

void sweepImpulseRows(ContactRows& rows, const ContactRows::Masses& masses,
                         std::size_t from, std::size_t to, Vec2* velocity, std::uint8_t* touched,
                         bool lanes) {
#if defined(ARTILLERY_CONTACT_AVX2)
    if (lanes) {
        avx2::impulseSweep(rows, masses, from, to, velocity);
        return;
    }
#else
    (void)lanes;
#endif
    for (std::size_t k = from; k < to; ++k)
        impulseRow(rows, masses, k, velocity, touched);
}

namespace detail {

std::size_t projectPairRuns(ContactRows& rows, const ContactRows::Masses& masses,
                            std::size_t from, std::size_t to, Vec2* position, double deepShare,
                            bool& deep) {
#if defined(ARTILLERY_CONTACT_AVX2)
    return avx2::projectPairRuns(rows, masses, from, to, position, deepShare, deep);
#else
    // never called without AVX2
    (void)rows, (void)masses, (void)to, (void)position, (void)deepShare, (void)deep;
    return from;
#endif
}

} // namespace detail

} // namespace phys
