#include "game/effects/effects.h"

#include "game/ammo.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace game {

using phys::Vec2;

namespace {

/// The effects' own world: gravity alone, no drag, no collisions, so every piece is on
/// the closed form (the model pass puts a free particle with nothing but gravity on it
/// there) and a tick costs a few multiplications per piece.
phys::WorldDef piecesWorld(const Match& m) {
    phys::WorldDef d;
    d.tickSeconds = m.world().def().tickSeconds;
    d.forces.gravity = m.world().def().forces.gravity;
    d.forces.drag = phys::DragModel::None;
    d.collision.model = phys::ContactModel::None;
    d.collision.particlePairs = false;
    d.collision.sleep = false;
    return d;
}

std::uint8_t tintOf(const std::string& material) {
    if (material == "wood") return 1;
    if (material == "stone") return 2;
    if (material == "steel") return 3;
    return 0;
}

} // namespace

Effects::Effects(const EffectsDef& def) : def_(def) {}

void Effects::reset() {
    const EffectsDef d = def_;
    *this = Effects(d);
}

double Effects::unit() {
    return static_cast<double>(rng_() >> 11) * 0x1.0p-53;
}

double Effects::pieceAge(phys::ParticleId id) const {
    return world_.time() - born_[id];
}

void Effects::throwPiece(Vec2 at, Vec2 velocity, double radius, PieceKind kind, std::uint8_t tint) {
    if (world_.particles.count() >= def_.maxPieces) return;
    phys::ParticleDef pd;
    pd.position = at;
    pd.velocity = velocity;
    pd.radius = radius;
    pd.mass = 0.01;
    const phys::ParticleId id = world_.particles.add(pd);
    if (kinds_.size() <= id) {
        kinds_.resize(id + 1);
        tints_.resize(id + 1);
        born_.resize(id + 1);
    }
    kinds_[id] = kind;
    tints_[id] = tint;
    born_[id] = world_.time();
    ++thrown_;
    ++thrownOf_[static_cast<std::size_t>(kind)];
}

void Effects::blast(Vec2 at, double radius, double impulse, std::uint8_t tint) {
    const double scale = radius / def_.referenceBlastRadius;
    // Ejecta leave a blast at speeds of the order of sqrt(2 g h) for a throw height h of a
    // few blast radii; spread them over a cone that opens upward.
    const double g = std::max(1.0, -world_.def().forces.gravity.y);
    const double vTypical = std::sqrt(2.0 * g * 3.0 * radius);
    if (def_.debris) {
        const int n = std::max(8, static_cast<int>(std::lround(def_.debrisPerBlast * scale)));
        for (int i = 0; i < n; ++i) {
            const double a = std::numbers::pi * (0.12 + 0.76 * unit());
            const double v = vTypical * (0.35 + 0.9 * unit());
            const bool dust = i % 3 == 2;
            throwPiece(at + Vec2{(unit() - 0.5) * radius * 0.5, 0.2 * radius},
                       Vec2{std::cos(a), std::sin(a)} * (dust ? 0.6 * v : v),
                       dust ? 0.06 + 0.06 * unit() : 0.08 + 0.14 * unit() * std::sqrt(scale),
                       dust ? PieceKind::Dust : PieceKind::Soil, tint);
        }
    }
    if (def_.smoke)
        for (int i = 0; i < 6; ++i) {
            const double a = 2.0 * std::numbers::pi * unit();
            smoke_.push_back(
                {at + Vec2{std::cos(a), std::sin(a) * 0.5 + 0.6} * radius * 0.5 * unit(),
                 Vec2{std::cos(a), std::abs(std::sin(a))} * (1.5 + 2.0 * unit()), 0.0,
                 0.4 * radius});
        }
    flashes_.push_back({at, 1.6 * radius, 0.0});
    // Screen shake by the blast's energy, relative to a cannonball's (150 N s over 3 m).
    shake_ = std::min(1.0, std::max(shake_, impulse * radius / 450.0));
}

void Effects::splinters(Vec2 at, double speed, std::uint8_t tint, int count) {
    if (!def_.debris) return;
    for (int i = 0; i < count; ++i) {
        const double a = std::numbers::pi * (0.05 + 0.9 * unit());
        const double v = std::min(12.0, 0.25 * speed + 2.0) * (0.4 + 0.8 * unit());
        throwPiece(at + Vec2{(unit() - 0.5) * 0.6, (unit() - 0.5) * 0.6},
                   Vec2{std::cos(a), std::sin(a)} * v, 0.05 + 0.06 * unit(), PieceKind::Splinter,
                   tint);
    }
}

void Effects::splash(Vec2 at, double speed) {
    ripples_.push_back({at, 0.0, std::min(2.0, speed / 20.0)});
    if (!def_.debris) return;
    // Spray rises at a fraction of the entry speed, steeply, both ways.
    const int n = 24 + static_cast<int>(std::min(24.0, speed));
    for (int i = 0; i < n; ++i) {
        const double a = std::numbers::pi * (0.3 + 0.4 * unit());
        const double v = std::min(16.0, 0.5 * speed + 3.0) * (0.4 + 0.7 * unit());
        throwPiece(at + Vec2{(unit() - 0.5) * 0.8, 0.05}, Vec2{std::cos(a), std::sin(a)} * v,
                   0.05 + 0.05 * unit(), PieceKind::Spray, 4);
    }
}

