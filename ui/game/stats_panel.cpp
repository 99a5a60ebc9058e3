#include "ui/game/stats_panel.h"

#include "ui/game/compare_chart.h"
#include "ui/game/level_camera.h"
#include "ui/platform/imgui_layer.h"
#include "ui/render/design_canvas.h"

#include "physics/diagnostics.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cfloat>
#include <cstdio>

namespace ui {

namespace {

ImVec4 imColor(Color c) { return ImVec4(c.r, c.g, c.b, c.a); }

/// The work-precision chart's size at full text size, px.
constexpr double kChartW = 340.0, kChartH = 210.0;

/// The first of `places` clear on `layout` (added to it as `name`); without a layout, the
/// first place.
std::optional<PixelRect> placeOverlay(ScreenLayout* layout, const char* name,
                                      const std::vector<PixelRect>& places) {
    return layout ? layout->placeOverlay(name, places) : std::optional(places.front());
}

/// One row of the legend in its three columns: the path, its landing error, its cost.
std::array<std::string, 3> legendRow(const game::IntegratorPath& p) {
    if (p.isReference) return {p.name + " (reference)", "", ""};
    char error[32] = "not down", cost[32];
    if (p.landed) std::snprintf(error, sizeof error, "%.3g m", p.landingError);
    std::snprintf(cost, sizeof cost, "%d eval/step", phys::info(p.integrator).evaluations);
    return {p.name, error, cost};
}

} // namespace

ConservedSample conservedQuantities(const game::Match& match) {
    const phys::World& w = match.world();
    ConservedSample s;
    s.time = match.time();
    s.energy = phys::energy(w.particles, w.springs, w.def().forces).total();
    const phys::Vec2 p = phys::momentum(w.particles);
    s.momentumX = p.x;
    s.momentumY = p.y;
    // Box2D bodies: 1/2 m v^2 + 1/2 I w^2 - m g.c, and m v.
    const phys::RigidWorld& rigid = match.rigid();
    const phys::Vec2 g = w.def().forces.gravity;
    for (const phys::BodyId id : rigid.bodies()) {
        const phys::RigidBodyState b = rigid.state(id);
        if (b.type != phys::BodyType::Dynamic) continue;
        s.energy += 0.5 * b.mass * phys::dot(b.linearVelocity, b.linearVelocity) +
                    0.5 * b.inertia * b.angularVelocity * b.angularVelocity -
                    b.mass * phys::dot(g, b.centerOfMass);
        s.momentumX += b.mass * b.linearVelocity.x;
        s.momentumY += b.mass * b.linearVelocity.y;
    }
    return s;
}

void StatsPanel::sample(const game::Match& match) {
    const double dt = match.world().def().tickSeconds;
    const auto capacity = static_cast<std::size_t>(std::clamp(historySeconds / dt, 2.0, 1e6));
    if (match.time() <= lastTime_ || energy_.size() != capacity) {
        // A new match, a rewind or a new tick length: start the plot afresh.
        energy_.assign(capacity, 0.0f);
        momentum_.assign(capacity, 0.0f);
        next_ = count_ = 0;
        firstEnergy_ = conservedQuantities(match).energy;
    }
    last_ = conservedQuantities(match);
    lastTime_ = match.time();
    tick_ = dt;
    energy_[next_] = static_cast<float>(last_.energy);
    momentum_[next_] = static_cast<float>(std::hypot(last_.momentumX, last_.momentumY));
    next_ = (next_ + 1) % energy_.size();
    count_ = std::min(count_ + 1, energy_.size());
}

std::optional<double> StatsPanel::energyTrend(double seconds) const {
    if (count_ < 2 || !(tick_ > 0.0)) return std::nullopt;
    const auto back = std::min(count_ - 1, static_cast<std::size_t>(std::lround(seconds / tick_)));
    const std::size_t cap = energy_.size();
    const double now = energy_[(next_ + cap - 1) % cap];
    const double then = energy_[(next_ + cap - 1 - back) % cap];
    if (then == 0.0) return std::nullopt;
    return (now - then) / std::abs(then);
}

void StatsPanel::runCompare(const game::Match& match, const PendingAim& aim) {
    paths_ = game::compareIntegrators(match, aim.angleDeg, aim.speedMps);
    work_ = game::shotWorkPrecision(match, aim.angleDeg, aim.speedMps);
    const phys::WorldDef& d = match.world().def();
    key_ = {aim.angleDeg, aim.speedMps, d.tickSeconds, match.wind(),
            static_cast<int>(phys::integrators().size()),
            static_cast<int>(match.cannon().projectile), static_cast<int>(d.forces.drag)};
}

std::optional<PixelRect> StatsPanel::drawLegend(Renderer2D& r, ScreenLayout* layout) const {
    // The legend, in pixels: under the wind box in the middle, else the top corners under
    // the HUD's band, else the bottom right; wherever it covers nothing on screen.
    const std::size_t lines = paths_.size();
    const double W = r.camera().width, H = r.camera().height, u = hudScale(W, H);
    const double w = 340.0 * u, h = (16.0 * static_cast<double>(lines) + 8.0) * u, m = 12.0 * u;
    const double top = kHudTopBand * u;
    const std::vector<PixelRect> places = {{0.5 * (W - w), top, 0.5 * (W + w), top + h},
                                           {m, top, m + w, top + h},
                                           {W - m - w, top, W - m, top + h},
                                           {W - m - w, H - m - h - 100.0 * u, W - m, H - m - 100.0 * u}};
    const auto placed = placeOverlay(layout, "compare.legend", places);
    if (!placed) return std::nullopt; // nowhere clear: the paths speak for themselves
    const PixelRect at = *placed;
    const double columns[3] = {4.0, 140.0, 245.0}; // design px: path, error, cost
    double y = at.y0 + 4.0 * u;
    for (const game::IntegratorPath& p : paths_) {
        const auto row = legendRow(p);
        for (std::size_t c = 0; c < 3; ++c)
            r.screenLabel({at.x0 + columns[c] * u, y}, row[c], compareColor(p),
                          static_cast<float>(u));
        y += 16.0 * u;
    }
    return at;
}

void StatsPanel::drawWorkChart(Renderer2D& r, const PixelRect& legend, ScreenLayout* layout) const {
    // Beside the legend: under it, at its left, at its right, above it; else in a corner
    // under the HUD's band; wherever it covers nothing. The chart's text is of a fixed
    // size (charts::ChartStyle), so it is first tried at no less than its full size, then
    // (on a small screen) at the HUD's scale with its text scaled alike.
    const double W = r.camera().width, H = r.camera().height, u = hudScale(W, H);
    const double g = 8.0 * u, m = 12.0 * u, top = kHudTopBand * u;
    std::vector<PixelRect> places;
    for (const double k : {std::max(u, 1.0), std::min(u, 1.0)}) {
        const double w = kChartW * k, h = kChartH * k;
        places.insert(places.end(),
                      {{legend.x0, legend.y1 + g, legend.x0 + w, legend.y1 + g + h},
                       {legend.x0 - g - w, legend.y0, legend.x0 - g, legend.y0 + h},
                       {legend.x1 + g, legend.y0, legend.x1 + g + w, legend.y0 + h},
                       {legend.x0, legend.y0 - g - h, legend.x0 + w, legend.y0 - g},
                       {m, top, m + w, top + h},
                       {W - m - w, top, W - m, top + h},
                       {W - m - w, H - m - h - 100.0 * u, W - m, H - m - 100.0 * u}});
    }
    const auto at = placeOverlay(layout, "compare.chart", places);
    if (!at) return; // nowhere clear: the legend's errors say it in numbers
    charts::ChartStyle style;
    style.textScale *= static_cast<float>(std::min(1.0, (at->x1 - at->x0) / kChartW));
    charts::drawChart(r, shotWorkChart(work_), {at->x0, at->y0, at->x1 - at->x0, at->y1 - at->y0},
                      style);
}

std::optional<phys::WorldDef> StatsPanel::panel(const game::Match& match, const PendingAim& aim) {
    std::optional<phys::WorldDef> apply;
    // Right, under the Physics window's title bar (the HUD holds the top left).
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
    const float top = topRightPanelsTop(display.x, display.y, panelPx(380), panelPx(10));
    ImGui::SetNextWindowPos(ImVec2(display.x - panelPx(342), top + panelPx(34)),
                            ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(panelPx(330), panelPx(600)), ImGuiCond_FirstUseEver);
    expanded_ = ImGui::Begin("Stats", nullptr, ImGuiWindowFlags_NoFocusOnAppearing);
    if (expanded_) {
        // --- Compare ------------------------------------------------------------------
        if (ImGui::CollapsingHeader("Compare integrators", ImGuiTreeNodeFlags_DefaultOpen)) {
            if (ImGui::Button(showCompare ? "Hide paths" : "Compare")) {
                showCompare = !showCompare;
                if (showCompare) runCompare(match, aim);
            }
            ImGui::SameLine();
            ImGui::Checkbox("follow the aim", &followAim_);
            if (!paths_.empty()) {
                const game::IntegratorPath& ref = paths_.back();
                ImGui::TextDisabled("landing error vs %s, tick %.4g s", ref.name.c_str(),
                                    match.world().def().tickSeconds);
                for (const game::IntegratorPath& p : paths_) {
                    ImGui::TextColored(imColor(compareColor(p)), "%-18s", p.name.c_str());
                    ImGui::SameLine(panelPx(160));
                    if (p.isReference)
                        ImGui::Text(p.landed ? "lands x = %.2f m" : "no landing", p.landing.x);
                    else if (p.landed)
                        ImGui::Text("%.3g m", p.landingError);
                    else
                        ImGui::TextDisabled("not down in %.0f s", game::kMaxFlightSeconds);
                }
            }
        }
        // --- Energy and momentum ---------------------------------------------------
        if (ImGui::CollapsingHeader("Energy and momentum", ImGuiTreeNodeFlags_DefaultOpen) &&
            count_ > 0) {
            // The ring buffer, oldest first: PlotLines starts at values_offset.
            const int n = static_cast<int>(count_);
            // The plots span the panel (a negative width, "up to the right edge less 1",
            // came out 4 px wide here).
            const ImVec2 plotSize(ImGui::GetContentRegionAvail().x, panelPx(70));
            const int offset = count_ < energy_.size() ? 0 : static_cast<int>(next_);
            const double drift = firstEnergy_ != 0.0 ? (last_.energy - firstEnergy_) / std::abs(firstEnergy_) : 0.0;
            char overlay[64];
            std::snprintf(overlay, sizeof overlay, "E = %.4g J (%+.2e)", last_.energy, drift);
            ImGui::PlotLines("##energy", energy_.data(), n, offset, overlay, FLT_MAX, FLT_MAX,
                             plotSize);
            std::snprintf(overlay, sizeof overlay, "|p| = %.4g kg m/s", std::hypot(last_.momentumX, last_.momentumY));
            ImGui::PlotLines("##momentum", momentum_.data(), n, offset, overlay, FLT_MAX, FLT_MAX,
                             plotSize);
            ImGui::TextDisabled("last %.0f s; particles, springs and Box2D bodies", historySeconds);
        }
        // --- Charts ----------------------------------------------------------------
        if (ImGui::Button(charts_.open ? "Close charts"
                                       : "Charts (work-precision, stability, scaling)"))
            charts_.open = !charts_.open;
        if (charts_.open) {
            ImGui::Separator();
            const charts::ChartsPanelRequests req = charts::chartsControls(charts_);
            if (req.applyChoice && charts_.choice) {
                phys::WorldDef d = match.world().def();
                d.integrator = charts_.choice->integrator;
                d.substeps = charts_.choice->substepsPerTick(d.tickSeconds);
                apply = d;
            }
        }
    }
    ImGui::End();

    followAim(match, aim);
    return apply;
}

void StatsPanel::followAim(const game::Match& match, const PendingAim& aim) {
    // Recompute when what the paths depend on has changed.
    if (!showCompare || !followAim_) return;
    const phys::WorldDef& d = match.world().def();
    const Key now{aim.angleDeg, aim.speedMps, d.tickSeconds, match.wind(),
                  static_cast<int>(phys::integrators().size()),
                  static_cast<int>(match.cannon().projectile), static_cast<int>(d.forces.drag)};
    if (!(now == key_)) runCompare(match, aim);
}

void StatsPanel::toggleCompare(const game::Match& match, const PendingAim& aim) {
    showCompare = !showCompare;
    if (showCompare) runCompare(match, aim);
}

std::vector<std::string> StatsPanel::legendLines() const {
    std::vector<std::string> out;
    for (const game::IntegratorPath& p : paths_) {
        const auto row = legendRow(p);
        out.push_back(row[1].empty() ? row[0] : row[0] + "  " + row[1] + "  " + row[2]);
    }
    return out;
}

void StatsPanel::drawWorld(Renderer2D& r, const game::Match& match, ScreenLayout* layout) {
    (void)match;
    if (showCompare) {
        for (const game::IntegratorPath& p : paths_) {
            const Color c = compareColor(p);
            r.polyline(p.points, c, p.isReference ? 1.5f : 2.0f);
            if (p.landed) r.fillCircle(p.landing, 0.0, c, 4.0f);
        }
        if (const auto legend = drawLegend(r, layout)) drawWorkChart(r, *legend, layout);
    }
    if (chartsShown()) { // folding the panel folds away its charts too
        // The charts (chartsArea) map pixels (chart.h), so they are drawn through a camera
        // whose units are pixels; the match's labels are kept and the match's camera
        // restored after.
        r.flush();
        const Camera world = r.camera();
        std::vector<Label> labels = r.labels();
        const double w = world.width, h = world.height;
        r.begin(Camera::framing({0.0, 0.0}, {w, h}, world.width, world.height));
        // Below the level's heading and the Sandbox panel's header under it, and right of
        // that panel while it is open beside them (the sandbox's tools).
        const double top = belowLevelHeading(w, h) + 30.0 * hudScale(w, h);
        charts::Rect area = charts::chartsArea(w, h, top);
        if (const auto tools = openWindowRect("Sandbox"))
            area = charts::rightOf(area, *tools, 12.0 * hudScale(w, h));
        charts::drawChartsPanel(r, charts_, area);
        r.flush();
        labels.insert(labels.end(), r.labels().begin(), r.labels().end());
        r.begin(world);
        for (const Label& l : labels)
            r.label(world.toWorld(l.pixel), l.text, l.color, {}, l.scale, l.alignX);
    }
}

} // namespace ui
