#include "physics/model_pass.h"

#include "physics/ballistics.h"
#include "physics/cpu_features.h"

#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>
#endif

namespace phys {

ModelRule::ModelRule(const ForceDef& f, bool allowed, double tick, const std::uint8_t* teth)
    : closedFormAllowed(allowed), tethered(teth), water(f.water), waterLevel(f.waterLevel),
      gravity(length(f.gravity)), tickSeconds(tick) {
    const bool airDrag = (f.drag == DragModel::Quadratic && f.airDensity > 0.0) ||
                         (f.drag == DragModel::Linear && f.linearDrag > 0.0);
    mask = kAlive | kSleeping | kNoGravity | (airDrag ? kNoDrag : 0u) |
           (f.pointGravity ? kAttractor : 0u);
    expect = kAlive | (airDrag ? kNoDrag : 0u);
}

std::uint32_t chooseModel(ParticleSet& s, std::size_t i, const ModelRule& r) {
    std::uint32_t fl = s.flags[i];
    bool closed = closedFormCandidate(r, fl, s.invMass[i]) && !(r.tethered && r.tethered[i]);
    if (closed && r.water) {
        // Stay clear of the water for the whole tick: the farthest it can fall.
        const double reach = std::abs(s.vy[i]) * r.tickSeconds +
                             r.gravity * r.tickSeconds * r.tickSeconds + s.radius[i];
        closed = s.py[i] - reach > r.waterLevel;
    }
    if (closed) {
        if (!(fl & kBallistic)) {
            fl |= kBallistic;
            s.launchT[i] = NAN; // launched at the first sub-step
            s.flags[i] = fl;
        }
    } else if (fl & kBallistic) {
        // Promoted to the integrator from its exact state; history from before the
        // closed form would be stale.
        fl &= ~(kBallistic | kVerletPrimed | kLeapfrogPrimed);
        s.flags[i] = fl;
    }
    return fl;
}

void launchBallistic(ParticleSet& s, std::size_t i, Vec2 g, double now) {
    bool on = std::isfinite(s.launchT[i]);
    if (on) {
        const double t = now - s.launchT[i];
        const BallisticState e =
            ballisticState({s.launchX[i], s.launchY[i]}, {s.launchVx[i], s.launchVy[i]}, g, t);
        on = e.position.x == s.px[i] && e.position.y == s.py[i] && e.velocity.x == s.vx[i] &&
             e.velocity.y == s.vy[i];
    }
    if (!on) {
        s.launchX[i] = s.px[i];
        s.launchY[i] = s.py[i];
        s.launchVx[i] = s.vx[i];
        s.launchVy[i] = s.vy[i];
        s.launchT[i] = now;
    }
}

void advanceBallistic(ParticleSet& s, std::size_t i, Vec2 g, double now) {
    const BallisticState e = ballisticState({s.launchX[i], s.launchY[i]},
                                            {s.launchVx[i], s.launchVy[i]}, g, now - s.launchT[i]);
    s.px[i] = e.position.x;
    s.py[i] = e.position.y;
    s.vx[i] = e.velocity.x;
    s.vy[i] = e.velocity.y;
}

namespace {

// The whole sub-step for one particle: the reference that the lane sweeps reproduce.
// A closed-form particle is relaunched if it left its parabola and set to it at the end;
// the others take the symplectic Euler step of integrate() (forces only on the active).
template <FlightScheme Scheme> struct OneParticle {
    ParticleSet& s;
    const LocalForceLaw& law;
    Vec2 g;
    double h, start, end;

    void operator()(std::size_t i, std::uint32_t f) const {
        if (f & kBallistic) {
            launchBallistic(s, i, g, start);
            advanceBallistic(s, i, g, end);
            return;
        }
        if constexpr (Scheme == FlightScheme::VelocityVerlet)
            velocityVerletLocalStep(s, i, f, law, g, h);
        else
            symplecticLocalStep(s, i, f, law, g, h);
    }
};

#if defined(__SSE2__)
// Two particles per step in SSE2 lanes; each 32-bit flags word is copied into both
// halves of its 64-bit lane, so 32-bit compares give 64-bit lane masks.
namespace sse2 {
struct Lanes {
    static constexpr std::size_t kWidth = 2;
    using Real = __m128d;
    using Mask = __m128i;
    static Real set(double x) { return _mm_set1_pd(x); }
    static Real load(const double* p) { return _mm_loadu_pd(p); }
    static void store(double* p, Real x) { _mm_storeu_pd(p, x); }
    static Real add(Real a, Real b) { return _mm_add_pd(a, b); }
    static Real sub(Real a, Real b) { return _mm_sub_pd(a, b); }
    static Real mul(Real a, Real b) { return _mm_mul_pd(a, b); }
    static Real sqrt(Real a) { return _mm_sqrt_pd(a); }
    static Real keep(Mask m, Real a) { return _mm_and_pd(_mm_castsi128_pd(m), a); } // a or 0
    static Real select(Mask m, Real a, Real b) {
        const Real k = _mm_castsi128_pd(m);
        return _mm_or_pd(_mm_and_pd(k, a), _mm_andnot_pd(k, b));
    }
    static Mask positive(Real a) { return _mm_castpd_si128(_mm_cmpgt_pd(a, _mm_setzero_pd())); }
    static Mask flags(const std::uint32_t* f) {
        const Mask w = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(f));
        return _mm_unpacklo_epi32(w, w);
    }
    static Mask word(std::uint32_t w) { return _mm_set1_epi32(static_cast<int>(w)); }
    static Mask equal(Mask f, Mask mask, Mask want) {
        return _mm_cmpeq_epi32(_mm_and_si128(f, mask), want);
    }
    static Mask bitAnd(Mask a, Mask b) { return _mm_and_si128(a, b); }
    static Mask bitAndNot(Mask a, Mask b) { return _mm_andnot_si128(a, b); }
    static Mask bitOr(Mask a, Mask b) { return _mm_or_si128(a, b); }
    static bool any(Mask m) { return _mm_movemask_epi8(m) != 0; }
    static bool all(Mask m) { return _mm_movemask_epi8(m) == 0xffff; }
    static Mask same(Real a, Real b) { return _mm_castpd_si128(_mm_cmpeq_pd(a, b)); } // a == b
    // A true lane is -1: subtracting the mask counts it.
    static Mask count(Mask counter, Mask m) { return _mm_sub_epi64(counter, m); }
    static int total(Mask c) {
        return static_cast<int>(_mm_cvtsi128_si64(c) + _mm_cvtsi128_si64(_mm_unpackhi_epi64(c, c)));
    }
};
#include "physics/model_pass_lanes.inc"
} // namespace sse2
#endif

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define ARTILLERY_FLIGHT_AVX2 1
// Four lanes (AVX2), compiled for AVX2 here only and chosen at run time where the
// processor has it: fewer instructions per particle than the SSE2 sweep, which lets the
// sweep keep up with memory. Flags are zero-extended into 64-bit lanes.
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
struct Lanes {
    static constexpr std::size_t kWidth = 4;
    using Real = __m256d;
    using Mask = __m256i;
    static Real set(double x) { return _mm256_set1_pd(x); }
    static Real load(const double* p) { return _mm256_loadu_pd(p); }
    static void store(double* p, Real x) { _mm256_storeu_pd(p, x); }
    static Real add(Real a, Real b) { return _mm256_add_pd(a, b); }
    static Real sub(Real a, Real b) { return _mm256_sub_pd(a, b); }
    static Real mul(Real a, Real b) { return _mm256_mul_pd(a, b); }
    static Real sqrt(Real a) { return _mm256_sqrt_pd(a); }
    static Real keep(Mask m, Real a) { return _mm256_and_pd(_mm256_castsi256_pd(m), a); }
    static Real select(Mask m, Real a, Real b) {
        return _mm256_blendv_pd(b, a, _mm256_castsi256_pd(m));
    }
    static Mask positive(Real a) {
        return _mm256_castpd_si256(_mm256_cmp_pd(a, _mm256_setzero_pd(), _CMP_GT_OQ));
    }
    static Mask flags(const std::uint32_t* f) {
        return _mm256_cvtepu32_epi64(_mm_loadu_si128(reinterpret_cast<const __m128i*>(f)));
    }
    static Mask word(std::uint32_t w) { return _mm256_set1_epi64x(w); }
    static Mask equal(Mask f, Mask mask, Mask want) {
        return _mm256_cmpeq_epi64(_mm256_and_si256(f, mask), want);
    }
    static Mask bitAnd(Mask a, Mask b) { return _mm256_and_si256(a, b); }
    static Mask bitAndNot(Mask a, Mask b) { return _mm256_andnot_si256(a, b); }
    static Mask bitOr(Mask a, Mask b) { return _mm256_or_si256(a, b); }
    static bool any(Mask m) { return !_mm256_testz_si256(m, m); }
    static bool all(Mask m) { return _mm256_movemask_pd(_mm256_castsi256_pd(m)) == 0xf; }
    static Mask same(Real a, Real b) { // a == b
        return _mm256_castpd_si256(_mm256_cmp_pd(a, b, _CMP_EQ_OQ));
    }
    static Mask count(Mask counter, Mask m) { return _mm256_sub_epi64(counter, m); }
    static int total(Mask c) {
        alignas(32) long long lane[4];
        _mm256_store_si256(reinterpret_cast<__m256i*>(lane), c);
        return static_cast<int>(lane[0] + lane[1] + lane[2] + lane[3]);
    }
};
#include "physics/model_pass_lanes.inc"
} // namespace avx2
#pragma GCC pop_options
#endif

