// The compare's colours and the compared shot's work-precision chart: each integrator's
// landing error against the force evaluations it spent (game/compare_work.h), log-log,
// one line per integrator in its path's colour, drawn beside the paths' legend.
#pragma once

#include "game/compare.h"
#include "game/compare_work.h"
#include "ui/charts/chart.h"

namespace ui {

/// The colour of an integrator's path, legend row and chart line.
Color compareColor(phys::Integrator m);
/// A path's colour: its integrator's, white for the reference.
Color compareColor(const game::IntegratorPath& p);

/// Errors below this are drawn on it (m): a log axis has no 0, and RK4 or velocity
/// Verlet under gravity alone land on the closed form to the last bits.
inline constexpr double kShotWorkFloor = 1e-6;

/// The chart: x force evaluations to the landing, y landing error (m, said in the title),
/// a line per integrator with the tick falling along it; no legend (the paths' legend is
/// beside).
charts::Chart shotWorkChart(const game::ShotWork& work);

} // namespace ui
