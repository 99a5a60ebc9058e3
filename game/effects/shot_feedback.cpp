#include "game/effects/shot_feedback.h"

#include "game/match.h"

#include <algorithm>
#include <cmath>

namespace game {

using phys::Vec2;

void ShotFeedback::reset() {
    *this = ShotFeedback();
}

void ShotFeedback::event(const Match& m, const GameEvent& e) {
    switch (e.kind) {
    case EventKind::Fired:
        inFlight_ = true;
        scored_ = false;
        shellAt_ = e.where;
        model_ = e.model;
        exact_.reset();
        // The last shot's notes give way to the new shot's.
        std::erase_if(notes_, [](const ShotNote& n) {
            return n.kind == ShotNote::Kind::Miss || n.kind == ShotNote::Kind::Verdict ||
                   n.kind == ShotNote::Kind::Exact;
        });
        break;
    case EventKind::Landed:
        if (inFlight_ && (exact_ = exactPathOf(m, e, model_)))
            notes_.push_back({ShotNote::Kind::Exact, exact_->exactLanding, {}, 0.0, 8.0});
        break;
    case EventKind::Burst:
        shellAt_ = e.where;
        break;
    case EventKind::TargetHit:
    case EventKind::Toppled:
    case EventKind::CannonHit:
        scored_ = true;
        notes_.push_back({ShotNote::Kind::Hit, e.where, {}, 0.0, 0.8});
        break;
    case EventKind::ShotOver:
        if (inFlight_) landings_.assign(1, shellAt_);
        inFlight_ = false;
        break;
    case EventKind::Verdict:
        notes_.push_back({ShotNote::Kind::Verdict, e.where, e.text, 0.0, 6.0});
        if (!scored_) notes_.push_back({ShotNote::Kind::Miss, shellAt_, {}, 0.0, 6.0});
        break;
    default:
        break;
    }
}

std::string ShotFeedback::verdict() const {
    for (auto n = notes_.rbegin(); n != notes_.rend(); ++n)
        if (n->kind == ShotNote::Kind::Verdict) return n->text;
    return "";
}

void ShotFeedback::tick(const Match& m, double dt) {
    if (const auto shell = m.shell()) shellAt_ = m.world().particles.position(*shell);
    for (ShotNote& n : notes_)
        n.age += dt;
    std::erase_if(notes_, [](const ShotNote& n) { return n.age > n.life; });
}

} // namespace game
