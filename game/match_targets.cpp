// Moving targets: where a target is along its path at a time, and the match moving them.
#include "game/match.h"

#include <algorithm>
#include <cmath>

namespace game {

using namespace phys;

Vec2 targetPositionAt(const Target& target, double t) {
    const auto& path = target.path;
    if (path.size() < 2) return target.position;
    double total = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) total += length(path[i] - path[i - 1]);
    if (total <= 0.0) return target.position;
    double d = std::fmod(target.speedMps * t, 2.0 * total);
    if (d > total) d = 2.0 * total - d;
    for (std::size_t i = 1; i < path.size(); ++i) {
        const double seg = length(path[i] - path[i - 1]);
        if (d <= seg || i + 1 == path.size())
            return path[i - 1] + (path[i] - path[i - 1]) * (seg > 0.0 ? std::min(1.0, d / seg) : 0.0);
        d -= seg;
    }
    return target.position;
}

void Match::updateTargets() {
    for (TargetState& s : targets_)
        if (s.def.path.size() >= 2) s.position = targetPositionAt(s.def, time());
}

} // namespace game