/// Pieces below the ground come down: soil stays as a speck, the rest is gone; pieces in
/// the air too long, or in the water, are gone too.
void Effects::settle(const Match& m) {
    phys::ParticleSet& ps = world_.particles;
    const bool water = m.level().physics.water;
    const double waterLevel = m.level().physics.waterLevel;
    for (std::size_t i = 0; i < ps.flags.size(); ++i) {
        if (!(ps.flags[i] & phys::kAlive)) continue;
        const Vec2 p{ps.px[i], ps.py[i]};
        const double ground = m.terrain().heightAt(p.x);
        const bool landed = p.y <= ground && ps.vy[i] < 0.0;
        const bool wet = water && p.y < waterLevel && ps.vy[i] < 0.0;
        const bool old = world_.time() - born_[i] > def_.debrisSeconds;
        if (!(landed || wet || old)) continue;
        if (landed && !wet && kinds_[i] == PieceKind::Soil) {
            if (specks_.size() >= def_.maxSpecks) specks_.erase(specks_.begin());
            specks_.push_back({{p.x, ground}, 2.0 * ps.radius[i]});
        }
        ps.remove(static_cast<phys::ParticleId>(i));
    }
}

void Effects::observe(const Match& m) {
    // Ticks since the last look: one in the window, more for a viewer that looks every
    // few ticks (frames written every N ticks); everything advances by all of them.
    std::uint64_t ticks = started_ ? m.tick() - lastTick_ : 0;
    if (!started_ || m.tick() < lastTick_ || m.events().size() < seenEvents_) {
        ticks = 0;
        reset();
        world_ = phys::World(piecesWorld(m));
        rng_.seed(m.level().seed ^ 0x9e3779b97f4a7c15ull); // its own stream, from the level's seed
        started_ = true;
    }
    lastTick_ = m.tick();
    const double dt = m.world().def().tickSeconds;
    const std::uint8_t groundTint = 0;

    // New events: what happened this tick.
    const auto& events = m.events();
    for (std::size_t k = seenEvents_; k < events.size(); ++k) {
        const GameEvent& e = events[k];
        feedback_.event(m, e);
        switch (e.kind) {
        case EventKind::Fired:
            firedAmmo_ = e.text;
            flashes_.push_back({e.where, 0.8, 0.0}); // the muzzle flash
            if (def_.smoke) smoke_.push_back({e.where, Vec2{0.0, 1.0}, 0.0, 0.5});
            break;
        case EventKind::Burst: {
            const auto ammo = ammoFromName(firedAmmo_);
            blast(e.where, e.value, ammo ? ammo->blastImpulse : 150.0, groundTint);
            // Blocks caught in the blast throw splinters.
            for (const BlockState& b : m.blocks())
                if (m.rigid().alive(b.body) &&
                    length(m.rigid().state(b.body).position - e.where) < e.value)
                    splinters(m.rigid().state(b.body).position, 20.0, tintOf(b.def.material), 6);
            break;
        }
        case EventKind::Crater:
            craters_.push_back({e.where, e.value});
            break;
        case EventKind::Toppled:
            for (const BlockState& b : m.blocks())
                if (m.rigid().alive(b.body) &&
                    length(m.rigid().state(b.body).position - e.where) < 1e-9)
                    splinters(e.where, 8.0, tintOf(b.def.material), 10);
            break;
        case EventKind::Bounce:
            // A hard hit on a block splinters it.
            if (e.value > 8.0)
                for (const BlockState& b : m.blocks()) {
                    if (!m.rigid().alive(b.body)) continue;
                    const double reach = 0.75 * std::max(b.def.size.x, b.def.size.y) + 0.3;
                    if (length(m.rigid().state(b.body).position - e.where) < reach) {
                        splinters(e.where, e.value, tintOf(b.def.material), 8);
                        break;
                    }
                }
            break;
        default:
            break;
        }
    }
    seenEvents_ = events.size();

    // Splashes: the shell crossed the water line going down since the last tick.
    if (const auto entry = waterEntry_.look(m)) splash(entry->point, entry->downSpeed);

    // A viewer that looked away for long catches up on at most ten seconds.
    const auto most = static_cast<std::uint64_t>(10.0 / dt);
    for (std::uint64_t k = 0; k < std::min(ticks, most); ++k)
        advance(m, dt);
}

void Effects::advance(const Match& m, double dt) {
    world_.step();
    settle(m);
    const Vec2 wind{m.wind(), 0.0};
    const double relax = 1.0 - std::exp(-dt / def_.smokeRelaxSeconds);
    for (Smoke& s : smoke_) {
        // The puff's velocity relaxes to the wind plus its rise: v += (w - v)(1 - e^(-dt/tau)).
        s.velocity += (wind + Vec2{0.0, def_.smokeRiseMps} - s.velocity) * relax;
        s.position += s.velocity * dt;
        s.age += dt;
        s.radius += 0.6 * dt;
    }
    std::erase_if(smoke_, [&](const Smoke& s) { return s.age > def_.smokeSeconds; });
    for (Flash& f : flashes_)
        f.age += dt;
    std::erase_if(flashes_, [&](const Flash& f) { return f.age > def_.flashSeconds; });
    for (Ripple& r : ripples_)
        r.age += dt;
    std::erase_if(ripples_, [](const Ripple& r) { return r.age > 1.2; });
    // Shake decays with a half-life of 0.12 s.
    shake_ *= std::exp2(-dt / 0.12);
    if (shake_ < 1e-3) shake_ = 0.0;
    feedback_.tick(m, dt);
}

} // namespace game
