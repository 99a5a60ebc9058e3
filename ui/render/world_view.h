// How a phys::World looks: particles as discs coloured by their state, springs as lines
// coloured by their strain, optional velocity arrows. Written against phys::DebugDraw
// only, so it can move into physics/ (as Box2D's b2World::DebugDraw) without a change.
#pragma once

#include "physics/debug_draw.h"
#include "physics/world.h"

#include <cstdint>
#include <vector>

namespace ui {

/// Particle positions at one tick, kept so frames can be drawn between two ticks.
struct PositionSnapshot {
    std::vector<double> x, y;
    std::vector<std::uint32_t> flags;
    void capture(const phys::ParticleSet& set);
};

struct WorldDrawOptions {
    bool springs = true;
    bool velocities = false;
    double velocityScale = 0.1; ///< arrow length per unit speed, s (m per m/s)
    double minRadius = 0.0;     ///< m; discs are never drawn smaller (keep tiny ones visible)
    /// The previous tick's positions and the blend factor (FixedClock::alpha): drawn at
    /// previous + alpha (current - previous). Null draws the current tick.
    const PositionSnapshot* previous = nullptr;
    double alpha = 1.0;
};

/// Colour of a particle by its state: fixed, sleeping, projectile, drag-free, free.
phys::Color particleColor(std::uint32_t flags, double invMass);
/// Colour of a spring by its strain (L - L0) / L0: blue compressed, grey at rest, red stretched.
phys::Color springColor(double strain);

/// Where particle i is drawn this frame (interpolated when a snapshot is given).
phys::Vec2 drawnPosition(const phys::ParticleSet& set, std::size_t i,
                         const WorldDrawOptions& options);

void drawWorld(phys::DebugDraw& draw, const phys::World& world, const WorldDrawOptions& options);

} // namespace ui
