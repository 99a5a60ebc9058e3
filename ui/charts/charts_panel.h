// The in-game Charts panel: the bench's diagrams (work-precision for the current scene,
// stability, scaling) measured on request and drawn with the same chart code as the
// PNGs, plus the "accurate enough, fastest" choice for a tolerance.
//
// Two calls per frame, like the rest of the game's UI:
//   drawChartsPanel(renderer, state, rect)  in the geometry pass (after the world,
//                                           before flush): the chart in a screen rect;
//   chartsControls(state)                   between ImGuiLayer::newFrame and render,
//                                           inside the window that opened the charts
//                                           (the Stats panel): the controls; returns
//                                           what was asked.
#pragma once

#include "game/bench/choose.h"
#include "game/bench/scaling.h"
#include "game/bench/stability.h"
#include "ui/charts/chart.h"
#include "ui/render/pixel_rect.h"

#include <algorithm>
#include <optional>
#include <vector>

namespace ui::charts {

enum class ChartsView { WorkPrecision, Stability, Scaling };

struct ChartsPanelState {
    bool open = true;
    ChartsView view = ChartsView::WorkPrecision;
    game::bench::AccuracyScene scene = game::bench::AccuracyScene::ProjectileDrag;
    double tolerance = 1e-3; ///< m, for "accurate enough, fastest"
    // Measurements (empty until measured; measuring runs on the UI thread for about a
    // second: the quick sweeps of the bench).
    std::vector<game::bench::WorkPrecisionPoint> points;
    std::vector<game::bench::StabilityRow> stability;
    std::vector<game::bench::GrowthCurve> growth;
    game::bench::ScalingReport scaling;
    std::optional<game::bench::MethodChoice> choice;
    bool choiceSearched = false; ///< a search ran (so "none within tolerance" can be said)
};

struct ChartsPanelRequests {
    /// The user pressed "use it": apply choice->integrator and
    /// choice->substepsPerTick(tick) to the world's settings.
    bool applyChoice = false;
};

/// Where the charts go on a screen of w x h pixels: from `top` (px, below whatever the
/// caller keeps at the top left) to above the panels at the bottom (7/10 of the way
/// down), from the left edge to short of the target's view and the Stats panel.
inline Rect chartsArea(double w, double h, double top) {
    return {0.02 * w, top, 0.66 * w, std::min(0.55 * h, 0.70 * h - top)};
}

/// `area` less what `panel` covers of its left side: it starts `gap` right of the panel
/// where the two overlap (its right edge stays), unless that leaves under half of it.
inline Rect rightOf(Rect area, const PixelRect& panel, double gap) {
    const double right = area.x + area.w, left = panel.x1 + gap;
    const bool overlaps = panel.overlaps({area.x, area.y, right, area.y + area.h});
    if (!overlaps || right - left < 0.5 * area.w) return area;
    return {left, area.y, right - left, area.h};
}

/// The controls (view, scene, Measure, "accurate enough, fastest"), drawn into the
/// current ImGui window: the panel that opened the charts keeps them beside its button,
/// off the charts and off the player's HUD. Measures when asked.
ChartsPanelRequests chartsControls(ChartsPanelState& state);

/// Draws the current view's charts into `area` (pixels) with the game's renderer.
void drawChartsPanel(Renderer2D& r, const ChartsPanelState& state, Rect area);

/// Measures what the current view needs (quick sweeps), without any UI.
void measure(ChartsPanelState& state);
/// Runs "accurate enough, fastest" for state.scene and state.tolerance on state.points
/// (measuring them first when needed).
void choose(ChartsPanelState& state);

} // namespace ui::charts
