#include "game/measure.h"

#include "game/match.h"

#include <cmath>
#include <numbers>

namespace game {

using phys::Vec2;

void ShotRecorder::observe(const Match& m) {
    if (m.time() < lastTime_) shots_.clear(); // a rewind or a restart
    lastTime_ = m.time();
    const auto shell = m.shell();
    if (!shell) {
        if (!shots_.empty()) shots_.back().flying = false;
        return;
    }
    if (shots_.empty() || shots_.back().shot != m.shotsFired()) {
        ShotRecord r;
        r.shot = m.shotsFired();
        const double invMass = m.world().particles.invMass[*shell];
        r.mass = invMass > 0.0 ? 1.0 / invMass : 0.0;
        r.gravity = phys::length(m.world().def().forces.gravity);
        r.samples.push_back({0.0, m.flight().launchPosition, m.flight().launchVelocity});
        shots_.push_back(std::move(r));
        if (shots_.size() > kMeasuredShots) shots_.erase(shots_.begin());
    }
    ShotRecord& r = shots_.back();
    r.flying = true;
    r.samples.push_back({m.flight().flown, m.world().particles.position(*shell),
                         m.world().particles.velocity(*shell)});
}

std::optional<ProbeReading> probe(const std::vector<ShotRecord>& shots, Vec2 at, double reach) {
    const ShotRecord* best = nullptr;
    const ShotSample* nearest = nullptr;
    double bestDistance = reach;
    for (const ShotRecord& r : shots)
        for (const ShotSample& s : r.samples)
            if (const double d = phys::length(s.position - at); d <= bestDistance) {
                bestDistance = d;
                best = &r;
                nearest = &s;
            }
    if (!nearest) return std::nullopt;
    ProbeReading p;
    p.t = nearest->t;
    p.position = nearest->position;
    p.velocity = nearest->velocity;
    p.speed = phys::length(nearest->velocity);
    p.kinetic = 0.5 * best->mass * p.speed * p.speed;
    p.potential = best->mass * best->gravity * nearest->position.y;
    return p;
}

TapeReading tape(Vec2 from, Vec2 to) {
    const Vec2 d = to - from;
    return {phys::length(d), std::atan2(d.y, d.x) * 180.0 / std::numbers::pi};
}

std::optional<double> stopwatch(const std::vector<ShotRecord>& shots) {
    if (shots.empty() || shots.back().samples.empty()) return std::nullopt;
    return shots.back().samples.back().t;
}

} // namespace game
