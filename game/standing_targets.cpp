#include "game/standing_targets.h"

#include "game/match.h"

#include <algorithm>
#include <cmath>

namespace game {

using phys::Vec2;

double StandingTarget::distanceFrom(Vec2 p) const {
    const Vec2 d = p - where;
    if (halfSize.x == 0.0 && halfSize.y == 0.0) return std::max(0.0, phys::length(d) - reach);
    // The box in its own frame: the distance past each half size, 0 inside.
    const double c = std::cos(angle), s = std::sin(angle);
    const double lx = std::abs(c * d.x + s * d.y) - halfSize.x, ly = std::abs(-s * d.x + c * d.y) - halfSize.y;
    return std::hypot(std::max(lx, 0.0), std::max(ly, 0.0));
}

std::vector<StandingTarget> standingTargets(const Match& m, int shooter) {
    std::vector<StandingTarget> out;
    std::size_t id = 0;
    if (m.level().mode == Mode::Duel) {
        for (; id < m.cannons().size(); ++id)
            if (static_cast<int>(id) != shooter && m.cannons()[id].hitPoints > 0)
                out.push_back({id, m.cannons()[id].def.position, kCannonRadius, {}, 0.0});
        return out;
    }
    for (const TargetState& t : m.targets()) {
        if (!t.hit) out.push_back({id, t.position, t.def.radius, {}, 0.0});
        ++id;
    }
    for (const BlockState& b : m.blocks()) {
        if (b.def.target && !b.toppled && m.rigid().alive(b.body)) {
            const phys::RigidBodyState s = m.rigid().state(b.body);
            out.push_back({id, s.position, 0.5 * std::max(b.def.size.x, b.def.size.y), b.def.size * 0.5, s.angle});
        }
        ++id;
    }
    for (const BlobState& b : m.blobs()) {
        if (b.def.target && !b.toppled) out.push_back({id, m.world().particles.position(b.center), b.def.radius, {}, 0.0});
        ++id;
    }
    return out;
}

} // namespace game
