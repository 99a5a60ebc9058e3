#include "physics/collision/paths.h"

#include "physics/collision/substep.h"

#include <algorithm>
#include <cmath>

namespace phys {

namespace {

// m/s: slower sliding than this is rounding residue of a stop, not motion.
constexpr double kRestSlide = 1e-9;

// Removes the part of `a` that pushes into the surface (normal n points out of it).
Vec2 withoutInward(Vec2 a, Vec2 n) {
    const double an = dot(a, n);
    return an < 0.0 ? a - n * an : a;
}

// The limit of supports alternating between two surfaces, normals m (the first) and n:
// x, a rate (acceleration or velocity) that n's support left not pushing into n. If it
// pushes into m, taking that part away pushes it into n again when the two face each
// other (m.n < 0: a notch, a wedge), and so on: the alternation ends at rest between
// them. Otherwise (m.n >= 0) x slides along m, clear of n.
// (`rounding`: kVelocityRounding or kAccelRounding, as the time of impact takes them.)
Vec2 heldByBoth(Vec2 x, Vec2 m, Vec2 n, double rounding) {
    const double xm = dot(x, m);
    if (xm >= -rounding * atLeastOne(x)) return x;
    if (dot(m, n) < 0.0) return {};
    return x - m * xm;
}

} // namespace

void SubstepPaths::begin(const ParticleSet& set) {
    const std::size_t n = set.slots();
    growTo(x0_, n), growTo(y0_, n), growTo(vx0_, n), growTo(vy0_, n);
    std::copy(set.px.begin(), set.px.end(), x0_.begin());
    std::copy(set.py.begin(), set.py.end(), y0_.begin());
    std::copy(set.vx.begin(), set.vx.end(), vx0_.begin());
    std::copy(set.vy.begin(), set.vy.end(), vy0_.begin());
}

// The parabola through the start and the end of the integrator's step (time_of_impact.h).
void SubstepPaths::build(const ParticleSet& set, const std::vector<std::uint32_t>& active,
                         double h) {
    const std::size_t n = set.slots();
    growTo(path_, n), growTo(sv_, n), growTo(sa_, n), growTo(touched_, n);
    growTo(accel0_, n), growTo(lastSupport_, n);
    ++substep_;
    const double k = 2.0 / (h * h);
    for (const std::uint32_t i : active) {
        const Vec2 p0{x0_[i], y0_[i]}, v0{vx0_[i], vy0_[i]};
        const Vec2 p1{set.px[i], set.py[i]}, v1{set.vx[i], set.vy[i]};
        path_[i] = {p0, v0, (p1 - p0 - v0 * h) * k, 0.0};
        sv_[i] = v0;
        const Vec2 dv = v1 - v0;
        if (isPositiveZero(dv)) { // a sleeper, say: 0 / h is +0, no division, no root
            sa_[i] = {};
            accel0_[i] = 0.0;
        } else {
            sa_[i] = dv / h;
            accel0_[i] = length(sa_[i]);
        }
        touched_[i] = 0;
    }
}

// A settled particle's path is this one too: at rest where it started.
void SubstepPaths::straightenToEnd(const ParticleSet& set, const std::vector<std::uint32_t>& active,
                                   double h) {
    for (const std::uint32_t i : active) {
        const Vec2 start{x0_[i], y0_[i]};
        const Vec2 moved = set.position(static_cast<ParticleId>(i)) - start;
        path_[i] = {start, isPositiveZero(moved) ? Vec2{} : moved / h, {}, 0.0};
    }
}

void SubstepPaths::finish(ParticleSet& set, const std::vector<std::uint32_t>& active,
                          double h) const {
    for (const std::uint32_t i : active) {
        if (!touched_[i]) continue;
        const PathMotion& m = path_[i];
        const Vec2 p = m.position(h), v = sv_[i] + sa_[i] * (h - m.t0);
        set.px[i] = p.x, set.py[i] = p.y, set.vx[i] = v.x, set.vy[i] = v.y;
        set.flags[i] &= ~kHistory; // multi-step integrators restart from the bounced state
    }
}

void SubstepPaths::rebase(std::size_t i, double t) {
    const PathMotion m = path_[i];
    sv_[i] = sv_[i] + sa_[i] * (t - m.t0);
    path_[i] = {m.position(t), m.velocity(t), m.a, t};
}

// supportAlong n, and a particle resting on two surfaces in one sub-step (a ball in the
// notch of two sleepers, or against a wall and a sleeper) held by both: the second
// support, along n, can bend its motion back into the first, along m, and the passes
// then alternated between the two, each taking a fraction of what was left, until they
// ran out (all eight, every step, for the last awake balls of a heap). Both hold it at
// once instead, as the alternation's limit (heldByBoth).
void SubstepPaths::support(std::size_t i, Vec2 n, Vec2 vNew, const PairProperties& pp,
                           double remaining, std::uint32_t surface) {
    supportAlong(i, n, vNew, pp, remaining);
    LastSupport& last = lastSupport_[i];
    if (last.substep == substep_ && last.surface != surface) {
        const Vec2 m0 = last.normal;
        PathMotion& m = path_[i];
        m.a = heldByBoth(m.a, m0, n, kAccelRounding);
        sa_[i] = heldByBoth(sa_[i], m0, n, kAccelRounding);
        m.v = heldByBoth(m.v, m0, n, kVelocityRounding);
        sv_[i] = heldByBoth(sv_[i], m0, n, kVelocityRounding);
    }
    last = {n, surface, substep_};
}

// Resting contact: the surface (normal n) carries particle i for the `remaining` time of
// the step. The inward part of its acceleration is removed (the normal force), and
// Coulomb friction acts through the acceleration, bounded by mu |a.n|:
// - not sliding and |a_t| <= mu_s |a.n|: static friction holds, no tangential motion;
// - sliding: dynamic friction decelerates at mu_d |a.n| against the slide; if that stops
//   the slide within the step (and static friction then holds), the particle ends the
//   step at the stopping point, v^2 / (2 a), at rest, rather than sliding back.
void SubstepPaths::supportAlong(std::size_t i, Vec2 n, Vec2 vNew, const PairProperties& pp,
                                double remaining) {
    PathMotion& m = path_[i];
    const double normalAccel = std::max(-std::min(dot(m.a, n), dot(sa_[i], n)), 0.0);
    m.a = withoutInward(m.a, n);
    sa_[i] = withoutInward(sa_[i], n);
    const Vec2 at = m.a - n * dot(m.a, n), sat = sa_[i] - n * dot(sa_[i], n);
    const Vec2 vt = vNew - n * dot(vNew, n);
    const double speedT = length(vt), accelT = length(at);
    const bool holds = accelT <= pp.staticFriction * normalAccel;
    if (speedT <= kRestSlide) {
        if (holds) {
            m.v -= vt; // (rounding residue)
            sv_[i] -= vt;
            m.a -= at;
            sa_[i] -= sat;
        } else { // starts to slide along a_t
            const Vec2 dir = at / accelT;
            m.a -= dir * (pp.dynamicFriction * normalAccel);
            sa_[i] -= dir * (pp.dynamicFriction * normalAccel);
        }
        return;
    }
    const Vec2 dir = vt / speedT;
    const double dec = pp.dynamicFriction * normalAccel - dot(at, dir); // net deceleration
    if (holds && dec > 0.0 && speedT <= dec * remaining && remaining > 0.0) {
        // Stops within the step: a straight path to the stopping point, and the state
        // velocity falls to zero at the end.
        const double stopDistance = speedT * speedT / (2.0 * dec);
        m.v = m.v - dir * dot(m.v, dir) + dir * (stopDistance / remaining);
        m.a -= at;
        sa_[i] = sa_[i] - sat - vt / remaining;
        return;
    }
    m.a -= dir * (pp.dynamicFriction * normalAccel);
    sa_[i] -= dir * (pp.dynamicFriction * normalAccel);
}

} // namespace phys
