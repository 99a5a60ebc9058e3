// Narrow phase: when, within a step, does a particle's path first touch a shape?
//
// The path of a particle over a step is the parabola the integrator implies,
//   p(t) = p + v (t - t0) + a/2 (t - t0)^2,  a = 2 (p1 - p0 - v0 h) / h^2,
// chosen so that it starts where the step started and ends exactly where the
// integrator put the particle. For the integrators that are exact under constant
// acceleration (velocity Verlet, midpoint, RK4, leapfrog) a = g under gravity alone and
// the path is the exact trajectory; for explicit Euler (a = 0: a straight line) and
// symplectic Euler (a = 2g) it reproduces their own positions at any fraction of the
// step, so their error stays visible instead of being corrected away.
//
// Two ways to find the time of impact (Claypool, "Basic Game Physics", collision detection):
// - overlap testing (continuous detection off): test only where the step ends; if
//   the particle overlaps, bisect in time, moving the particle back and forth by
//   halves (five halvings are usually enough, says the lecture), then place the time inside
//   the last bracket with secant steps on the signed gap, so the bounce happens where
//   the gap is zero rather than up to dt/32 early or late. A thin wall crossed within
//   one step is never seen: it tunnels.
// - intersection testing (continuous detection on, the default): the sphere swept
//   along the chord of the path (a capsule), inflated by how far a parabola can bow
//   off its chord (|a| T^2 / 8), rejects most shapes at once and otherwise gives a
//   safe starting time; from there conservative advancement walks the true path,
//   t += gap(t) / max|v|, a step that can never pass the first contact (the gap
//   closes no faster than the speed), until the gap is below the tolerance.
#pragma once

#include "physics/collision/shapes.h"
#include "physics/vec2.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace phys {

/// A particle's path from t0 (seconds into the step) on; see the file comment.
struct PathMotion {
    Vec2 p, v, a; ///< position (m) and path velocity (m/s) at t0, path acceleration (m/s^2)
    double t0 = 0.0;
    Vec2 position(double t) const {
        const double s = t - t0;
        return p + v * s + a * (0.5 * s * s);
    }
    Vec2 velocity(double t) const { return v + a * (t - t0); }
    /// The same path seen from another particle's path (both from the later t0).
    PathMotion relativeTo(const PathMotion& o) const {
        const double t = std::max(t0, o.t0);
        return {position(t) - o.position(t), velocity(t) - o.velocity(t), a - o.a, t};
    }
};

/// Settings of the time-of-impact search (WorldDef::collision holds them).
struct ToiSettings {
    bool continuous = true; ///< swept-sphere + conservative advancement; off: overlap at step end
    int bisectionHalvings = 5; ///< halvings of the overlap bracket, 0..60
    double tolerance = 1e-9;   ///< m: a gap this small counts as touching
    int maxAdvanceIterations =
        64; ///< conservative-advancement steps before falling back to bisection
};

/// First parameter s in [0, 1] at which a sphere of radius r moving in a straight line
/// from p0 to p1 touches the shape (the swept sphere: a capsule test), or nullopt.
/// 0 when it already touches at p0.
std::optional<double> sweptSphere(const Segment& s, double r, Vec2 p0, Vec2 p1);
std::optional<double> sweptSphere(const Circle& c, double r, Vec2 p0, Vec2 p1);
std::optional<double> sweptSphere(const ConvexPolygon& poly, double r, Vec2 p0, Vec2 p1);

/// max(1, |v|), without the root when |v|^2 <= 1: the root of a number at most 1 is at
/// most 1 (it is correctly rounded and sqrt(1) = 1), so the same bits. A resting pair,
/// which every pass of a pile tests, mostly moves slower than 1 m/s.
inline double atLeastOne(Vec2 v) {
    return lengthSquared(v) <= 1.0 ? 1.0 : std::max(1.0, length(v));
}

/// Of a rate, parts this small against max(1, |rate|) are rounding (a resolved contact
/// leaves ~1e-17 m/s along its normal): of a velocity, and of an acceleration.
constexpr double kVelocityRounding = 1e-12, kAccelRounding = 1e-9;

/// Radii: a sphere inside a shape by no more than this that is not heading in is touching,
/// not in contact. The contact solver leaves resting piles that far inside each other (and
/// mends it); pushed out here instead, a ball in the notch of two others was pushed from
/// one into the other, pass after pass, by less each time (a few 1e-7 m).
constexpr double kOverlapSlop = 1e-3;

