#include "physics/diagnostics.h"

#include "physics/collision/broadphase.h"
#include "physics/rigid/rigid_world.h"
#include "physics/world.h"

#include <algorithm>
#include <cmath>

namespace phys {

EnergyReport energy(const ParticleSet& s, const std::vector<Spring>& springs,
                    const ForceDef& forces) {
    EnergyReport e;
    for (std::size_t i = 0; i < s.slots(); ++i) {
        if (!(s.flags[i] & kAlive) || s.invMass[i] <= 0.0) continue;
        const double m = 1.0 / s.invMass[i];
        e.kinetic += 0.5 * m * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
        if (!(s.flags[i] & kNoGravity))
            e.potential -= m * (forces.gravity.x * s.px[i] + forces.gravity.y * s.py[i]);
    }
    for (const Spring& sp : springs) {
        if (sp.broken) continue;
        const Vec2 b = sp.b == kNoParticle ? sp.anchor : s.position(sp.b);
        const double ext = length(s.position(sp.a) - b) - sp.restLength;
        e.elastic += 0.5 * sp.stiffness * ext * ext;
    }
    return e;
}

Vec2 momentum(const ParticleSet& s) {
    Vec2 p;
    for (std::size_t i = 0; i < s.slots(); ++i) {
        if (!(s.flags[i] & kAlive) || s.invMass[i] <= 0.0) continue;
        p += s.velocity(static_cast<ParticleId>(i)) / s.invMass[i];
    }
    return p;
}

std::uint64_t hashBytes(std::uint64_t h, const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

std::uint64_t stateHash(const ParticleSet& s, std::uint64_t h) {
    for (std::size_t i = 0; i < s.slots(); ++i) {
        if (!(s.flags[i] & kAlive)) continue;
        const double v[4] = {s.px[i], s.py[i], s.vx[i], s.vy[i]};
        h = hashBytes(h, &i, sizeof i);
        h = hashBytes(h, v, sizeof v);
        h = hashBytes(h, &s.flags[i], sizeof s.flags[i]);
    }
    return h;
}

// ---- debug view ------------------------------------------------------------------------

ParticleModel modelOf(std::uint32_t flags, double invMass) {
    if (!(invMass > 0.0)) return ParticleModel::Fixed;
    if (flags & kSleeping) return ParticleModel::Sleeping;
    if (flags & kBallistic) return ParticleModel::ClosedForm;
    return ParticleModel::Integrated;
}

void netForces(const World& world, std::vector<Vec2>& out) {
    const ParticleSet& s = world.particles;
    const std::size_t n = s.slots();
    // The generators other than uniform gravity, exactly as the integrators evaluate them.
    std::vector<double> fx(n), fy(n);
    const Dynamics dynamics(world.def().forces, world.springs, s);
    dynamics.nonGravityForces(s.px.data(), s.py.data(), s.vx.data(), s.vy.data(), fx.data(),
                              fy.data());
    const Vec2 g = world.def().forces.gravity;
    out.assign(n, Vec2{});
    for (std::size_t i = 0; i < n; ++i) {
        if (!(s.flags[i] & kAlive) || !(s.invMass[i] > 0.0)) continue;
        Vec2 f{fx[i], fy[i]};
        if (!(s.flags[i] & kNoGravity)) f += g * (1.0 / s.invMass[i]);
        out[i] = f;
    }
}

namespace {
constexpr std::uint8_t kTethered = 1; // on a spring, rod or cable
constexpr std::uint8_t kTouched = 2;  // in a contact this tick
} // namespace

void ClosedFormGhosts::clear() {
    launch_.clear();
    on_.clear();
    flags_.clear();
    velocity_.clear();
    acceleration_.clear();
}

void ClosedFormGhosts::observe(const World& world) {
    const ParticleSet& s = world.particles;
    const std::size_t n = s.slots();
    const Vec2 g = world.def().forces.gravity;
    if (!(g == gravity_)) {
        clear(); // launches under the old gravity describe nothing now
        gravity_ = g;
    }
    const double now = world.time();
    const double dt = on_.empty() ? 0.0 : now - time_;
    time_ = now;
    launch_.resize(n);
    on_.resize(n, 0);
    flags_.resize(n, 0);
    velocity_.resize(n);
    acceleration_.resize(n);

    scratch_.assign(n, 0);
    auto mark = [&](ParticleId id, std::uint8_t bit) {
        if (id < n) scratch_[id] |= bit;
    };
    for (const Spring& sp : world.springs) {
        if (sp.broken) continue;
        mark(sp.a, kTethered);
        mark(sp.b, kTethered);
    }
    for (const DistanceConstraint& c : world.constraints) {
        mark(c.a, kTethered);
        mark(c.b, kTethered);
    }
    for (const ContactEvent& e : world.contacts()) {
        mark(e.a, kTouched);
        mark(e.b, kTouched);
    }
    netForces(world, forces_);

    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t f = s.flags[i];
        const bool inFlight = (f & (kAlive | kSleeping | kBallistic | kNoGravity)) == kAlive &&
                              s.invMass[i] > 0.0 && !(scratch_[i] & kTethered);
        const Vec2 v = s.velocity(static_cast<ParticleId>(i));
        const Vec2 a = forces_[i] * s.invMass[i];
        if (inFlight) {
            bool relaunch = !on_[i] || (scratch_[i] & kTouched);
            if (!relaunch) {
                // A velocity change the forces do not explain (trapezoid over the ticks since
                // the last look) is an impulse: a blast, a push from a body.
                const Vec2 explained = (acceleration_[i] + a) * (0.5 * dt);
                const Vec2 change = v - velocity_[i];
                relaunch = length(change - explained) > 0.25 + 0.1 * length(explained);
            }
            if (relaunch) {
                const bool handedOver = (flags_[i] & (kAlive | kBallistic)) == (kAlive | kBallistic) &&
                                        !(scratch_[i] & kTouched) && std::isfinite(s.launchT[i]);
                launch_[i] = handedOver ? Launch{{s.launchX[i], s.launchY[i]},
                                                 {s.launchVx[i], s.launchVy[i]},
                                                 s.launchT[i]}
                                        : Launch{s.position(static_cast<ParticleId>(i)), v, now};
            }
        }
        on_[i] = inFlight ? 1 : 0;
        flags_[i] = f;
        velocity_[i] = v;
        acceleration_[i] = a;
    }
}

std::optional<ClosedFormGhosts::Launch> ClosedFormGhosts::launch(ParticleId i) const {
    if (i >= on_.size() || !on_[i]) return std::nullopt;
    return launch_[i];
}

std::optional<BallisticState> ClosedFormGhosts::at(ParticleId i, double t) const {
    const auto l = launch(i);
    if (!l) return std::nullopt;
    return ballisticState(l->position, l->velocity, gravity_, t - l->time);
}

void contactMarks(const World& world, const RigidWorld* rigid, std::vector<ContactMark>& out) {
    out.clear();
    const ParticleSet& s = world.particles;
    for (const ContactEvent& e : world.contacts()) {
        const double r = e.a < s.slots() ? s.radius[e.a] : 0.0;
        out.push_back({ContactMark::Kind::Particle, e.position - e.normal * r, e.normal, e.resting});
    }
    if (!rigid) return;
    std::vector<RigidCircleContact> found;
    for (std::size_t i = 0; i < s.slots(); ++i) {
        if ((s.flags[i] & (kAlive | kSleeping | kNoCollide)) != kAlive || !(s.invMass[i] > 0.0))
            continue;
        rigid->circleContacts(s.position(static_cast<ParticleId>(i)), s.radius[i], found);
        for (const RigidCircleContact& c : found)
            if (c.separation <= 0.0)
                out.push_back({ContactMark::Kind::ParticleBody, c.point, c.normal, false});
    }
    std::vector<RigidContactView> pairs;
    rigid->contacts(pairs);
    for (const RigidContactView& c : pairs)
        out.push_back({ContactMark::Kind::Bodies, c.point, c.normal, false});
}

namespace {
/// A collidable particle's box: where it is, radius plus the time-of-impact tolerance
/// around it (the broad phase's box of a particle that does not move in the step).
bool particleBox(const ParticleSet& s, std::size_t i, const CollisionDef& def, Vec2& lo, Vec2& hi) {
    if ((s.flags[i] & (kAlive | kNoCollide)) != kAlive) return false;
    if (!std::isfinite(s.px[i]) || !std::isfinite(s.py[i])) return false; // the guard's to remove
    const double r = s.radius[i] + def.toiTolerance;
    lo = s.position(static_cast<ParticleId>(i)) - Vec2{r, r};
    hi = s.position(static_cast<ParticleId>(i)) + Vec2{r, r};
    return true;
}
std::int64_t cellOf(double x, double inv) {
    return static_cast<std::int64_t>(std::clamp(std::floor(x * inv), -1e15, 1e15));
}
} // namespace

double gridCellSize(const ParticleSet& s, const CollisionDef& def) {
    if (def.gridCellSize > 0.0) return def.gridCellSize;
    double sum = 0.0;
    int count = 0;
    Vec2 lo, hi;
    for (std::size_t i = 0; i < s.slots(); ++i) {
        const bool moving = s.invMass[i] > 0.0 && !(s.flags[i] & kSleeping);
        if (!moving || !particleBox(s, i, def, lo, hi)) continue;
        sum += (hi.x - lo.x) + (hi.y - lo.y);
        ++count;
    }
    return count > 0 && sum > 0.0 ? sum / count : 1.0;
}

void occupiedCells(const ParticleSet& s, const CollisionDef& def, OccupiedCells& out) {
    out.cells.clear();
    out.cellSize = gridCellSize(s, def);
    const double inv = 1.0 / out.cellSize;
    Vec2 lo, hi;
    for (std::size_t i = 0; i < s.slots(); ++i) {
        if (!particleBox(s, i, def, lo, hi)) continue;
        const std::int64_t x0 = cellOf(lo.x, inv), y0 = cellOf(lo.y, inv);
        const std::int64_t x1 = cellOf(hi.x, inv), y1 = cellOf(hi.y, inv);
        if ((x1 - x0 + 1) * (y1 - y0 + 1) > UniformGrid::kMaxCellsPerBox) continue;
        for (std::int64_t x = x0; x <= x1; ++x)
            for (std::int64_t y = y0; y <= y1; ++y)
                out.cells.push_back({x, y, 1});
    }
    std::sort(out.cells.begin(), out.cells.end(), [](const GridCell& a, const GridCell& b) {
        return a.x != b.x ? a.x < b.x : a.y < b.y;
    });
    // Merge the entries of one cell, counting its particles.
    std::size_t k = 0;
    for (std::size_t j = 0; j < out.cells.size(); ++j) {
        if (k > 0 && out.cells[k - 1].x == out.cells[j].x && out.cells[k - 1].y == out.cells[j].y)
            ++out.cells[k - 1].particles;
        else
            out.cells[k++] = out.cells[j];
    }
    out.cells.resize(k);
}

} // namespace phys
