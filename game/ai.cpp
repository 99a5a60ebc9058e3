#include "game/ai.h"

#include "game/ai_cover.h"
#include "game/ai_weapons.h"
#include "game/weapons.h"

#include "physics/ballistics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace game {

using namespace phys;

const char* difficultyName(Difficulty d) {
    switch (d) {
    case Difficulty::Easy: return "easy";
    case Difficulty::Normal: return "normal";
    case Difficulty::Hard: return "hard";
    }
    return "?";
}

std::optional<Difficulty> difficultyFromName(const std::string& name) {
    for (Difficulty d : {Difficulty::Easy, Difficulty::Normal, Difficulty::Hard})
        if (name == difficultyName(d)) return d;
    return std::nullopt;
}

AimError aimError(Difficulty d) {
    switch (d) {
    // At duel ranges (~250 m at 50-70 m/s) one degree moves the landing point by up to
    // ~9 m and 1 % of speed by ~5 m, against a cannon 1.5 m wide plus half a blast.
    case Difficulty::Easy: return {1.2, 0.025};
    case Difficulty::Normal: return {0.5, 0.01};
    case Difficulty::Hard: return {0.2, 0.004};
    }
    return {0.0, 0.0};
}

namespace {

/// A path that passes this close to the aim point is on target, m.
constexpr double kOnTarget = 0.5;
/// How far a trial path keeps from a block beyond the shell's radius, m: the aim error
/// added afterwards must not turn a path that grazes its own wall into a hit on it.
constexpr double kCoverMargin = 0.3;

// Closest approach of a previewed path (a sample a tick, from the muzzle) to the target:
// how close, m, and when, s after the shot.
struct Approach {
    double miss = INFINITY;
    double seconds = 0.0;
};

Approach closestApproach(const std::vector<Vec2>& path, Vec2 target, double tick) {
    Approach best;
    for (std::size_t i = 1; i < path.size(); ++i) {
        // Distance from the target to the segment between samples.
        const Vec2 a = path[i - 1], b = path[i], ab = b - a;
        const double t = std::clamp(dot(target - a, ab) / std::max(1e-12, lengthSquared(ab)), 0.0, 1.0);
        const double d = length(a + ab * t - target);
        if (d < best.miss) best = {d, (static_cast<double>(i - 1) + t) * tick};
    }
    return best;
}

/// One aim at one target: the exact solution in the open, else trial shots through the
/// same simulation. Counts its trials in the solution it fills.
class Aimer {
public:
    Aimer(const Match& match, Vec2 target, std::optional<std::size_t> projectile)
        : match_(match), c_(match.cannon()), target_(target), projectile_(projectile),
          g_(-match.world().def().forces.gravity.y), cover_(coverFor(match, target, projectile)) {}

    AimSolution aim() {
        if (match_.ballisticOnly() && exactInTheOpen()) return out_;
        trialSearch(0);
        // No straight path reaches: paths that fly on through up to two contacts (a ceiling
        // to bank off, water to skip on).
        if (!(out_.missM < kOnTarget)) trialSearch(2);
        bounces_ = found_;
        if (std::isfinite(out_.missM))
            out_.flightSeconds = approach(out_.angleDeg, out_.speedMps, false).seconds;
        return out_;
    }

private:
    // In a duel a trial path ends at the first block in its way (the preview flies through
    // bodies): the blocks are the castles' cover. In practice they are what the shot is
    // for, and a shell into the blocks in front of a target block is a fair way to it.
    static BlockCover coverFor(const Match& match, Vec2 target, std::optional<std::size_t> projectile) {
        const Ammo ammo = match.ammoAt(projectile.value_or(match.cannon().projectile));
        return match.level().mode == Mode::Duel
                   ? BlockCover(match, target, 0.5 * ammo.preset.diameter + kCoverMargin)
                   : BlockCover();
    }

    // Past the budget a trial is a miss, not flown; the chosen path's own flight time is
    // always measured (`budgeted` false).
    Approach approach(double angleDeg, double speed, bool budgeted = true) {
        if (budgeted && out_.trialTicks >= kMaxTrialTicks) return Approach{};
        ++out_.trials;
        std::vector<Vec2> path =
            match_.previewTrajectory(angleDeg, speed, 20.0, target_.x, projectile_, bounces_);
        out_.trialTicks += static_cast<long>(path.size());
        path.resize(std::min(path.size(), cover_.firstBlocked(path) + 1));
        return closestApproach(path, target_, match_.world().def().tickSeconds);
    }

