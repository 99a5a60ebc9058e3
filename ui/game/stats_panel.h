// The Stats window: Compare (the current aim fired with every
// integrator at once, each path drawn in the world in its own colour, with its landing
// error in a legend), a live plot of the match's total energy and momentum over the last
// seconds, and the Charts panel (work-precision, stability, scaling) behind a button.
//
// Three calls, like the rest of the game's UI:
//   sample(match)               after every tick: one energy and momentum sample;
//   panel(match, aim)           between ImGuiLayer::newFrame and render: the window;
//                               returns world settings to apply ("use it" in Charts);
//   drawWorld(renderer, match)  in the geometry pass, after the match: the compare
//                               paths and the charts.
#pragma once

#include "game/compare.h"
#include "game/compare_work.h"
#include "game/match.h"
#include "ui/charts/charts_panel.h"
#include "ui/game/match_view.h"
#include "ui/game/screen_layout.h"
#include "ui/render/renderer2d.h"

#include <optional>
#include <string>
#include <vector>

namespace ui {

/// One tick's conserved quantities: particles (springs included) plus Box2D bodies.
struct ConservedSample {
    double time = 0.0;     ///< s
    double energy = 0.0;   ///< kinetic + gravitational + elastic, J
    double momentumX = 0.0; ///< kg m/s
    double momentumY = 0.0; ///< kg m/s
};

/// Energy and momentum of everything that moves in the match (particles, springs and the
/// kinetic energy and momentum of dynamic rigid bodies; their potential energy in gravity
/// too, -m g.c at the centre of mass, so a falling block conserves).
ConservedSample conservedQuantities(const game::Match& match);

class StatsPanel {
  public:
    StatsPanel() { charts_.open = false; }
    /// After every tick. A match whose clock went back (rewind, restart) starts afresh.
    void sample(const game::Match& match);
    /// The Stats window, with the charts' controls in it while the charts are open. `aim`
    /// is the aim on screen. Returns world settings to apply when the charts' "Use it"
    /// was pressed.
    std::optional<phys::WorldDef> panel(const game::Match& match, const PendingAim& aim);
    /// The compared shot's work-precision (empty before the first compare).
    const game::ShotWork& work() const { return work_; }
    /// Every frame, shown or not: the compare paths follow the aim (and the tick, the
    /// wind, the projectile, drag) while they are on and "follow the aim" is ticked.
    void followAim(const game::Match& match, const PendingAim& aim);
    /// Compare in one key (X): the paths of every integrator for the aim on screen, on
    /// or off, without the window.
    void toggleCompare(const game::Match& match, const PendingAim& aim);
    /// Compare paths and the charts, through the match's camera (begin() already called).
    /// The legend stands where it covers nothing in `layout` (when given) and is added
    /// to it as the overlay "compare.legend"; with no clear place it is left out. The
    /// shot's work-precision chart stands beside it the same way ("compare.chart").
    void drawWorld(Renderer2D& r, const game::Match& match, ScreenLayout* layout = nullptr);
    /// The legend's lines: each path's name, its landing error against the reference and
    /// its cost, force evaluations per step ("explicit-euler  0.691 m  1 eval/step").
    std::vector<std::string> legendLines() const;

    /// Relative change of the energy over the last `seconds` of samples (fewer when the
    /// match is younger), e.g. +0.04 for 4 % gained; none before two samples or at zero
    /// energy. Shown by the Physics panel: explicit Euler gaining energy on springs.
    std::optional<double> energyTrend(double seconds) const;

    /// The charts are drawn over the view (open, and the panel not folded).
    bool chartsShown() const { return charts_.open && expanded_; }

    bool showCompare = false; ///< draw the compare paths and their legend
    double historySeconds = 20.0; ///< how much of the energy plot is kept, s

  private:
    void runCompare(const game::Match& match, const PendingAim& aim);
    /// The legend, where it covers nothing; returns where (none: left out).
    std::optional<PixelRect> drawLegend(Renderer2D& r, ScreenLayout* layout) const;
    /// The shot's work-precision chart beside the legend at `legend`, where it covers
    /// nothing, as the overlay "compare.chart".
    void drawWorkChart(Renderer2D& r, const PixelRect& legend, ScreenLayout* layout) const;

    // Ring buffer of samples, at most historySeconds / tick of them.
    std::vector<float> energy_, momentum_;
    std::size_t next_ = 0, count_ = 0;
    double lastTime_ = -1.0;
    double firstEnergy_ = 0.0;
    double tick_ = 0.0; ///< s, the tick of the samples
    ConservedSample last_;

    std::vector<game::IntegratorPath> paths_;
    game::ShotWork work_; ///< the compared shot's work-precision (game/compare_work.h)
    bool followAim_ = true;
    struct Key {
        double angle = 0, speed = 0, tick = 0, wind = 0;
        int integrators = 0, projectile = -1, drag = -1;
        bool operator==(const Key&) const = default;
    } key_;

    charts::ChartsPanelState charts_;
    bool expanded_ = false; ///< the Stats window was open (not folded) this frame
};

} // namespace ui
