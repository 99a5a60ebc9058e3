#include "game/ai_cover.h"

#include <algorithm>
#include <cmath>

namespace game {

using phys::Vec2;

namespace {
constexpr double kColumn = 2.0; // m
} // namespace

bool BlockCover::Box::contains(Vec2 p) const {
    // Into the block's frame: rotate by -angle about its centre.
    const Vec2 d = p - centre;
    const double x = d.x * cos + d.y * sin, y = -d.x * sin + d.y * cos;
    return std::abs(x) <= half.x && std::abs(y) <= half.y;
}

long BlockCover::column(double x) const { return static_cast<long>(std::floor(x / kColumn)); }

BlockCover::BlockCover(const Match& match, Vec2 target, double margin) {
    for (const BlockState& b : match.blocks()) {
        if (!match.rigid().alive(b.body)) continue;
        const phys::RigidBodyState s = match.rigid().state(b.body);
        Box box{s.position, b.def.size * 0.5 + Vec2{margin, margin}, std::cos(s.angle),
                std::sin(s.angle)};
        if (box.contains(target)) continue;
        // The columns its bounding circle reaches.
        const double reach = length(box.half);
        const auto index = static_cast<std::uint32_t>(boxes_.size());
        for (long c = column(s.position.x - reach); c <= column(s.position.x + reach); ++c)
            columns_.push_back({c, index});
        boxes_.push_back(box);
    }
    std::sort(columns_.begin(), columns_.end());
}

std::size_t BlockCover::firstBlocked(const std::vector<Vec2>& path) const {
    if (boxes_.empty()) return path.size();
    for (std::size_t i = 0; i < path.size(); ++i) {
        const long c = column(path[i].x);
        auto it = std::lower_bound(columns_.begin(), columns_.end(), std::pair<long, std::uint32_t>{c, 0});
        for (; it != columns_.end() && it->first == c; ++it)
            if (boxes_[it->second].contains(path[i])) return i;
    }
    return path.size();
}

} // namespace game