    // Exact in the open: the smallest speed step from the current power that reaches, the
    // low arc, then the high one. The closed form knows no walls or ceilings, so each arc
    // is flown once through the same simulation and kept only if nothing stops it short of
    // the target (a wall to lob over, a ceiling to stay under).
    bool exactInTheOpen() {
        for (double s = std::max(5.0, c_.speedMps); s <= c_.def.maxSpeedMps + 1e-9; s += 2.5)
            for (std::size_t arc = 0; arc < 2; ++arc) {
                // The muzzle moves with the angle; two fixed-point passes settle it.
                double angle = c_.angleDeg;
                std::vector<FiringSolution> sol;
                for (int pass = 0; pass < 3; ++pass) {
                    sol = solveFiring(match_.muzzle(angle), target_, s, g_);
                    if (sol.size() <= arc) break;
                    angle = sol[arc].angleDeg;
                }
                if (sol.size() <= arc) continue;
                const Approach a = approach(angle, s);
                if (!(a.miss < kOnTarget)) continue;
                out_.angleDeg = angle;
                out_.speedMps = s;
                out_.missM = 0.0;
                out_.exact = true;
                out_.flightSeconds = a.seconds;
                return true;
            }
        return false;
    }

    double direction() const { return target_.x >= c_.def.position.x ? 1.0 : -1.0; }
    double toAngle(double elevation) const { return direction() > 0 ? elevation : 180.0 - elevation; }
    double trial(double elevation, double speed) { return approach(toAngle(elevation), speed).miss; }

    // Golden section on [elevation - 10, elevation + 10]: one new trial per iteration.
    std::pair<double, double> refine(double elevation, double s) {
        const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
        double lo = std::max(0.0, elevation - 10.0), hi = std::min(89.0, elevation + 10.0);
        double x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo);
        double m1 = trial(x1, s), m2 = trial(x2, s);
        for (int it = 0; it < 16; ++it) {
            if (m1 < m2) {
                hi = x2;
                x2 = x1;
                m2 = m1;
                x1 = hi - phi * (hi - lo);
                m1 = trial(x1, s);
            } else {
                lo = x1;
                x1 = x2;
                m1 = m2;
                x2 = lo + phi * (hi - lo);
                m2 = trial(x2, s);
            }
        }
        return m1 < m2 ? std::pair{x1, m1} : std::pair{x2, m2};
    }

    // Trial shots through the same simulation, at increasing power from what a vacuum shot
    // would need until a path passes within half a metre: the coarse sweep, its best
    // elevation refined, and when that does not reach, the best of the other family (below
    // 45 degrees, or above) refined too: a low path that ends on cover near the target can
    // come closer than a steep one that drops onto it. Paths fly on through `allowed` ticks
    // with a contact.
    void trialSearch(int allowed) {
        bounces_ = allowed;
        const Vec2 d = target_ - c_.def.position;
        const double vacuum = std::sqrt(std::max(0.0, g_ * (d.y + length(d)))); // least speed in vacuum
        const double step = 0.1 * c_.def.maxSpeedMps;
        for (double s = std::min(c_.def.maxSpeedMps, std::max(10.0, 1.15 * vacuum));;
             s = std::min(c_.def.maxSpeedMps, s + step)) {
            const auto [bestElev, bestMiss] = bestAt(s);
            if (bestMiss < out_.missM) {
                out_.missM = bestMiss;
                out_.angleDeg = toAngle(bestElev);
                out_.speedMps = s;
                found_ = bounces_;
            }
            if (bestMiss < kOnTarget || s >= c_.def.maxSpeedMps) break;
        }
    }

    /// The best elevation at speed `s` and its miss.
    std::pair<double, double> bestAt(double s) {
        double bestElev = 45.0, bestMiss = INFINITY;
        double coarse[8];
        for (int k = 0; k < 8; ++k) {
            const double e = 10.0 + 10.0 * k;
            coarse[k] = trial(e, s);
            if (coarse[k] < bestMiss) {
                bestMiss = coarse[k];
                bestElev = e;
            }
        }
        const bool steep = bestElev > 45.0; // the family of the best coarse elevation
        if (const auto [e, m] = refine(bestElev, s); m < bestMiss) bestMiss = m, bestElev = e;
        if (!(bestMiss < kOnTarget)) {
            double otherElev = 0.0, otherMiss = INFINITY;
            for (int k = 0; k < 8; ++k)
                if ((10.0 + 10.0 * k > 45.0) != steep && coarse[k] < otherMiss)
                    otherMiss = coarse[k], otherElev = 10.0 + 10.0 * k;
            if (const auto [e, m] = refine(otherElev, s); m < bestMiss) bestMiss = m, bestElev = e;
        }
        return {bestElev, bestMiss};
    }

