// Weapon behaviours, read from the weapon's row (game/weapons.cpp): each is a rule on
// the shell's state after the tick, so a weapon is a set of numbers, not a code path.
#include "game/match.h"
#include "game/weapons.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace game {

using namespace phys;

namespace {

/// Ticks of a duration, to the nearest tick: a fuse of T s bursts round(T / dt) ticks
/// after firing.
std::uint64_t ticksOf(double seconds, double dt) {
    return static_cast<std::uint64_t>(std::llround(seconds / dt));
}

} // namespace

bool Match::shellHeld() const {
    const Behaviour& b = shellAmmo_.behaviour;
    // A weapon rests only on something: at the top of a vertical throw it is slow, not
    // resting.
    return flight_.stuckTick.has_value() || flight_.digging || b.fuseSeconds > 0.0 ||
           (shellAmmo_.weapon && !flight_.inContact);
}

bool Match::burstAndEnd(Vec2 at) {
    burst(at);
    endShot(closestMiss_);
    return true;
}

void Match::startTunnel(Vec2 p) {
    const Vec2 in = flight_.lastVelocity;
    const double speed = length(in);
    flight_.digging = true;
    flight_.digOrigin = p;
    flight_.digDirection = speed > 0.0 ? in * (1.0 / speed) : Vec2{0.0, -1.0};
    flight_.digSpeed = std::max(speed, 5.0);
    world_.particles.setVelocity(shell_, {0.0, 0.0});
    world_.particles.invMass[shell_] = 0.0;
}

bool Match::stepTunnel() {
    // The tunnel: the tip moves on at its impact speed along its incoming direction,
    // carving as it goes, and bursts at p0 + L d (exactly, on the last tick).
    const Behaviour& b = shellAmmo_.behaviour;
    const double dt = world_.def().tickSeconds;
    flight_.dug = std::min(b.digLength, flight_.dug + flight_.digSpeed * dt);
    const Vec2 tip = flight_.digOrigin + flight_.digDirection * flight_.dug;
    world_.particles.setPosition(shell_, tip);
    const bool done = flight_.dug >= b.digLength;
    if ((done || flight_.dug - flight_.carvedTo >= 0.5 * b.digRadius) &&
        level_.terrain.destructible && terrain_.carve(tip, b.digRadius)) {
        flight_.carvedTo = flight_.dug;
        rebuildStaticShapes();
        world_.wakeAll();
        emit(EventKind::Crater, current_, tip, b.digRadius);
    }
    return done ? burstAndEnd(tip) : false;
}

bool Match::stepWeapon(Vec2 p, bool touched, bool impact) {
    const Behaviour& b = shellAmmo_.behaviour;
    const double dt = world_.def().tickSeconds;
    const std::uint64_t flown = tick() - shellFiredTick_;
    const Vec2 v = world_.particles.velocity(shell_);
    flight_.flown = static_cast<double>(flown) * dt;
    const bool newImpact = impact && !flight_.touching;
    flight_.touching = impact;
    flight_.inContact = touched;

    if (flight_.digging) return stepTunnel();
    if (flight_.stuckTick) {
        if (tick() - *flight_.stuckTick >= ticksOf(b.stickSeconds, dt)) return burstAndEnd(p);
        return false;
    }
    if (b.fuseSeconds > 0.0 && flown >= ticksOf(b.fuseSeconds, dt)) return burstAndEnd(p);
    if (b.airburstHeight > 0.0 && v.y < 0.0 && p.y - terrain_.heightAt(p.x) <= b.airburstHeight)
        return burstAndEnd(p);
    if (b.apexFragments > 0 && !flight_.split && flight_.lastVelocity.y > 0.0 && v.y <= 0.0) {
        splitShell();
        return false;
    }
    switch (b.onImpact) {
    case OnImpact::Burst:
        if (touched) return burstAndEnd(p);
        break;
    case OnImpact::Bounce:
        if (newImpact) {
            ++flight_.impacts;
            if (b.burstAfterBounces > 0 && flight_.impacts >= b.burstAfterBounces)
                return burstAndEnd(p);
        }
        break;
    case OnImpact::Stick:
        if (touched) {
            // e = 0 and no slip: all velocity goes; held in place (inverse mass 0).
            world_.particles.setVelocity(shell_, {0.0, 0.0});
            world_.particles.invMass[shell_] = 0.0;
            flight_.stuckTick = tick();
            if (b.stickSeconds <= 0.0) return burstAndEnd(p);
        }
        break;
    case OnImpact::Dig:
        if (touched) startTunnel(p);
        break;
    }
    if (b.burstAtRest) {
        const bool resting = (world_.particles.flags[shell_] & kSleeping) ||
                             (touched && static_cast<double>(flown) * dt > 1.0 && length(v) < 0.05);
        if (resting) return burstAndEnd(p);
    }
    flight_.lastVelocity = v;
    return false;
}