template <DragModel Drag, FlightScheme Scheme>
ModelCounts sweep(ParticleSet& s, const LocalForceLaw& law, const ModelRule* rule, Vec2 g, double h,
                  double start, double end, int lanes) {
    const OneParticle<Scheme> one{s, law, g, h, start, end};
    ModelCounts counts;
    const std::size_t n = s.slots();
    std::size_t i = 0;
    auto single = [&](std::size_t k) {
        const std::uint32_t f = rule ? chooseModel(s, k, *rule) : s.flags[k];
        one(k, f);
        countModel(counts, f, s.invMass[k]);
    };
    if (law.water) lanes = 1; // buoyancy and water drag: one particle at a time
#if defined(ARTILLERY_FLIGHT_AVX2)
    if (lanes >= 4 && processorHasAvx2())
        i = avx2::laneSweep<Drag, Scheme>(s, law, rule, g, h, start, end, i, counts, single);
#endif
#if defined(__SSE2__)
    if (lanes >= 2)
        i = sse2::laneSweep<Drag, Scheme>(s, law, rule, g, h, start, end, i, counts, single);
#endif
    for (; i < n; ++i)
        single(i);
    return counts;
}

template <FlightScheme Scheme>
ModelCounts flightPassOf(ParticleSet& s, const ForceDef& forces, const ModelRule* rule, double h,
                         double start, double end, int lanes) {
    const LocalForceLaw law(forces);
    switch (forces.drag) {
    case DragModel::Linear:
        return sweep<DragModel::Linear, Scheme>(s, law, rule, forces.gravity, h, start, end, lanes);
    case DragModel::Quadratic:
        return sweep<DragModel::Quadratic, Scheme>(s, law, rule, forces.gravity, h, start, end,
                                                   lanes);
    case DragModel::None:
        break;
    }
    return sweep<DragModel::None, Scheme>(s, law, rule, forces.gravity, h, start, end, lanes);
}

} // namespace

ModelCounts flightPass(ParticleSet& s, const ForceDef& forces, const ModelRule* rule, double h,
                       double start, double end, FlightScheme scheme, int lanes) {
    if (scheme == FlightScheme::VelocityVerlet)
        return flightPassOf<FlightScheme::VelocityVerlet>(s, forces, rule, h, start, end, lanes);
    return flightPassOf<FlightScheme::SymplecticEuler>(s, forces, rule, h, start, end, lanes);
}

ModelCounts symplecticFlightPass(ParticleSet& s, const ForceDef& forces, const ModelRule* rule,
                                 double h, double start, double end, int lanes) {
    return flightPass(s, forces, rule, h, start, end, FlightScheme::SymplecticEuler, lanes);
}

} // namespace phys
