#include "physics/collision/time_of_impact.h"

#include <limits>

namespace phys {

namespace {

// First s in [0, 1] with |p0 + s d - c| = R, entering; 0 if p0 is already inside.
std::optional<double> rayCircle(Vec2 c, double R, Vec2 p0, Vec2 p1) {
    const Vec2 d = p1 - p0, m = p0 - c;
    const double mm = dot(m, m) - R * R;
    if (mm <= 0.0) return 0.0;
    const double b = dot(d, m), dd = dot(d, d);
    if (b >= 0.0 || dd <= 0.0) return std::nullopt; // moving away, or not moving
    const double disc = b * b - dd * mm;
    if (disc < 0.0) return std::nullopt;
    const double s = (-b - std::sqrt(disc)) / dd;
    return s <= 1.0 ? std::optional<double>(std::max(s, 0.0)) : std::nullopt;
}

} // namespace

// A capsule is the segment's two end circles plus the slab |n.(p - a)| <= R between them.
std::optional<double> sweptSphere(const Segment& seg, double r, Vec2 p0, Vec2 p1) {
    if (closestPoint(seg, p0).distance <= r) return 0.0;
    double best = std::numeric_limits<double>::infinity();
    for (const Vec2 c : {seg.a, seg.b})
        if (auto s = rayCircle(c, r, p0, p1)) best = std::min(best, *s);
    const Vec2 ab = seg.b - seg.a;
    const double len2 = lengthSquared(ab);
    if (len2 > 0.0) {
        const Vec2 n = perp(ab) / std::sqrt(len2);
        const double d0 = dot(n, p0 - seg.a), dn = dot(n, p1 - p0);
        const double side = d0 > 0.0 ? 1.0 : -1.0;
        if (dn * side < 0.0) {
            const double s = (side * r - d0) / dn;
            if (s >= 0.0 && s <= 1.0) {
                const double u = dot(p0 + (p1 - p0) * s - seg.a, ab) / len2;
                if (u >= 0.0 && u <= 1.0) best = std::min(best, s);
            }
        }
    }
    return best <= 1.0 ? std::optional<double>(best) : std::nullopt;
}

std::optional<double> sweptSphere(const Circle& c, double r, Vec2 p0, Vec2 p1) {
    return rayCircle(c.center, c.radius + r, p0, p1);
}

// From outside, a sphere reaches a convex polygon through one of its edges' capsules.
std::optional<double> sweptSphere(const ConvexPolygon& poly, double r, Vec2 p0, Vec2 p1) {
    if (closestPoint(poly, p0).distance <= r) return 0.0;
    std::optional<double> best;
    const std::size_t n = poly.vertices.size();
    for (std::size_t i = 0; i < n; ++i)
        if (auto s = sweptSphere(Segment{poly.vertices[i], poly.vertices[(i + 1) % n]}, r, p0, p1))
            if (!best || *s < *best) best = s;
    return best;
}

} // namespace phys