void Match::splitShell() {
    // The split conserves momentum: n fragments of m/n each, in pairs at v + d_k and
    // v - d_k, so sum (m/n) v_i = m v exactly up to rounding (the d_k cancel in pairs).
    const Behaviour& b = shellAmmo_.behaviour;
    const int n = std::max(2, b.apexFragments - b.apexFragments % 2);
    ParticleSet& set = world_.particles;
    const Vec2 p = set.position(shell_), v = set.velocity(shell_);
    const double m = set.mass(shell_);
    ParticleDef pd;
    pd.mass = m / n;
    pd.radius = set.radius[shell_] / std::cbrt(static_cast<double>(n)); // same density
    pd.dragCoefficient = set.dragCd[shell_];
    pd.material = set.material[shell_];
    pd.flags = kProjectile;
    set.remove(shell_);
    flight_.split = true;
    flight_.apexMass = m;
    flight_.apexVelocity = v;
    std::vector<ParticleId> pieces;
    for (int k = 0; k < n / 2; ++k) {
        const double a = std::numbers::pi * (k + 0.5) / (n / 2);
        const Vec2 d{std::cos(a), std::sin(a)};
        for (const double side : {1.0, -1.0}) {
            pd.velocity = v + d * (side * b.fragmentSpreadMps);
            pd.position = p + d * (side * 2.5 * pd.radius); // apart, so they do not collide
            pieces.push_back(set.add(pd));
        }
    }
    shell_ = pieces.front();
    flight_.fragments.assign(pieces.begin() + 1, pieces.end());
    flight_.lastVelocity = set.velocity(shell_);
}

void Match::stepFragments() {
    auto& list = flight_.fragments;
    if (list.empty()) return;
    ParticleSet& set = world_.particles;
    CannonState& shooter = cannons_[static_cast<std::size_t>(current_)];
    const double dt = world_.def().tickSeconds;
    const double flight = static_cast<double>(tick() - shellFiredTick_) * dt;
    std::vector<ParticleId> flying;
    for (const ParticleId f : list) {
        if (!set.alive(f)) continue;
        const Vec2 p = set.position(f);
        const double r = set.radius[f];
        // A fragment scores a target it passes through, by how close it is on that tick.
        for (TargetState& t : targets_) {
            if (t.hit) continue;
            const double d = length(p - t.position);
            if (d > t.def.radius + r) continue;
            t.hit = true;
            const double closeness = 1.0 - d / (t.def.radius + r);
            const int points =
                static_cast<int>(std::lround(t.def.points * (0.5 + 0.5 * closeness)));
            shooter.score += points;
            emit(EventKind::TargetHit, current_, t.position, points);
        }
        bool touched = false;
        for (const ContactEvent& e : world_.contacts())
            touched = touched || e.a == f || e.b == f;
        for (const BodyContactEvent& e : coupling_.events())
            touched = touched || e.particle == f;
        if (touched) {
            burst(p, -1, f);
            continue;
        }
        const bool outside =
            p.x < level_.worldMin.x || p.x > level_.worldMax.x || p.y < level_.worldMin.y;
        if (outside || flight > kMaxFlightSeconds || !std::isfinite(p.x) || !std::isfinite(p.y)) {
            set.remove(f);
            continue;
        }
        flying.push_back(f);
    }
    list = std::move(flying);
}

bool Match::promoteFragment() {
    auto& list = flight_.fragments;
    while (!list.empty()) {
        const ParticleId f = list.back();
        list.pop_back();
        if (!world_.particles.alive(f)) continue;
        scorePasses(true); // the passes of the piece that has ended
        if (world_.particles.alive(shell_)) world_.particles.remove(shell_);
        shell_ = f;
        flight_.touching = false;
        flight_.lastVelocity = world_.particles.velocity(f);
        return true;
    }
    return false;
}

} // namespace game
