// How a phys::World looks: particles as discs coloured by their state, springs as lines
// coloured by their strain, and the debug view's overlays (the "Draw" controls):
// velocities, net forces, closed-form ghosts, contacts, broad-phase cells, sleeping state
// and the model each object is in. Written against phys::DebugDraw only, so it can move
// into physics/ (as Box2D's b2World::DebugDraw) without a change, and a test can record
// exactly what it emits.
//
// Section index
//   options      PositionSnapshot, DebugOverlays, WorldDrawOptions
//   colours      particleColor, springColor, the overlays' colours (kOverlay*)
//   drawing      drawWorld (particles, springs, overlays), drawOverlays (overlays alone)
#pragma once

#include "physics/debug_draw.h"
#include "physics/diagnostics.h"
#include "physics/world.h"

#include <cstdint>
#include <vector>

namespace phys {
class RigidWorld;
}

namespace ui {

/// Particle positions at one tick, kept so frames can be drawn between two ticks.
struct PositionSnapshot {
    std::vector<double> x, y;
    std::vector<std::uint32_t> flags;
    void capture(const phys::ParticleSet& set);
};

/// The debug view's toggles: the "draw" section of the physics panel, the `artillery
/// play` flags of the same names. Each draws over whatever shows the world.
struct DebugOverlays {
    bool velocities = false; ///< velocity arrows (yellow)
    bool forces = false;     ///< net force arrows (magenta): gravity, drag, wind, springs
    bool ghosts = false;     ///< closed-form ghost and exact parabola of integrated flights
    bool contacts = false;   ///< last tick's contact points and normals (red)
    bool cells = false;      ///< uniform-grid cells that hold particles (green)
    bool sleeping = false;   ///< sleeping particles and bodies dimmed, with a "z"
    bool models = false;     ///< a ring per particle, an outline per body: its model
    double velocityScale = 0.1; ///< m of arrow per m/s (s)
    /// Screen pixels of arrow per weight: a particle's force arrow is F / (m |g|) times
    /// this, so gravity alone draws this long straight down whatever the mass and the zoom
    /// (|g| = 9.81 m/s^2 when there is no gravity).
    double weightArrowPixels = 30.0;
    /// Force arrows longer than this many weights are drawn this long with a second head.
    static constexpr double kMaxWeights = 3.0;
    bool any() const {
        return velocities || forces || ghosts || contacts || cells || sleeping || models;
    }
};

struct WorldDrawOptions {
    bool springs = true;
    double minRadius = 0.0; ///< m; discs are never drawn smaller (keep tiny ones visible)
    /// The previous tick's positions and the blend factor (FixedClock::alpha): drawn at
    /// previous + alpha (current - previous). Null draws the current tick.
    const PositionSnapshot* previous = nullptr;
    double alpha = 1.0;
    DebugOverlays overlays;
    /// Metres per screen pixel: markers, heads and rings keep their size on screen.
    double pixel = 0.02;
    /// Launch states for `overlays.ghosts` (kept by the caller, observed every tick).
    const phys::ClosedFormGhosts* ghosts = nullptr;
    /// Box2D bodies for contacts, sleeping and models (the game's blocks), if any.
    const phys::RigidWorld* rigid = nullptr;
};

/// Colour of a particle by its state: fixed, sleeping, projectile, drag-free, free.
phys::Color particleColor(std::uint32_t flags, double invMass);
/// Colour of a spring by its strain (L - L0) / L0: blue compressed, grey at rest, red stretched.
phys::Color springColor(double strain);

// The overlays' colours, each distinct from the others and from the scene's.
inline constexpr phys::Color kOverlayVelocity = phys::Color::hex(0xffe14d);
inline constexpr phys::Color kOverlayForce = phys::Color::hex(0xff3df0);
inline constexpr phys::Color kOverlayGhost = phys::Color::hex(0xf2d9ff);
inline constexpr phys::Color kOverlayGhostPath = phys::Color::hex(0xf2d9ff, 0.45f);
inline constexpr phys::Color kOverlayGhostError = phys::Color::hex(0xff7a45);
inline constexpr phys::Color kOverlayContact = phys::Color::hex(0xff1f1f);
inline constexpr phys::Color kOverlayCell = phys::Color::hex(0x3dff5a);
inline constexpr phys::Color kOverlaySleep = phys::Color::hex(0xa98bff);
inline constexpr phys::Color kOverlaySleepShade = phys::Color::hex(0x0b0f1a, 0.5f);
/// The ring of each model (overlays.models), and the outline of Box2D bodies.
phys::Color modelColor(phys::ParticleModel model);
inline constexpr phys::Color kOverlayRigidAwake = phys::Color::hex(0xff7ad0);
inline constexpr phys::Color kOverlayRigidAsleep = phys::Color::hex(0x8c5a7c);

/// Where particle i is drawn this frame (interpolated when a snapshot is given).
phys::Vec2 drawnPosition(const phys::ParticleSet& set, std::size_t i,
                         const WorldDrawOptions& options);

/// Springs, particles, then the overlays.
void drawWorld(phys::DebugDraw& draw, const phys::World& world, const WorldDrawOptions& options);
/// The overlays alone, over a world drawn some other way (the game's own art). Never
/// emits a non-finite coordinate: a particle with one is skipped.
void drawOverlays(phys::DebugDraw& draw, const phys::World& world, const WorldDrawOptions& options);

} // namespace ui
