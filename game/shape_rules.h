// What the physics can take, as pure checks on level geometry. Each returns an empty
// string when the shape is fine, or what is wrong with it in words for the loader's
// message. The limits are Box2D's and the particle layer's:
//  - Box2D welds polygon vertices closer than half its linear slop (5 mm) and asserts
//    a polygon's area above FLT_EPSILON, so every edge must be at least kMinEdge (one slop) long
//    and every block side kMinBlockSide;
//  - a sliver (a long thin block) makes Box2D's contact solver stiff: a block's aspect
//    ratio stays within kMaxBlockAspect;
//  - the particle layer's segment and polygon tests assume simple shapes: no repeated
//    vertex, no zero-length edge, no edge crossing another.
#pragma once

#include "physics/vec2.h"

#include <string>
#include <vector>

namespace game {

inline constexpr double kMinEdge = 0.005;       ///< m, Box2D's linear slop
inline constexpr double kMinBlockSide = 0.05;   ///< m
inline constexpr double kMaxBlockAspect = 200.0;

/// An open polyline: every segment at least kMinEdge long, no segment crossing a
/// non-adjacent one.
std::string polylineProblem(const std::vector<phys::Vec2>& points);
/// A closed convex polygon, counter-clockwise: edges at least kMinEdge, simple (no
/// crossing edges), and its narrowest width at least kMinEdge.
std::string polygonProblem(const std::vector<phys::Vec2>& points);
/// A box of the given width and height.
std::string blockSizeProblem(phys::Vec2 size);

/// An oriented box (centre, size, angle in degrees) for overlap tests.
struct Box {
    phys::Vec2 center, size;
    double angleDeg = 0.0;
};
/// True when two boxes overlap by more than `slack` metres (separating-axis test on
/// the four face normals).
bool boxesOverlap(const Box& a, const Box& b, double slack);
/// The first pair (i < j) of boxes that overlap by more than `slack`, or {-1, -1}.
/// Sweep over x-sorted bounding boxes: about n log n for boxes that are apart.
std::pair<int, int> firstOverlap(const std::vector<Box>& boxes, double slack);

} // namespace game
