#include "physics/diagnostics.h"

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

} // namespace phys
