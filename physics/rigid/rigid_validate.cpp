// The validation of RigidWorld's definitions: the world's settings, polygons and terrain chains.
#include "physics/rigid/rigid_world.h"

#include "physics/rigid/box2d_bridge.h"

#include <box2d/box2d.h>

#include <cmath>
#include <numbers>

namespace phys {

using namespace box2d_bridge;

// ---- validation ------------------------------------------------------------------------

std::string validate(const RigidWorldDef& def, double tickSeconds) {
    if (!(tickSeconds > 0.0) || !std::isfinite(tickSeconds))
        return "tick " + fmt(tickSeconds) + " s: must be finite and > 0";
    if (!finite(def.gravity)) return "gravity " + fmt(def.gravity) + ": must be finite";
    if (def.velocityIterations < 1)
        return "velocityIterations " + std::to_string(def.velocityIterations) + ": must be >= 1";
    if (def.positionIterations < 0)
        return "positionIterations " + std::to_string(def.positionIterations) + ": must be >= 0";
    if (def.substeps < 1 || def.substeps > 64)
        return "substeps " + std::to_string(def.substeps) + ": must be in 1..64";
    const double perStep = length(def.gravity) * tickSeconds / def.substeps;
    if (!(def.restitutionThreshold > perStep) || !std::isfinite(def.restitutionThreshold))
        return "restitutionThreshold " + fmt(def.restitutionThreshold) +
               " m/s is not above the speed gravity adds in one sub-step (" + fmt(perStep) +
               " m/s = |g| x tick / substeps): resting bodies would bounce on it and never "
               "sleep; raise it above " +
               fmt(perStep) + " or use more sub-steps";
    return {};
}

std::string validateConvexPolygon(std::span<const Vec2> v) {
    const std::size_t n = v.size();
    if (n < 3 || n > static_cast<std::size_t>(b2_maxPolygonVertices))
        return "polygon has " + std::to_string(n) + " vertices; Box2D allows 3.." +
               std::to_string(b2_maxPolygonVertices) +
               " (b2_maxPolygonVertices): split it into convex pieces (addPolygon per piece)";
    for (std::size_t i = 0; i < n; ++i)
        if (!finite(v[i])) return "vertex " + std::to_string(i) + " is not finite";
    // Box2D welds points closer than half the linear slop, which would change the count.
    const double weld = 0.5 * b2_linearSlop;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (length(v[i] - v[j]) < weld)
                return "vertices " + std::to_string(i) + " " + fmt(v[i]) + " and " +
                       std::to_string(j) + " " + fmt(v[j]) + " are closer than " + fmt(weld) +
                       " m (half of b2_linearSlop): remove one";
    double area2 = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        area2 += cross(v[i], v[(i + 1) % n]);
    if (!(std::abs(area2) > 2.0 * b2_linearSlop * b2_linearSlop))
        return "polygon area " + fmt(0.5 * area2) + " m^2 is degenerate (vertices collinear?)";
    const double winding = area2 > 0.0 ? 1.0 : -1.0;
    // Strict convexity: every corner turns the same way as the winding, by a clear
    // margin (Box2D's hull would silently drop a flat corner and change the shape).
    double turning = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 e0 = v[(i + 1) % n] - v[i];
        const Vec2 e1 = v[(i + 2) % n] - v[(i + 1) % n];
        const double s = winding * cross(e0, e1) / (length(e0) * length(e1));
        if (!(s > 1e-6))
            return "corner at vertex " + std::to_string((i + 1) % n) + " " + fmt(v[(i + 1) % n]) +
                   " is " + (s < 0.0 ? "reflex" : "flat") +
                   ": the polygon must be strictly convex (split concave shapes, drop "
                   "collinear points)";
        turning += std::atan2(winding * cross(e0, e1), dot(e0, e1));
    }
    // All corners turning one way is not enough: a star pentagon does too, but its
    // turning adds up to 4 pi, not 2 pi.
    if (std::abs(turning - 2.0 * std::numbers::pi) > 1e-6)
        return "polygon crosses itself (its edges wind " + fmt(turning / (2.0 * std::numbers::pi)) +
               " times around): list the vertices in order around the outline";
    return {};
}

std::string validateChain(std::span<const Vec2> p, bool loop) {
    const std::size_t need = loop ? 3 : 2;
    if (p.size() < need)
        return std::string(loop ? "terrain loop" : "terrain polyline") + " has " +
               std::to_string(p.size()) + " points; needs at least " + std::to_string(need);
    for (std::size_t i = 0; i < p.size(); ++i)
        if (!finite(p[i])) return "terrain point " + std::to_string(i) + " is not finite";
    const std::size_t edges = loop ? p.size() : p.size() - 1;
    for (std::size_t i = 0; i < edges; ++i) {
        const std::size_t j = (i + 1) % p.size();
        if (length(p[j] - p[i]) < b2_linearSlop)
            return "terrain points " + std::to_string(i) + " " + fmt(p[i]) + " and " +
                   std::to_string(j) + " " + fmt(p[j]) + " are closer than b2_linearSlop (" +
                   fmt(b2_linearSlop) + " m): merge them";
    }
    return {};
}

} // namespace phys
