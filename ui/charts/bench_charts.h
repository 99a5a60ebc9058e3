// The bench's measurements as charts: work-precision (one panel per scene), stability
// (energy growth against w dt, the largest stable w dt and the stiffest rope spring per
// integrator) and scaling (cost per step against N, and the side-by-side ratios). Used
// by `artillery bench` for its PNGs and by the in-game Charts panel.
#pragma once

#include "game/bench/scaling.h"
#include "game/bench/stability.h"
#include "game/bench/work_precision.h"
#include "ui/charts/chart.h"

#include <string>
#include <vector>

namespace ui::charts {

/// The same colour and marker for an integrator in every chart.
Color integratorColor(phys::Integrator m);
Marker integratorMarker(phys::Integrator m);
/// One legend entry per integrator (a line with its marker and name).
std::vector<Series> integratorLegend();

/// One chart per scene present in `points`: error (m) against CPU time per simulated
/// second, log-log, one line per integrator, dt falling along each line.
std::vector<Chart> workPrecisionCharts(const std::vector<game::bench::WorkPrecisionPoint>& points);

std::vector<Chart> stabilityCharts(const std::vector<game::bench::StabilityRow>& rows,
                                   const std::vector<game::bench::GrowthCurve>& curves);

std::vector<Chart> scalingCharts(const game::bench::ScalingReport& report);

/// Pictures: the charts of each kind laid out for a PNG of width x height (or a panel).
void drawWorkPrecision(Renderer2D& r, Rect area,
                       const std::vector<game::bench::WorkPrecisionPoint>& points);
void drawStability(Renderer2D& r, Rect area, const std::vector<game::bench::StabilityRow>& rows,
                   const std::vector<game::bench::GrowthCurve>& curves);
void drawScaling(Renderer2D& r, Rect area, const game::bench::ScalingReport& report);

/// The scaling charts' title, with where they were measured (the machine, and the load
/// or that they were taken under load), since their figures move with both. In a panel
/// too narrow for a line of both (`narrow`) it gives its line to where: the line charts'
/// own titles say what they show.
std::string scalingTitle(const game::bench::ScalingReport& report, bool narrow);

} // namespace ui::charts
