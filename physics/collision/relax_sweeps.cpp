// The sweeps of the end-of-step contact solver (ParticleCollisions::relaxContacts): warm
// start, velocity sweeps over all contacts and then band by band, position sweeps the
// same way. Each contact is visited some twenty times a sub-step, so the sweeps run on a
// layout made for the loop, built once:
//   rows      one row per contact and phase, in the order the phase visits them, holding
//             what the visit reads (normal, closing speed, friction, the inverse and the
//             effective masses, each side's share of a push); the banded masses of shock
//             propagation are worked out once per contact, not once per visit;
//   copies    the velocities and positions as pairs, with two slots past the particles:
//             kStill, at rest, which a shape reads as its velocity, and kSink, which
//             takes the push on an immovable side, so no visit branches on either;
//   masses    each row keeps its effective mass 1 / (wa + wb), so a visit multiplies
//             where it divided twice (a division costs several multiplications' time);
//             a normal divides both of its components by one length in one two-lane
//             division, which rounds each lane as the scalar one does; a pair of balls
//             apart by their radii or more needs no push, and costs no square root.
#include "physics/collision/particle_collisions.h"

#include <algorithm>
#include <cmath>

namespace phys {

namespace {

// Two doubles in one SSE register: x / y lane by lane is IEEE division in each lane.
using Lanes = double __attribute__((vector_size(16)));

// (x0 / d, x1 / d), each rounded as the scalar division rounds it.
inline Lanes divideBoth(double x0, double x1, double d) {
    const Lanes num = {x0, x1}, den = {d, d};
    return num / den;
}

// The mass the contact's impulse moves: 1 / (wa + wb), 0 when neither side moves.
inline double effectiveMass(double wa, double wb) {
    return wa + wb > 0.0 ? 1.0 / (wa + wb) : 0.0;
}

} // namespace

// The sweeps, as the solve's steps: copies in, warm start, velocity, position, copies out.
void ParticleCollisions::sweepContacts(ParticleSet& set, const StaticShapes& shapes,
                                       const CollisionDef& def) {
    copyForSweeps(set);
    warmStart();
    buildImpulseRows();
    sweepImpulses(def);
    buildProjectRows(set);
    sweepProjections(shapes, def);
    copyAfterSweeps(set);
}

// The velocities and positions as pairs, kStill at rest, and "moved by the solver" cleared
// for every slot.
void ParticleCollisions::copyForSweeps(const ParticleSet& set) {
    const auto n = static_cast<std::uint32_t>(set.slots());
    sweepVelocity_.resize(n + 2);
    sweepPosition_.resize(n + 2);
    for (std::uint32_t i = 0; i < n; ++i) {
        sweepVelocity_[i] = {set.vx[i], set.vy[i]};
        sweepPosition_[i] = {set.px[i], set.py[i]};
    }
    sweepVelocity_[n] = sweepVelocity_[n + 1] = {}; // kStill, kSink
    if (touched_.size() < n + 2) touched_.resize(n + 2);
    std::fill(touched_.begin(), touched_.end(), 0);
}

void ParticleCollisions::copyAfterSweeps(ParticleSet& set) const {
    for (std::size_t i = 0; i < set.slots(); ++i) {
        set.vx[i] = sweepVelocity_[i].x, set.vy[i] = sweepVelocity_[i].y;
        set.px[i] = sweepPosition_[i].x, set.py[i] = sweepPosition_[i].y;
    }
}

// A contact that was there at the end of the last sub-step starts from the impulses it
// ended with (both lists are in pair order, so one merge finds them). In a resting pile
// those are nearly the answer, and the sweeps only correct them.
void ParticleCollisions::warmStart() {
    Vec2* const v = sweepVelocity_.data();
    std::size_t w = 0;
    for (RelaxContact& c : contacts_) {
        const std::uint64_t key = (std::uint64_t{c.a} << 32) | c.proxy;
        while (w < warm_.size() && warm_[w].key < key)
            ++w;
        if (w == warm_.size() || warm_[w].key != key) continue;
        c.normalImpulse = warm_[w].normalImpulse;
        c.tangentImpulse = warm_[w].tangentImpulse;
        const Vec2 J = c.normal * c.normalImpulse + perp(c.normal) * c.tangentImpulse;
        v[c.a] += J * c.wa;
        touched_[c.a] = 1;
        if (c.b != kNoParticle) {
            v[c.b] -= J * c.wb;
            touched_[c.b] = 1;
        }
    }
}

// The velocity rows, in contactOrder_; those of bands 1 to bands - 2, which are swept on
// their own (band 0 is never used, and the last holds the contacts that nothing connects
// to the ground), with the masses of their band too.
void ParticleCollisions::buildImpulseRows() {
    const auto kSink = static_cast<std::uint32_t>(sweepVelocity_.size() - 1);
    const auto kStill = kSink - 1;
    const std::size_t count = contacts_.size(), bands = bandStart_.size() - 1;
    impulseRows_.resize(count);
    for (std::uint32_t k = 0; k < count; ++k) {
        const RelaxContact& c = contacts_[contactOrder_[k]];
        ImpulseRow& r = impulseRows_[k];
        const bool shape = c.b == kNoParticle;
        r.a = c.a;
        r.readB = shape ? kStill : c.b;
        r.pushB = !shape && c.wb > 0.0 ? c.b : kSink;
        r.nx = c.normal.x, r.ny = c.normal.y;
        r.closing = c.closing, r.friction = c.friction;
        r.wa = c.wa, r.wb = c.wb, r.mass = effectiveMass(c.wa, c.wb);
        r.normalImpulse = c.normalImpulse, r.tangentImpulse = c.tangentImpulse;
    }
    for (std::size_t band = 1; band + 1 < bands; ++band)
        for (std::uint32_t k = bandStart_[band]; k < bandStart_[band + 1]; ++k) {
            const RelaxContact& c = contacts_[contactOrder_[k]];
            ImpulseRow& r = impulseRows_[k];
            const auto [wa, wb] = shockMasses(c, static_cast<std::uint32_t>(band));
            r.shockWa = wa, r.shockWb = wb, r.shockMass = effectiveMass(wa, wb);
            r.shockB = c.b != kNoParticle && wb > 0.0 ? c.b : kSink;
        }
}

// Velocity: sweeps over all contacts, then band by band from the ground up; the impulses
// they end with go back to the contacts (the warm start and the events read them there).
void ParticleCollisions::sweepImpulses(const CollisionDef& def) {
    Vec2* const v = sweepVelocity_.data();
    // One contact's velocity step: the normal impulse that stops the closing velocity
    // (accumulated, never pulling), and friction along the tangent within mu_s times it.
    auto impulse = [&](ImpulseRow& r, double wa, double wb, double mass, std::uint32_t pushB) {
        if (!(mass > 0.0)) return;
        const Vec2 vrel = v[r.a] - v[r.readB];
        const Vec2 normal{r.nx, r.ny}, t = perp(normal);
        const double total =
            std::max(r.normalImpulse - (dot(vrel, normal) + r.closing) * mass, 0.0);
        const double jn = total - r.normalImpulse;
        r.normalImpulse = total;
        const double limit = r.friction * r.normalImpulse;
        const double tangential = std::clamp(r.tangentImpulse - dot(vrel, t) * mass, -limit, limit);
        const double jt = tangential - r.tangentImpulse;
        r.tangentImpulse = tangential;
        if (jn == 0.0 && jt == 0.0) return;
        const Vec2 J = normal * jn + t * jt;
        v[r.a] += J * wa;
        v[pushB] -= J * wb;
        touched_[r.a] = 1;
        touched_[pushB] = 1;
    };
    const std::size_t bands = bandStart_.size() - 1;
    for (int sweep = 0; sweep < def.relaxVelocitySweeps; ++sweep)
        for (ImpulseRow& r : impulseRows_)
            impulse(r, r.wa, r.wb, r.mass, r.pushB);
    for (std::size_t band = 1; band + 1 < bands; ++band)
        for (int sweep = 0; sweep < kShockSweeps; ++sweep)
            for (std::uint32_t k = bandStart_[band]; k < bandStart_[band + 1]; ++k) {
                ImpulseRow& r = impulseRows_[k];
                impulse(r, r.shockWa, r.shockWb, r.shockMass, r.shockB);
            }
    for (std::uint32_t k = 0; k < impulseRows_.size(); ++k) {
        RelaxContact& c = contacts_[contactOrder_[k]];
        c.normalImpulse = impulseRows_[k].normalImpulse;
        c.tangentImpulse = impulseRows_[k].tangentImpulse;
    }
}

// The position rows: contactOrder_ with the contacts against what never moves (a shape, a
// fixed or sleeping particle) after the others, in the whole list and within each band,
// so that nothing is left inside those, whatever else stays to do. A row whose sides are
// both immovable in its band is left out: its visit would do nothing.
void ParticleCollisions::buildProjectRows(const ParticleSet& set) {
    const auto kSink = static_cast<std::uint32_t>(sweepPosition_.size() - 1);
    const std::size_t count = contacts_.size(), bands = bandStart_.size() - 1;
    auto immovableSide = [](const RelaxContact& c) {
        return c.b == kNoParticle || c.wa == 0.0 || c.wb == 0.0;
    };
    auto addRow = [&](std::vector<ProjectRow>& rows, std::uint32_t k, double wa, double wb) {
        if (!(wa + wb > 0.0)) return;
        const std::uint32_t index = contactOrder_[k];
        const RelaxContact& c = contacts_[index];
        ProjectRow r;
        r.a = c.a, r.b = c.b, r.contact = index;
        r.pushB = c.b != kNoParticle && wb > 0.0 ? c.b : kSink;
        const double ra = set.radius[c.a];
        r.reach = c.b == kNoParticle ? ra : ra + set.radius[c.b];
        r.cap = 0.2 * (c.b == kNoParticle ? ra : std::min(ra, set.radius[c.b]));
        r.fa = wa / (wa + wb), r.fb = wb / (wa + wb);
        rows.push_back(r);
    };
    auto movableFirst = [&](std::uint32_t from, std::uint32_t to, std::vector<ProjectRow>& rows,
                            bool banded) {
        for (const bool statics : {false, true})
            for (std::uint32_t k = from; k < to; ++k) {
                const RelaxContact& c = contacts_[contactOrder_[k]];
                if (immovableSide(c) != statics) continue;
                if (!banded) {
                    addRow(rows, k, c.wa, c.wb);
                } else {
                    const ImpulseRow& ir = impulseRows_[k];
                    addRow(rows, k, ir.shockWa, ir.shockWb);
                }
            }
    };
    projectRows_.clear();
    movableFirst(0, static_cast<std::uint32_t>(count), projectRows_, false);
    shockProjectRows_.clear();
    shockProjectStart_.assign(bands + 1, 0u); // where each band's rows start
    for (std::size_t band = 1; band + 1 < bands; ++band) {
        shockProjectStart_[band] = static_cast<std::uint32_t>(shockProjectRows_.size());
        movableFirst(bandStart_[band], bandStart_[band + 1], shockProjectRows_, true);
        shockProjectStart_[band + 1] = static_cast<std::uint32_t>(shockProjectRows_.size());
    }
}

// Position: sweeps over all contacts, then band by band from the ground up. Velocities are
// left as the impulses made them, so the projection adds no energy.
void ParticleCollisions::sweepProjections(const StaticShapes& shapes, const CollisionDef& def) {
    Vec2* const p = sweepPosition_.data();
    // One contact's position step: push the overlap apart along the current normal, at most
    // a fifth of the smaller radius at a time.
    auto project = [&](const ProjectRow& r) {
        Vec2 normal;
        double depth;
        if (r.b == kNoParticle) {
            const RelaxContact& c = contacts_[r.contact];
            SurfacePoint sp = shapes.closestPoint(c.shape, p[r.a]);
            // Keep the side the contact was found on: a segment has two, and a centre
            // that the other contacts pushed across it must come back across, at once,
            // not be pushed out of the far side (and fall out of the level).
            const bool crossed = dot(sp.normal, c.normal) < 0.0;
            if (crossed) sp = {-sp.distance, c.normal};
            normal = sp.normal;
            depth = crossed ? r.reach - sp.distance : std::min(r.reach - sp.distance, r.cap);
        } else {
            const Vec2 d = p[r.a] - p[r.b];
            const double distanceSquared = dot(d, d);
            if (distanceSquared >= r.reach * r.reach) return;
            const double L = std::sqrt(distanceSquared);
            if (L > 0.0) {
                const Lanes unit = divideBoth(d.x, d.y, L);
                normal = {unit[0], unit[1]};
            } else {
                normal = {0.0, 1.0};
            }
            depth = std::min(r.reach - L, r.cap);
        }
        if (!(depth > 0.0)) return;
        const Vec2 move = normal * depth;
        p[r.a] += move * r.fa;
        p[r.pushB] -= move * r.fb;
        touched_[r.a] = 1;
        touched_[r.pushB] = 1;
    };
    const std::size_t bands = bandStart_.size() - 1;
    for (int sweep = 0; sweep < def.relaxPositionSweeps; ++sweep)
        for (const ProjectRow& r : projectRows_)
            project(r);
    for (std::size_t band = 1; band + 1 < bands; ++band)
        for (int sweep = 0; sweep < kShockSweeps; ++sweep)
            for (std::uint32_t k = shockProjectStart_[band]; k < shockProjectStart_[band + 1]; ++k)
                project(shockProjectRows_[k]);
}

} // namespace phys
