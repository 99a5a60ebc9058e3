// The match's scoring: structures knocked off their place, the score, the largest the
// rules allow and the stars (the rules themselves: game/scoring.h).
#include "game/match.h"

#include "game/scoring.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace game {

using namespace phys;

void Match::scoreToppled() {
    constexpr double kDegToRad = std::numbers::pi / 180.0;
    CannonState& shooter = cannons_[static_cast<std::size_t>(current_)];
    // Structures knocked off their place score for whoever fired last.
    for (BlockState& b : blocks_) {
        if (!b.def.target || b.toppled || !rigid_->alive(b.body)) continue;
        const RigidBodyState s = rigid_->state(b.body);
        if (shotsFired_ == 0) {
            // Settling before the first shot is not toppling: follow the block until then.
            b.def.position = s.position;
            b.def.angleDeg = s.angle / kDegToRad;
            continue;
        }
        const double moved = length(s.position - b.def.position);
        const double tilt = std::abs(std::remainder(s.angle - b.def.angleDeg * kDegToRad, 2.0 * std::numbers::pi));
        if (moved > std::max(b.def.size.x, b.def.size.y) || tilt > 0.25 * std::numbers::pi) {
            b.toppled = true;
            shooter.score += kTargetBlockPoints;
            emit(EventKind::Toppled, current_, s.position, kTargetBlockPoints);
        }
    }
    for (BlobState& b : blobs_) {
        if (!b.def.target || b.toppled) continue;
        const Vec2 p = world_.particles.position(b.center);
        if (shotsFired_ == 0) { // settling before the first shot is not toppling
            b.def.center = p;
            continue;
        }
        if (length(p - b.def.center) > b.def.radius) {
            b.toppled = true;
            shooter.score += kTargetBlobPoints;
            emit(EventKind::Toppled, current_, p, kTargetBlobPoints);
        }
    }
}

bool Match::allTargetsDown() const {
    bool allDown = true;
    for (const auto& t : targets_) allDown = allDown && t.hit;
    for (const auto& b : blocks_) allDown = allDown && (!b.def.target || b.toppled);
    for (const auto& b : blobs_) allDown = allDown && (!b.def.target || b.toppled);
    return allDown;
}

int Match::score() const {
    int s = 0;
    for (const auto& c : cannons_) s += c.score;
    return s;
}

int Match::maxScore() const { return levelScoring(level_).maxScore(); }

int Match::stars() const {
    if (level_.mode != Mode::Practice || winner_ != 0) return 0;
    const int earned = levelScoring(level_).stars(score(), true);
    return assisted_ ? std::min(earned, kAssistedMaxStars) : earned;
}

} // namespace game
