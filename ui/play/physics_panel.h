// The live controls (ImGui): every setting the world has (integrator, tick rate,
// sub-steps, gravity, drag, wind, contact model, continuous detection; in a match also
// each projectile's restitution and the material pairs), time (pause, single step,
// slow motion), what to draw, and the stats line. A panel is a function that edits
// settings structs and says whether it changed them (Dear ImGui's immediate mode).
#pragma once

#include "game/settings.h"
#include "physics/stability.h"
#include "physics/world.h"
#include "ui/render/world_view.h"

#include <cstdint>
#include <optional>
#include <string>

namespace ui {

struct TimeControls {
    bool paused = false;
    bool stepRequested = false; ///< one tick, while paused
    float timeScale = 1.0f;     ///< simulated seconds per wall second
};

struct ViewControls {
    bool trails = true;
    bool labels = true;
    bool interpolate = true; ///< blend the last two ticks by the clock's alpha
    DebugOverlays draw;      ///< velocities, forces, ghosts, contacts, cells, sleeping, models
};

struct SceneRequests {
    bool fire = false;
    bool reset = false;
};

/// Figures the stats line shows.
struct FrameStats {
    double frameMs = 0.0;   ///< wall time of the last frame (smoothed), ms
    double physicsUs = 0.0; ///< World::profile().totalUs of the last tick, us
    double integrateUs = 0.0;
    double springsUs = 0.0;
    int ticksThisFrame = 0;
    std::uint64_t tick = 0;
    double simSeconds = 0.0;
    std::size_t particles = 0;
    std::size_t springs = 0;
    std::size_t vertices = 0; ///< in the renderer's last flush
    const char* context = ""; ///< which GL context draws
    std::string status;       ///< last message (screenshot saved, ...)
    /// The stiffest spring of the scene: the panel flags it past the integrator's limit.
    phys::StiffestSpring stiffest;
    /// Relative change of the energy over the last energyTrendSeconds, when known.
    std::optional<double> energyTrend;
    double energyTrendSeconds = 2.0;
};

/// Draws the panel. Returns true when `def` was edited (apply it at the next tick).
bool physicsPanel(phys::WorldDef& def, TimeControls& time, ViewControls& view, SceneRequests& scene,
                  const FrameStats& stats);
/// The panel of a match: also each projectile's restitution (a measured preset, or e
/// typed) and the table of the material pairs in play (e, friction, e typed to override
/// it). Every edit goes through game::applySetting. Returns true when `settings` changed.
bool physicsPanel(game::LiveSettings& settings, const game::MaterialsInPlay& inPlay,
                  TimeControls& time, ViewControls& view, SceneRequests& scene,
                  const FrameStats& stats);

/// Index of the gravity preset whose g matches, or -1 for a custom value.
int gravityPresetIndex(double g);

} // namespace ui
