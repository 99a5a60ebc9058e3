#include "game/terrain.h"

#include <algorithm>
#include <cmath>

namespace game {

Heightfield::Heightfield(const std::vector<phys::Vec2>& src, double spacing) : spacing_(spacing) {
    const double x0 = src.front().x, x1 = src.back().x;
    // At most kMaxSamples segments: every particle step and every trial shot of the
    // computer indexes them, so a 20 km ground is sampled every 2.4 m, not every 0.5 m.
    constexpr double kMaxSamples = 8192;
    const int n = static_cast<int>(std::clamp(std::ceil((x1 - x0) / spacing), 1.0, kMaxSamples));
    points_.reserve(static_cast<std::size_t>(n) + 1);
    std::size_t seg = 0;
    for (int i = 0; i <= n; ++i) {
        const double x = i == n ? x1 : x0 + (x1 - x0) * i / n;
        while (seg + 2 < src.size() && src[seg + 1].x < x) ++seg;
        const phys::Vec2 a = src[seg], b = src[std::min(seg + 1, src.size() - 1)];
        const double t = b.x > a.x ? std::clamp((x - a.x) / (b.x - a.x), 0.0, 1.0) : 0.0;
        points_.push_back({x, a.y + (b.y - a.y) * t});
    }
    spacing_ = n > 0 ? (x1 - x0) / n : spacing;
}

double Heightfield::heightAt(double x) const {
    if (x <= points_.front().x) return points_.front().y;
    if (x >= points_.back().x) return points_.back().y;
    const double f = (x - points_.front().x) / spacing_;
    const std::size_t i = std::min(static_cast<std::size_t>(f), points_.size() - 2);
    const double t = (x - points_[i].x) / (points_[i + 1].x - points_[i].x);
    return points_[i].y + (points_[i + 1].y - points_[i].y) * t;
}

bool Heightfield::carve(phys::Vec2 c, double radius) {
    bool changed = false;
    for (auto& p : points_) {
        const double dx = p.x - c.x;
        if (std::abs(dx) >= radius) continue;
        const double bottom = c.y - std::sqrt(radius * radius - dx * dx);
        if (p.y > bottom) {
            p.y = bottom;
            changed = true;
        }
    }
    return changed;
}

} // namespace game
