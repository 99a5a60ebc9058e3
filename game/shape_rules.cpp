#include "game/shape_rules.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace game {

using phys::Vec2;

namespace {

int orientation(Vec2 a, Vec2 b, Vec2 c) {
    const double v = phys::cross(b - a, c - a);
    return v > 0.0 ? 1 : v < 0.0 ? -1 : 0;
}

bool onSegment(Vec2 a, Vec2 b, Vec2 p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

/// Closed segments ab and cd share a point (orientation test, collinear cases included).
bool segmentsMeet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
    const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
    const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
    if (o1 != o2 && o3 != o4) return true;
    return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) ||
           (o3 == 0 && onSegment(c, d, a)) || (o4 == 0 && onSegment(c, d, b));
}

std::string shortEdge(std::size_t i) {
    return "edge " + std::to_string(i) + " is shorter than " + "5 mm"
           " (a repeated or nearly repeated point)";
}

} // namespace

std::string polylineProblem(const std::vector<Vec2>& p) {
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
        if (phys::length(p[i + 1] - p[i]) < kMinEdge) return shortEdge(i);
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
        for (std::size_t j = i + 2; j + 1 < p.size(); ++j)
            if (segmentsMeet(p[i], p[i + 1], p[j], p[j + 1]))
                return "segment " + std::to_string(i) + " crosses segment " + std::to_string(j) +
                       " (a polyline must not touch itself)";
    return "";
}

std::string polygonProblem(const std::vector<Vec2>& p) {
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i)
        if (phys::length(p[(i + 1) % n] - p[i]) < kMinEdge) return shortEdge(i);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue; // adjacent through the closing edge
            if (segmentsMeet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]))
                return "edge " + std::to_string(i) + " crosses edge " + std::to_string(j) +
                       " (a polygon must be simple, not a bow-tie or star)";
        }
    // Narrowest width of a convex polygon: the least, over its edges, of the farthest
    // vertex from that edge's line (rotating calipers, brute force for <= 8 vertices).
    double width = INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 a = p[i], e = p[(i + 1) % n] - a;
        double far = 0.0;
        for (const Vec2& v : p) far = std::max(far, std::abs(phys::cross(e, v - a)) / phys::length(e));
        width = std::min(width, far);
    }
    if (width < kMinEdge) return "it is a sliver, narrower than 5 mm";
    return "";
}

std::string blockSizeProblem(Vec2 s) {
    if (!(s.x >= kMinBlockSide && s.y >= kMinBlockSide))
        return "expected a width and height of at least 0.05 m (Box2D cannot take smaller)";
    if (std::max(s.x, s.y) > kMaxBlockAspect * std::min(s.x, s.y))
        return "expected a block at most 200 times longer than it is wide (a sliver)";
    return "";
}

namespace {

struct Frame {
    Vec2 c, u, v; // centre and unit axes
    double hx, hy;
};

Frame frame(const Box& b) {
    const double a = b.angleDeg * std::numbers::pi / 180.0;
    return {b.center, {std::cos(a), std::sin(a)}, {-std::sin(a), std::cos(a)}, 0.5 * b.size.x,
            0.5 * b.size.y};
}

double radiusAlong(const Frame& f, Vec2 axis) {
    return f.hx * std::abs(phys::dot(f.u, axis)) + f.hy * std::abs(phys::dot(f.v, axis));
}

double halfWidthX(const Box& b) { const Frame f = frame(b); return radiusAlong(f, {1.0, 0.0}); }

} // namespace

bool boxesOverlap(const Box& a, const Box& b, double slack) {
    const Frame fa = frame(a), fb = frame(b);
    const Vec2 d = fb.c - fa.c;
    for (const Vec2 axis : {fa.u, fa.v, fb.u, fb.v})
        if (std::abs(phys::dot(d, axis)) >= radiusAlong(fa, axis) + radiusAlong(fb, axis) - slack)
            return false;
    return true;
}

std::pair<int, int> firstOverlap(const std::vector<Box>& boxes, double slack) {
    std::vector<int> order(boxes.size());
    std::vector<double> lo(boxes.size()), hi(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        order[i] = static_cast<int>(i);
        const double h = halfWidthX(boxes[i]);
        lo[i] = boxes[i].center.x - h;
        hi[i] = boxes[i].center.x + h;
    }
    std::sort(order.begin(), order.end(), [&](int a, int b) { return lo[a] < lo[b]; });
    std::pair<int, int> best{-1, -1};
    for (std::size_t k = 0; k < order.size(); ++k)
        for (std::size_t m = k + 1; m < order.size() && lo[order[m]] < hi[order[k]] - slack; ++m) {
            const int i = std::min(order[k], order[m]), j = std::max(order[k], order[m]);
            if (boxesOverlap(boxes[i], boxes[j], slack) &&
                (best.first < 0 || std::pair(i, j) < best))
                best = {i, j};
        }
    return best;
}

} // namespace game
