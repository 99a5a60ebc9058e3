#include "game/effects/shot_feedback.h"

#include "game/match.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace game {

using phys::Vec2;

std::string missText(double missMetres, bool longShot) {
    char text[64];
    std::snprintf(text, sizeof text, "missed by %.1f m, %s", missMetres,
                  longShot ? "long" : "short");
    return text;
}

std::vector<TargetMark> standingTargets(const Match& m) {
    std::vector<TargetMark> out;
    if (m.level().mode == Mode::Duel) {
        for (std::size_t i = 0; i < m.cannons().size(); ++i)
            if (static_cast<int>(i) != m.currentPlayer() && m.cannons()[i].hitPoints > 0)
                out.push_back({m.cannons()[i].def.position, kCannonRadius});
        return out;
    }
    for (const TargetState& t : m.targets())
        if (!t.hit) out.push_back({t.position, t.def.radius});
    for (const BlockState& b : m.blocks())
        if (b.def.target && !b.toppled && m.rigid().alive(b.body))
            out.push_back(
                {m.rigid().state(b.body).position, 0.5 * std::max(b.def.size.x, b.def.size.y)});
    for (const BlobState& b : m.blobs())
        if (b.def.target && !b.toppled)
            out.push_back({m.world().particles.position(b.center), b.def.radius});
    return out;
}

void ShotFeedback::reset() {
    *this = ShotFeedback();
}

void ShotFeedback::event(const Match& m, const GameEvent& e) {
    char text[32];
    switch (e.kind) {
    case EventKind::Fired:
        inFlight_ = true;
        scored_ = false;
        shooter_ = e.player;
        shellAt_ = e.where;
        aimedAt_ = standingTargets(m);
        model_ = e.model;
        exact_.reset();
        // The last shot's notes give way to the new shot's.
        std::erase_if(notes_, [](const ShotNote& n) {
            return n.kind == ShotNote::Kind::Miss || n.kind == ShotNote::Kind::Exact;
        });
        break;
    case EventKind::Landed:
        if (inFlight_ && (exact_ = exactPathOf(m, e, model_)))
            notes_.push_back({ShotNote::Kind::Exact, exact_->exactLanding, exactPathText(*exact_), 0.0, 8.0});
        break;
    case EventKind::Burst:
        shellAt_ = e.where;
        break;
    case EventKind::TargetHit:
    case EventKind::Toppled:
        scored_ = true;
        std::snprintf(text, sizeof text, "+%.0f", e.value);
        notes_.push_back({ShotNote::Kind::Points, e.where, text, 0.0, 1.5});
        notes_.push_back({ShotNote::Kind::Hit, e.where, {}, 0.0, 0.8});
        break;
    case EventKind::CannonHit:
        scored_ = true;
        notes_.push_back({ShotNote::Kind::Points, e.where, "HIT!", 0.0, 1.5});
        notes_.push_back({ShotNote::Kind::Hit, e.where, {}, 0.0, 0.8});
        break;
    case EventKind::ShotOver:
        if (inFlight_) landed(m, e.value);
        inFlight_ = false;
        break;
    default:
        break;
    }
}

void ShotFeedback::landed(const Match& m, double closestMiss) {
    landings_.assign(1, shellAt_);
    if (scored_ || aimedAt_.empty()) return;
    // The nearest target to where the shell came down, of those standing when it left.
    const TargetMark* nearest = nullptr;
    double best = INFINITY;
    for (const TargetMark& t : aimedAt_) {
        const double d = length(shellAt_ - t.where) - t.reach;
        if (d < best) best = d, nearest = &t;
    }
    const double miss = closestMiss >= 0.0 ? closestMiss : std::max(0.0, best);
    // Long: beyond the target seen from the cannon that fired.
    const Vec2 cannon = m.cannons()[static_cast<std::size_t>(shooter_)].def.position;
    const double side = nearest->where.x >= cannon.x ? 1.0 : -1.0;
    const bool longShot = (shellAt_.x - nearest->where.x) * side > 0.0;
    notes_.push_back({ShotNote::Kind::Miss, shellAt_, missText(miss, longShot), 0.0, 6.0});
}

void ShotFeedback::tick(const Match& m, double dt) {
    if (const auto shell = m.shell()) shellAt_ = m.world().particles.position(*shell);
    for (ShotNote& n : notes_)
        n.age += dt;
    std::erase_if(notes_, [](const ShotNote& n) { return n.age > n.life; });
}

} // namespace game
