// The cost in a corner (F3): the frame time, the physics time of the last tick, and how
// many particles, springs, rods and bodies each model moves (the closed form, the
// integrator, Box2D), so a tweak's price is seen where it is paid. A small ImGui window
// ("Cost") standing in a corner clear of the targets, cannons and shell (the game screen
// places it by the screen layout's rule and records it as the overlay "panel.Cost").
#pragma once

#include "game/match.h"

#include <imgui.h>

#include <string>
#include <vector>

namespace ui {

/// What the readout shows, gathered from the match's last tick and the frame clock.
struct CostFigures {
    double frameMs = 0.0;      ///< wall time of a frame (smoothed), ms
    double particlesUs = 0.0;  ///< the particle world's tick, us
    double rigidUs = 0.0;      ///< Box2D's step, us
    double tickHz = 0.0;       ///< ticks per simulated second
    int substeps = 1;
    std::string integrator;    ///< its canonical name
    int closedForm = 0, integrated = 0, sleeping = 0, fixed = 0; ///< particles by model
    std::size_t springs = 0;   ///< springs (all integrated)
    std::size_t rods = 0;      ///< rods and cables (projected after the integrator)
    int bodiesAwake = 0, bodiesAsleep = 0; ///< Box2D's non-static bodies
};

CostFigures costFigures(const game::Match& match, double frameMs);

/// The readout's lines, e.g. "physics 41 us/tick  (particles 35, Box2D 6)",
/// "closed form  1 particle", "velocity-verlet  12 particles, 20 springs".
std::vector<std::string> costLines(const CostFigures& f);

/// The window at `at` (ImGui's coordinates); call between newFrame and render.
void costReadout(const CostFigures& f, ImVec2 at);

/// An estimate of the window's size before it has been drawn once (ImGui's units).
ImVec2 costReadoutEstimate();

} // namespace ui
