#include "physics/coupling.h"

#include <cmath>

namespace phys {

CouplingStats ParticleBodyCoupling::exchange(ParticleSet& set, const MaterialTable& materials,
                                             RigidWorld& rigid) {
    CouplingStats stats;
    events_.clear();
    for (std::size_t i = 0; i < set.slots(); ++i) {
        const std::uint32_t flags = set.flags[i];
        if (!(flags & kAlive) || (flags & (kNoCollide | kSleeping)) || set.invMass[i] <= 0.0)
            continue;
        const auto id = static_cast<ParticleId>(i);
        const double r = set.radius[i];
        rigid.circleContacts(set.position(id), r, contacts_);
        for (const RigidCircleContact& c : contacts_) {
            if (c.separation > 0.0) continue;
            ++stats.contacts;
            const Vec2 n = c.normal;
            // Move the particle out of the body (position only).
            set.px[i] -= c.separation * n.x;
            set.py[i] -= c.separation * n.y;
            const Vec2 u = set.velocity(id) - rigid.velocityAt(c.body, c.point);
            const double un = dot(u, n);
            if (un >= 0.0) continue; // separating or resting without approach
            const Material& pm = materials[set.material[i]];
            const double e = pm.restitution * c.restitution;
            const double mu = std::sqrt(pm.dynamicFriction * c.friction);
            const double wp = set.invMass[i];
            const double wn = wp + rigid.inverseEffectiveMass(c.body, c.point, n);
            const double jn = -(1.0 + e) * un / wn;
            Vec2 J = n * jn;
            const Vec2 ut = u - n * un;
            const double slip = length(ut);
            if (slip > 0.0) {
                const Vec2 t = ut / slip;
                const double wt = wp + rigid.inverseEffectiveMass(c.body, c.point, t);
                const double jt = std::max(-slip / wt, -mu * jn); // clamp to the friction cone
                J += t * jt;
            }
            // The body gets -J (it pushes back on the particle with +J); the particle gets
            // minus what the body actually received.
            const Vec2 delivered = rigid.applyImpulse(c.body, -J, c.point);
            set.setVelocity(id, set.velocity(id) - delivered * wp);
            events_.push_back({id, c.body, c.point, n, -un, -delivered});
            ++stats.impulses;
            stats.impulseSum += length(delivered);
        }
    }
    return stats;
}

} // namespace phys
