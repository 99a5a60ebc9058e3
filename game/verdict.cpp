#include "game/verdict.h"

#include "game/exact_path.h"
#include "game/match.h"
#include "game/standing_targets.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace game {

using phys::Vec2;

namespace {

/// How a cannon is named in a hit on it: the computer's, yours (one person playing), or
/// a player's by number.
std::vector<std::string> cannonNames(const Match& m) {
    int people = 0;
    for (const CannonState& c : m.cannons()) people += c.def.player != "cpu";
    std::vector<std::string> names;
    for (const CannonState& c : m.cannons())
        names.push_back(c.def.player == "cpu" ? "the computer's cannon"
                        : people == 1        ? "your cannon"
                                             : "player " + c.def.player + "'s cannon");
    return names;
}

} // namespace

std::string missText(double missMetres, const std::string& side) {
    char text[64];
    std::snprintf(text, sizeof text, "missed by %.1f m%s%s", missMetres, side.empty() ? "" : ", ",
                  side.c_str());
    return text;
}

std::string missSide(int crossed) { return crossed > 0 ? "over" : crossed < 0 ? "under" : "short"; }

std::string verdictText(const ShotTally& t, bool duel, const std::vector<std::string>& names) {
    if (!t.cannonsHit.empty()) {
        std::string text = "hit ";
        for (std::size_t i = 0; i < t.cannonsHit.size(); ++i) {
            const auto k = static_cast<std::size_t>(t.cannonsHit[i]);
            text += (i ? " and " : "") + (k < names.size() ? names[k] : std::string("a cannon"));
        }
        return text;
    }
    if (!duel && (t.discsHit > 0 || t.toppled > 0)) {
        std::string text;
        if (t.discsHit > 0) text = t.discsHit == 1 ? "hit" : "hit " + std::to_string(t.discsHit);
        if (t.toppled > 0)
            text += (text.empty() ? "" : " and ") +
                    (t.toppled == 1 ? std::string("toppled") : "toppled " + std::to_string(t.toppled));
        return text + " +" + std::to_string(t.points);
    }
    if (!std::isfinite(t.miss)) return "missed";
    return missText(t.miss, t.side);
}

bool structuresAtRest(const Match& m) {
    for (const auto& b : m.blocks()) {
        if (!m.rigid().alive(b.body)) continue;
        const phys::RigidBodyState s = m.rigid().state(b.body);
        if (length(s.linearVelocity) > 0.05 || std::abs(s.angularVelocity) > 0.05) return false;
    }
    for (const auto& b : m.blobs())
        if (b.def.target && !b.toppled && length(m.world().particles.velocity(b.center)) > 0.05)
            return false;
    return true;
}

void ShotJudge::sample(const Match& m, Vec2 p) {
    const Vec2 from = tally_.landing;
    tally_.landing = p;
    for (const StandingTarget& s : standingTargets(m, tally_.player)) {
        if (crossed_.size() <= s.id) crossed_.resize(s.id + 1, 0);
        const double distance = s.distanceFrom(p);
        // The first time the path crosses the target's vertical line: above it or below,
        // at the height interpolated along the tick's chord.
        if (crossed_[s.id] == 0 && (from.x - s.where.x) * (p.x - s.where.x) <= 0.0 && from.x != p.x) {
            const double y = from.y + (p.y - from.y) * (s.where.x - from.x) / (p.x - from.x);
            crossed_[s.id] = y >= s.where.y ? 1 : -1;
        }
        if (distance < tally_.miss) {
            tally_.miss = distance;
            nearest_ = s.id;
        }
    }
}

void ShotJudge::observe(const Match& m, const GameEvent& e) {
    if (m.sandbox()) return;
    switch (e.kind) {
    case EventKind::Fired:
        *this = ShotJudge();
        open_ = true;
        tally_.player = e.player;
        tally_.landing = e.where;
        model_ = e.model;
        break;
    case EventKind::Landed:
        if (open_ && comparison_.empty())
            if (const std::optional<ExactPath> exact = exactPathOf(m, e, model_))
                comparison_ = exactPathText(*exact);
        break;
    case EventKind::Burst:
        if (open_ && !shotOver_) sample(m, e.where);
        break;
    case EventKind::TargetHit:
    case EventKind::Toppled:
        if (!open_) break;
        tally_.points += static_cast<int>(std::lround(e.value));
        ++(e.kind == EventKind::TargetHit ? tally_.discsHit : tally_.toppled);
        break;
    case EventKind::CannonHit:
        if (open_ && std::find(tally_.cannonsHit.begin(), tally_.cannonsHit.end(), e.player) ==
                         tally_.cannonsHit.end())
            tally_.cannonsHit.push_back(e.player);
        break;
    case EventKind::ShotOver:
        if (open_ && !shotOver_) shotOver_ = true, overTick_ = e.tick;
        break;
    default:
        break;
    }
}

std::optional<GameEvent> ShotJudge::afterTick(const Match& m) {
    if (!open_) return std::nullopt;
    if (!shotOver_) {
        if (const auto shell = m.shell()) sample(m, m.world().particles.position(*shell));
        return std::nullopt;
    }
    const double waited = static_cast<double>(m.tick() - overTick_) * m.world().def().tickSeconds;
    const bool settled = m.level().mode == Mode::Duel || m.allTargetsDown() || structuresAtRest(m) ||
                         waited >= kSettleSeconds;
    if (!settled) return std::nullopt;
    return verdict(m);
}

std::optional<GameEvent> ShotJudge::close(const Match& m) {
    if (!open_) return std::nullopt;
    return verdict(m);
}

GameEvent ShotJudge::verdict(const Match& m) {
    open_ = false;
    const bool duel = m.level().mode == Mode::Duel;
    GameEvent e;
    e.tick = m.tick();
    e.kind = EventKind::Verdict;
    e.player = tally_.player;
    e.where = tally_.landing;
    e.value = duel ? 0.0 : tally_.points;
    tally_.side = missSide(nearest_ < crossed_.size() ? crossed_[nearest_] : 0);
    e.text = verdictText(tally_, duel, cannonNames(m));
    if (!comparison_.empty()) e.text += "; " + comparison_;
    return e;
}

} // namespace game