/// The time of impact of a sphere of `radius` on path `m` that starts touching a surface
/// whose normal there is `normal`: a contact only if the path heads into the surface,
/// now (v.n < 0, or v.n = 0 and a.n < 0) or, leaving slower than it is pulled back, when
/// it returns before tEnd (t = -2 v.n / a.n on a flat surface; rounding leaves v.n ~
/// +1e-17 after a resting contact, which returns at once). Normal components below
/// rounding (a resolved contact leaves ~1e-17) are zero. `g0`: the gap at the start.
inline std::optional<double> touchingTime(double g0, Vec2 normal, double radius,
                                          const PathMotion& m, double tEnd, const ToiSettings& s) {
    const double t0 = m.t0;
    const double vn = dot(normal, m.v), an = dot(normal, m.a);
    const double vEps = kVelocityRounding * atLeastOne(m.v);
    const double aEps = kAccelRounding * atLeastOne(m.a);
    const double slop = std::max(s.tolerance, kOverlapSlop * radius);
    if (g0 < -slop || vn < -vEps || (vn <= vEps && an < -aEps)) return t0;
    if (an < -aEps && -2.0 * vn / an <= tEnd - t0) return t0 - 2.0 * vn / an;
    return std::nullopt;
}

/// Finds the time of impact in [m.t0, tEnd] of a sphere of `radius` on path `m` with
/// a static shape (Shape: Segment, Circle or ConvexPolygon; see the file comment).
/// A sphere that starts touching counts only if it is heading in (or inside by more than
/// kOverlapSlop radii).
template <class Shape>
std::optional<double> timeOfImpact(const Shape& shape, double radius, const PathMotion& m,
                                   double tEnd, const ToiSettings& s) {
    auto gap = [&](double t) { return distanceTo(shape, m.position(t)) - radius; };
    const double t0 = m.t0;
    if (!(tEnd > t0)) return std::nullopt;
    const SurfacePoint start = closestPoint(shape, m.p);
    const double g0 = start.distance - radius;
    if (g0 <= s.tolerance) return touchingTime(g0, start.normal, radius, m, tEnd, s);

    // Bisection of a bracket [ta, tb] with gap(ta) > 0 >= gap(tb), then secant
    // (Illinois) steps inside it; returns a time whose gap is within the tolerance, or
    // the last time before contact.
    auto bracketRoot = [&](double ta, double ga, double tb, double gb) {
        for (int k = 0; k < s.bisectionHalvings; ++k) {
            const double tm = 0.5 * (ta + tb), gm = gap(tm);
            if (gm > 0.0)
                ta = tm, ga = gm;
            else
                tb = tm, gb = gm;
        }
        int side = 0;
        for (int k = 0; k < 60 && ga > s.tolerance; ++k) {
            const double t = ta + (tb - ta) * (ga / (ga - gb));
            const double g = gap(t);
            if (!(t > ta && t < tb)) break;
            if (g > 0.0) {
                ta = t, ga = g;
                if (side == 1) gb *= 0.5; // Illinois: halve the stale end's weight
                side = 1;
            } else {
                tb = t, gb = g;
                if (side == -1) ga *= 0.5;
                side = -1;
                if (g >= -s.tolerance) return t;
            }
        }
        return ta;
    };

    if (!s.continuous) {
        const double gEnd = gap(tEnd);
        if (gEnd > 0.0) return std::nullopt; // overlap testing sees only the end of the step
        return bracketRoot(t0, g0, tEnd, gEnd);
    }

    // Swept sphere along the chord, inflated by the bow of the parabola off its chord.
    const double T = tEnd - t0;
    const double bow = length(m.a) * T * T * 0.125;
    const auto hit = sweptSphere(shape, radius + bow + s.tolerance, m.p, m.position(tEnd));
    if (!hit) return std::nullopt;
    // Conservative advancement on the true path; |v(t)| is linear in t's components, so
    // its maximum over the interval is at an end.
    const double vmax = std::max(length(m.v), length(m.velocity(tEnd)));
    if (!(vmax > 0.0)) return std::nullopt;
    double t = t0 + *hit * T;
    double g = gap(t);
    if (g <= s.tolerance) return t; // the inflated capsule is entered before the sphere: safe
    for (int k = 0; k < s.maxAdvanceIterations; ++k) {
        const double next = t + g / vmax;
        if (next > tEnd) return std::nullopt;
        const double gn = gap(next);
        if (gn <= s.tolerance) {
            if (gn >= -s.tolerance) return next;
            return bracketRoot(t, g, next, gn); // rounding overshoot: pin the root
        }
        t = next;
        g = gn;
    }
    // Grazing: advancement crawls. Fall back to an overlap test at the end.
    const double gEnd = gap(tEnd);
    if (gEnd > 0.0) return std::nullopt;
    return bracketRoot(t, g, tEnd, gEnd);
}

} // namespace phys
