// Static shapes the particles collide with: segments (and polylines made of them:
// terrain, walls), circles and convex polygons. They never move; each has a material.
//
// Every shape answers one question, the closest point: for a point p, the signed
// distance from the shape's surface to p (negative inside a circle or polygon) and
// the outward unit normal there. A particle of radius r touches the shape when that
// distance equals r; the narrow phase finds when that happens.
#pragma once

#include "physics/materials.h"
#include "physics/vec2.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace phys {

/// Axis-aligned box, m.
struct Aabb {
    Vec2 lo, hi;
    bool overlaps(const Aabb& o) const {
        return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y;
    }
    /// overlaps() without branches, for loops where which boxes overlap is a coin toss.
    bool overlapsBranchless(const Aabb& o) const {
        return (lo.x <= o.hi.x) & (o.lo.x <= hi.x) & (lo.y <= o.hi.y) & (o.lo.y <= hi.y);
    }
    /// `o` lies inside this box, edges included (without branches).
    bool contains(const Aabb& o) const {
        return (lo.x <= o.lo.x) & (lo.y <= o.lo.y) & (o.hi.x <= hi.x) & (o.hi.y <= hi.y);
    }
};

/// A two-sided line segment a-b (a zero-thickness wall; a polyline is a chain of them).
struct Segment {
    Vec2 a, b;
    MaterialId material = material::kDefault;
};

struct Circle {
    Vec2 center;
    double radius = 1.0; ///< m, > 0
    MaterialId material = material::kDefault;
};

/// A convex polygon, vertices counter-clockwise; normals[i] is the outward unit normal
/// of the edge vertices[i] -> vertices[i+1].
struct ConvexPolygon {
    std::vector<Vec2> vertices;
    std::vector<Vec2> normals;
    MaterialId material = material::kDefault;
};

enum class ShapeKind : std::uint8_t { Segment, Circle, Polygon };

/// One static shape by kind and index into its list.
struct ShapeRef {
    ShapeKind kind = ShapeKind::Segment;
    std::uint32_t index = 0;
};

/// Closest-point answer: signed distance from the surface to the point, m, and the
/// outward unit normal of the surface there (points from the shape to the point).
struct SurfacePoint {
    double distance = 0.0;
    Vec2 normal{0.0, 1.0};
};

SurfacePoint closestPoint(const Segment& s, Vec2 p);
SurfacePoint closestPoint(const ConvexPolygon& poly, Vec2 p);
/// Inline, with one root: every pair of particles the narrow phase tests asks for it,
/// and its callers mostly read the normal only when the two touch.
inline SurfacePoint closestPoint(const Circle& c, Vec2 p) {
    const Vec2 d = p - c.center;
    const double l = length(d);
    return {l - c.radius, l > 1e-300 ? d / l : Vec2{0.0, 1.0}};
}

/// closestPoint(shape, p).distance alone, to the same bits, without the normal (the
/// narrow phase's gap function asks for it many times per pair).
inline double distanceTo(const Segment& s, Vec2 p) {
    const Vec2 ab = s.b - s.a;
    const double len2 = lengthSquared(ab);
    const double t = len2 > 0.0 ? std::clamp(dot(p - s.a, ab) / len2, 0.0, 1.0) : 0.0;
    return length(p - (s.a + t * ab));
}
inline double distanceTo(const Circle& c, Vec2 p) {
    return length(p - c.center) - c.radius;
}
inline double distanceTo(const ConvexPolygon& poly, Vec2 p) {
    return closestPoint(poly, p).distance;
}

Aabb bounds(const Segment& s);
Aabb bounds(const Circle& c);
Aabb bounds(const ConvexPolygon& poly);

/// All static shapes of a world.
struct StaticShapes {
    std::vector<Segment> segments;
    std::vector<Circle> circles;
    std::vector<ConvexPolygon> polygons;

    void addSegment(Vec2 a, Vec2 b, MaterialId m = material::kDefault);
    /// A chain of segments through the points (terrain, walls). Returns "" or an error.
    std::string addPolyline(std::span<const Vec2> points, MaterialId m = material::kDefault);
    /// Returns "" or an error (radius must be > 0).
    std::string addCircle(Vec2 center, double radius, MaterialId m = material::kDefault);
    /// Returns "" when added, else why not (fewer than 3 vertices, not convex, degenerate).
    /// Clockwise input is reversed to counter-clockwise.
    std::string addPolygon(std::span<const Vec2> vertices, MaterialId m = material::kDefault);
    /// An axis-aligned box as a polygon (walls, platforms).
    void addBox(Vec2 lo, Vec2 hi, MaterialId m = material::kDefault);

    std::size_t count() const { return segments.size() + circles.size() + polygons.size(); }
    /// The i-th shape in the order segments, circles, polygons.
    ShapeRef ref(std::size_t i) const;
    SurfacePoint closestPoint(ShapeRef s, Vec2 p) const;
    Aabb bounds(ShapeRef s) const;
    MaterialId material(ShapeRef s) const;
    void clear();

    /// Changes whenever a shape is added or the set is cleared, and is unique across all
    /// StaticShapes (a copy keeps it: same version, same shapes). The broad phase keeps its
    /// index of the static shapes until the version changes. Code that edits the vectors
    /// above directly must call touch() afterwards.
    std::uint64_t version() const { return version_; }
    void touch();

  private:
    std::uint64_t version_ = 0;
};

/// Calls f with the concrete shape behind a reference (no virtual call per contact).
template <class F> auto withShape(const StaticShapes& shapes, ShapeRef ref, F&& f) {
    switch (ref.kind) {
    case ShapeKind::Circle:
        return f(shapes.circles[ref.index]);
    case ShapeKind::Polygon:
        return f(shapes.polygons[ref.index]);
    case ShapeKind::Segment:
        break;
    }
    return f(shapes.segments[ref.index]);
}

} // namespace phys
