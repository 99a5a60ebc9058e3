#include "physics/collision/shapes.h"

#include <atomic>

#include <algorithm>
#include <cmath>
#include <limits>

namespace phys {

namespace {
// Unit vector of v, or `fallback` when v is (numerically) zero.
Vec2 unitOr(Vec2 v, Vec2 fallback) {
    const double l = length(v);
    return l > 1e-300 ? v / l : fallback;
}
} // namespace

// Closest point on a-b: c = a + clamp(t) (b - a), t = (p - a).(b - a) / |b - a|^2.
SurfacePoint closestPoint(const Segment& s, Vec2 p) {
    const Vec2 ab = s.b - s.a;
    const double len2 = lengthSquared(ab);
    const double t = len2 > 0.0 ? std::clamp(dot(p - s.a, ab) / len2, 0.0, 1.0) : 0.0;
    const Vec2 d = p - (s.a + t * ab);
    const double dist = length(d);
    if (dist > 1e-300) return {dist, d / dist};
    // On the segment itself the side is undefined; the left normal is as good as any
    // (worked out only here: it costs a root and two divisions).
    return {dist, unitOr(perp(ab), {0.0, 1.0})};
}

// Outside: the nearest edge point. Inside: minus the distance to the nearest edge
// line (the least separating axis), with that edge's normal.
SurfacePoint closestPoint(const ConvexPolygon& poly, Vec2 p) {
    const std::size_t n = poly.vertices.size();
    double maxSep = -std::numeric_limits<double>::infinity();
    std::size_t best = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double s = dot(poly.normals[i], p - poly.vertices[i]);
        if (s > maxSep) {
            maxSep = s;
            best = i;
        }
    }
    if (maxSep <= 0.0) return {maxSep, poly.normals[best]};
    SurfacePoint out{std::numeric_limits<double>::infinity(), poly.normals[best]};
    for (std::size_t i = 0; i < n; ++i) {
        const SurfacePoint e =
            closestPoint(Segment{poly.vertices[i], poly.vertices[(i + 1) % n]}, p);
        if (e.distance < out.distance) out = e;
    }
    return out;
}

Aabb bounds(const Segment& s) {
    return {{std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y)},
            {std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y)}};
}
Aabb bounds(const Circle& c) {
    return {c.center - Vec2{c.radius, c.radius}, c.center + Vec2{c.radius, c.radius}};
}
Aabb bounds(const ConvexPolygon& poly) {
    Aabb b{poly.vertices[0], poly.vertices[0]};
    for (const Vec2 v : poly.vertices) {
        b.lo = {std::min(b.lo.x, v.x), std::min(b.lo.y, v.y)};
        b.hi = {std::max(b.hi.x, v.x), std::max(b.hi.y, v.y)};
    }
    return b;
}

void StaticShapes::touch() {
    // One counter for the whole process: a version names one content, whichever set holds it.
    static std::atomic<std::uint64_t> next{1};
    version_ = next.fetch_add(1, std::memory_order_relaxed);
}

void StaticShapes::addSegment(Vec2 a, Vec2 b, MaterialId m) {
    segments.push_back({a, b, m});
    touch();
}

std::string StaticShapes::addPolyline(std::span<const Vec2> points, MaterialId m) {
    if (points.size() < 2) return "a polyline needs at least 2 points";
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        addSegment(points[i], points[i + 1], m);
    return {};
}

std::string StaticShapes::addCircle(Vec2 center, double radius, MaterialId m) {
    if (!(radius > 0.0) || !std::isfinite(radius)) return "circle radius must be > 0 m";
    circles.push_back({center, radius, m});
    touch();
    return {};
}

std::string StaticShapes::addPolygon(std::span<const Vec2> vertices, MaterialId m) {
    const std::size_t n = vertices.size();
    if (n < 3) return "a polygon needs at least 3 vertices";
    double area2 = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        area2 += cross(vertices[i], vertices[(i + 1) % n]);
    if (!(std::abs(area2) > 0.0)) return "polygon has zero area";
    ConvexPolygon poly;
    poly.material = m;
    poly.vertices.assign(vertices.begin(), vertices.end());
    if (area2 < 0.0) std::reverse(poly.vertices.begin(), poly.vertices.end());
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 a = poly.vertices[i], b = poly.vertices[(i + 1) % n],
                   c = poly.vertices[(i + 2) % n];
        if (cross(b - a, c - b) < 0.0)
            return "polygon is not convex (vertex " + std::to_string((i + 1) % n) + ")";
        const Vec2 e = b - a;
        if (!(lengthSquared(e) > 0.0)) return "polygon has a repeated vertex";
        poly.normals.push_back(unitOr(Vec2{e.y, -e.x}, {0.0, 1.0})); // right of a CCW edge = out
    }
    polygons.push_back(std::move(poly));
    touch();
    return {};
}

void StaticShapes::addBox(Vec2 lo, Vec2 hi, MaterialId m) {
    const Vec2 v[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
    addPolygon(v, m);
}

ShapeRef StaticShapes::ref(std::size_t i) const {
    if (i < segments.size()) return {ShapeKind::Segment, static_cast<std::uint32_t>(i)};
    i -= segments.size();
    if (i < circles.size()) return {ShapeKind::Circle, static_cast<std::uint32_t>(i)};
    return {ShapeKind::Polygon, static_cast<std::uint32_t>(i - circles.size())};
}

SurfacePoint StaticShapes::closestPoint(ShapeRef s, Vec2 p) const {
    switch (s.kind) {
    case ShapeKind::Segment:
        return phys::closestPoint(segments[s.index], p);
    case ShapeKind::Circle:
        return phys::closestPoint(circles[s.index], p);
    case ShapeKind::Polygon:
        return phys::closestPoint(polygons[s.index], p);
    }
    return {};
}

Aabb StaticShapes::bounds(ShapeRef s) const {
    switch (s.kind) {
    case ShapeKind::Segment:
        return phys::bounds(segments[s.index]);
    case ShapeKind::Circle:
        return phys::bounds(circles[s.index]);
    case ShapeKind::Polygon:
        return phys::bounds(polygons[s.index]);
    }
    return {};
}

MaterialId StaticShapes::material(ShapeRef s) const {
    switch (s.kind) {
    case ShapeKind::Segment:
        return segments[s.index].material;
    case ShapeKind::Circle:
        return circles[s.index].material;
    case ShapeKind::Polygon:
        return polygons[s.index].material;
    }
    return material::kDefault;
}

void StaticShapes::clear() {
    segments.clear();
    circles.clear();
    polygons.clear();
    touch();
}

} // namespace phys
