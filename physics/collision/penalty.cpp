#include "physics/collision/penalty.h"

#include "physics/collision/contact_impulse.h"

#include <algorithm>
#include <cmath>

namespace phys {

void resolvePenaltyContacts(const Substep& sub, const std::vector<ProxyPair>& pairs) {
    ParticleSet& set = sub.set;
    const StaticShapes& shapes = sub.shapes;
    const auto n = static_cast<std::uint32_t>(set.slots());
    for (const ProxyPair& pair : pairs) {
        const std::uint32_t a = pair.first, b = pair.second;
        const bool isStatic = b >= n;
        if (!isStatic && !sub.def.particlePairs) continue;
        const Vec2 pa = set.position(a);
        SurfacePoint sp;
        double reach = set.radius[a];
        ShapeRef ref{};
        if (isStatic) {
            ref = shapes.ref(b - n);
            sp = shapes.closestPoint(ref, pa);
        } else {
            const Vec2 dv = pa - set.position(b);
            const double L = length(dv);
            sp = {L, L > 0.0 ? dv / L : Vec2{0.0, 1.0}};
            reach += set.radius[b];
        }
        const double depth = reach - sp.distance;
        if (!(depth > 0.0)) continue;
        const double wa = movable(set, a) ? set.invMass[a] : 0.0;
        const double wb = isStatic || !movable(set, b) ? 0.0 : set.invMass[b];
        const Vec2 vrel = set.velocity(a) - (isStatic ? Vec2{} : set.velocity(b));
        const PairProperties& pp =
            sub.mats.pair(set.material[a], isStatic ? shapes.material(ref) : set.material[b]);
        const double vn = dot(vrel, sp.normal);
        const double jn =
            penaltyImpulse(depth, vn, wa, wb, pp.restitution, sub.def.penaltyHertz, sub.h);
        // Dynamic friction only (a spring contact has no sticking state), never reversing.
        const Vec2 vt = vrel - sp.normal * vn;
        const double speedT = length(vt);
        Vec2 J = sp.normal * jn;
        if (speedT > 0.0 && wa + wb > 0.0)
            J -= vt / speedT * std::min(pp.dynamicFriction * jn, speedT / (wa + wb));
        set.vx[a] += J.x * wa, set.vy[a] += J.y * wa;
        set.flags[a] &= ~(kHistory | kSleeping);
        if (!isStatic) {
            set.vx[b] -= J.x * wb, set.vy[b] -= J.y * wb;
            if (wb > 0.0) set.flags[b] &= ~(kHistory | kSleeping);
        }
        sub.events.push_back({a, isStatic ? kNoParticle : b, ref, sub.tickTime + sub.h, sp.normal,
                              -vn, jn, false, pa, set.velocity(a)});
        ++sub.stats.impacts;
    }
}

} // namespace phys
