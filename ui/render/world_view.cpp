#include "ui/render/world_view.h"

#include <algorithm>
#include <cmath>

namespace ui {

using phys::Color;
using phys::Vec2;

void PositionSnapshot::capture(const phys::ParticleSet& set) {
    x = set.px;
    y = set.py;
    flags = set.flags;
}

Color particleColor(std::uint32_t flags, double invMass) {
    if (invMass == 0.0) return Color::hex(0x8a9099);          // fixed: anchors, walls
    if (flags & phys::kSleeping) return Color::hex(0x6c7fa3); // asleep: skipped by the step
    if (flags & phys::kProjectile)
        return (flags & phys::kNoDrag) ? Color::hex(0xe8f0ff, 0.85f) // vacuum reference shot
                                       : Color::hex(0xff8a1e);       // shell in the air
    if (flags & phys::kAttractor) return Color::hex(0xb07cf0);
    return Color::hex(0x3fb6c9);
}

Color springColor(double strain) {
    const Color rest = Color::hex(0xc9ccd2), stretched = Color::hex(0xe8473a),
                squeezed = Color::hex(0x3a7de8);
    // Full colour at 10 % strain: visible long before anything breaks.
    const float t = static_cast<float>(std::min(std::abs(strain) / 0.1, 1.0));
    const Color& to = strain > 0.0 ? stretched : squeezed;
    return {rest.r + (to.r - rest.r) * t, rest.g + (to.g - rest.g) * t,
            rest.b + (to.b - rest.b) * t, 1.0f};
}

Vec2 drawnPosition(const phys::ParticleSet& set, std::size_t i, const WorldDrawOptions& o) {
    const Vec2 now{set.px[i], set.py[i]};
    const PositionSnapshot* prev = o.previous;
    // A slot that was dead (or reused) in the previous tick has nothing to blend from.
    if (!prev || i >= prev->x.size() || !(prev->flags[i] & phys::kAlive)) return now;
    const Vec2 before{prev->x[i], prev->y[i]};
    return before + (now - before) * o.alpha;
}

void drawWorld(phys::DebugDraw& draw, const phys::World& world, const WorldDrawOptions& o) {
    const phys::ParticleSet& set = world.particles;

    if (o.springs) {
        for (const phys::Spring& s : world.springs) {
            if (s.broken || !set.alive(s.a)) continue;
            const Vec2 a = drawnPosition(set, s.a, o);
            const bool toParticle = s.b != phys::kNoParticle;
            if (toParticle && !set.alive(s.b)) continue;
            const Vec2 b = toParticle ? drawnPosition(set, s.b, o) : s.anchor;
            const double len = phys::length(a - b);
            const double strain = s.restLength > 0.0 ? (len - s.restLength) / s.restLength : 0.0;
            draw.segment(a, b, springColor(strain));
        }
    }

    for (std::size_t i = 0; i < set.slots(); ++i) {
        if (!(set.flags[i] & phys::kAlive)) continue;
        const Vec2 p = drawnPosition(set, i, o);
        const double r = std::max(set.radius[i], o.minRadius);
        draw.solidCircle(p, r, {}, particleColor(set.flags[i], set.invMass[i]));
    }

    if (o.velocities) {
        const Color arrow = Color::hex(0xffe14d);
        for (std::size_t i = 0; i < set.slots(); ++i) {
            if (!(set.flags[i] & phys::kAlive) || set.invMass[i] == 0.0) continue;
            const Vec2 p = drawnPosition(set, i, o);
            const Vec2 tip = p + set.velocity(static_cast<phys::ParticleId>(i)) * o.velocityScale;
            // An arrow from segments, so any DebugDraw can show it.
            const Vec2 d = tip - p;
            const double len = phys::length(d);
            if (len <= 1e-9) continue;
            const Vec2 u = d / len;
            const double head = std::min(0.25 * len, 0.5);
            draw.segment(p, tip, arrow);
            draw.segment(tip, tip - u * head + phys::perp(u) * (0.5 * head), arrow);
            draw.segment(tip, tip - u * head - phys::perp(u) * (0.5 * head), arrow);
        }
    }
}

} // namespace ui
