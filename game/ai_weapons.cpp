#include "game/ai_weapons.h"

#include "game/weapons.h"

#include <numbers>

namespace game {

using phys::Vec2;

namespace {

enum class Aim { Cannon, Structure, Disc };

Aim aimKind(const Match& m, Vec2 target) {
    if (m.level().mode == Mode::Duel) return Aim::Cannon;
    for (const auto& t : m.targets())
        if (!t.hit && t.position == target) return Aim::Disc;
    return Aim::Structure;
}

/// How well a weapon suits the aim (larger is better).
double worth(const Weapon& w, Aim aim, double speed) {
    const double area = 0.25 * std::numbers::pi * w.body.diameter * w.body.diameter;
    const double k = 1.225 * w.body.dragCoefficient * area / (2.0 * w.body.mass);
    switch (aim) {
    case Aim::Cannon:
        return w.blastRadius;
    case Aim::Structure:
        return w.body.mass * speed + w.blastImpulse;
    case Aim::Disc:
        return -k;
    }
    return 0.0;
}

} // namespace

std::optional<std::string> chooseWeapon(const Match& match, Vec2 target) {
    const CannonState& c = match.cannon();
    const Aim aim = aimKind(match, target);
    const double speed = c.def.maxSpeedMps * 0.75;
    std::optional<std::string> best;
    double bestWorth = -INFINITY;
    for (std::size_t i = 0; i < c.def.projectiles.size(); ++i) {
        const Weapon* w = weaponFromName(c.def.projectiles[i]);
        if (!w || (i < c.ammoLeft.size() && c.ammoLeft[i] == 0)) continue;
        // A digger or a sticky charge is no use against a disc in the air.
        if (aim == Aim::Disc && w->behaviour.onImpact != OnImpact::Burst) continue;
        const double v = worth(*w, aim, speed);
        if (v > bestWorth) {
            bestWorth = v;
            best = w->name;
        }
    }
    // No weapon fits and the selection is spent (the last mortar fired): the first of
    // the list with ammunition left, else the cannon would ask to fire nothing for ever.
    const auto spent = [&](std::size_t i) { return i < c.ammoLeft.size() && c.ammoLeft[i] == 0; };
    if (!best && spent(c.projectile))
        for (std::size_t i = 0; i < c.def.projectiles.size(); ++i)
            if (!spent(i) && knownProjectile(c.def.projectiles[i])) {
                best = c.def.projectiles[i];
                break;
            }
    if (best && *best == c.def.projectiles[c.projectile]) return std::nullopt;
    return best;
}

} // namespace game