    const Match& match_;
    const CannonState& c_;
    const Vec2 target_;
    const std::optional<std::size_t> projectile_;
    const double g_;
    const BlockCover cover_;
    AimSolution out_;
    int bounces_ = 0; ///< contacts a trial shot flies on through
    int found_ = 0;   ///< the allowance the best path was found with
};

} // namespace

AimSolution aimAt(const Match& match, Vec2 target, std::optional<std::size_t> projectile) {
    return Aimer(match, target, projectile).aim();
}

std::optional<Vec2> chooseTarget(const Match& match) {
    const Vec2 from = match.cannon().def.position;
    std::optional<Vec2> best;
    double bestD = INFINITY;
    auto consider = [&](Vec2 p) {
        const double d = length(p - from);
        if (d < bestD) {
            bestD = d;
            best = p;
        }
    };
    if (match.level().mode == Mode::Duel) {
        for (std::size_t i = 0; i < match.cannons().size(); ++i)
            if (static_cast<int>(i) != match.currentPlayer() && match.cannons()[i].hitPoints > 0)
                consider(match.cannons()[i].def.position);
    } else {
        for (const auto& t : match.targets())
            if (!t.hit) consider(t.position);
        for (const auto& b : match.blocks())
            if (b.def.target && !b.toppled) consider(b.def.position);
        // A target blob scores when knocked off its place: aim at where it is now.
        for (const auto& b : match.blobs())
            if (b.def.target && !b.toppled)
                consider(b.center != phys::kNoParticle ? match.world().particles.position(b.center)
                                                       : b.def.center);
    }
    return best;
}

double ComputerPlayer::gaussian() {
    // Box-Muller on the top 53 bits: the same numbers on every platform.
    auto unit = [&] { return (static_cast<double>(rng_() >> 11) + 0.5) * 0x1.0p-53; };
    const double u1 = unit(), u2 = unit();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

const TargetState* movingTargetAt(const Match& match, Vec2 target) {
    for (const TargetState& t : match.targets())
        if (!t.hit && t.def.path.size() >= 2 && t.def.speedMps > 0.0 && t.position == target)
            return &t;
    return nullptr;
}

AimSolution aimToFireNow(const Match& match, Vec2 target, std::optional<std::size_t> projectile,
                         double delaySeconds) {
    const TargetState* moving = movingTargetAt(match, target);
    const double fired = match.time() + delaySeconds;
    if (moving) target = targetPositionAt(moving->def, fired);
    AimSolution aim = aimAt(match, target, projectile);
    if (moving)
        for (int pass = 0; pass < 2; ++pass)
            aim = aimAt(match, targetPositionAt(moving->def, fired + aim.flightSeconds), projectile);
    return aim;
}

std::vector<Command> ComputerPlayer::takeTurn(const Match& match, std::uint64_t tick,
                                              double delaySeconds) {
    std::vector<Command> out;
    const auto target = chooseTarget(match);
    if (!target) {
        Command end;
        end.tick = tick;
        end.kind = CommandKind::EndTurn;
        out.push_back(end);
        return out;
    }
    // The weapon first, so the trial shots fly what will be fired.
    const CannonState& c = match.cannon();
    const auto& list = c.def.projectiles;
    auto indexOf = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(list.begin(), list.end(), name) - list.begin());
    };
    std::size_t projectile = c.projectile;
    if (const auto weapon = chooseWeapon(match, *target)) projectile = indexOf(*weapon);
    AimSolution aim = aimToFireNow(match, *target, projectile, delaySeconds);
    // What it chose does not reach (a light ball into a headwind): another projectile
    // with rounds left that does, or comes closest.
    if (!(aim.missM < kOnTarget))
        for (std::size_t k = 0; k < list.size(); ++k) {
            const bool spent = k < c.ammoLeft.size() && c.ammoLeft[k] == 0;
            if (k == projectile || spent || !knownProjectile(list[k])) continue;
            const AimSolution other = aimToFireNow(match, *target, k, delaySeconds);
            if (other.missM < aim.missM) aim = other, projectile = k;
        }
    if (projectile != c.projectile) {
        Command sel;
        sel.tick = tick;
        sel.kind = CommandKind::Select;
        sel.text = list[projectile];
        out.push_back(sel);
    }
    const AimError err = aimError(difficulty_);
    Command a;
    a.tick = tick;
    a.kind = CommandKind::Aim;
    a.number = std::clamp(aim.angleDeg + err.angleDeg * gaussian(), -180.0, 180.0);
    Command p;
    p.tick = tick;
    p.kind = CommandKind::Power;
    p.number = std::clamp(aim.speedMps * (1.0 + err.speedFraction * gaussian()), 0.0, c.def.maxSpeedMps);
    Command f;
    f.tick = tick;
    f.kind = CommandKind::Fire;
    out.insert(out.end(), {a, p, f});
    return out;
}

} // namespace game
