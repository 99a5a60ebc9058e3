#include "ui/charts/charts_panel.h"

#include "game/bench/machine.h"
#include "ui/charts/bench_charts.h"

#include <imgui.h>

#include <cmath>
#include <string>

namespace ui::charts {

using namespace game::bench;

namespace {

/// The live sweep: fewer halvings and one repeat, so a click costs about a second.
WorkPrecisionDef liveSweep(AccuracyScene scene) {
    WorkPrecisionDef d = choiceSweep(scene);
    if (scene == AccuracyScene::Cloth || scene == AccuracyScene::PendulumRods) d.largestDt = 0.02;
    d.halvings = 5;
    d.repeats = 1;
    return d;
}

bool hasData(const ChartsPanelState& s) {
    switch (s.view) {
    case ChartsView::WorkPrecision:
        return !s.points.empty() && s.points.front().scene == s.scene;
    case ChartsView::Stability: return !s.stability.empty();
    case ChartsView::Scaling: return !s.scaling.points.empty();
    }
    return false;
}

// The scene of the work-precision chart and of the search for the cheapest method.
void sceneCombo(ChartsPanelState& s) {
    const auto scenes = accuracyScenes();
    int scene = 0;
    for (std::size_t i = 0; i < scenes.size(); ++i)
        if (scenes[i].id == s.scene) scene = static_cast<int>(i);
    if (ImGui::BeginCombo("scene", scenes[scene].name)) {
        for (std::size_t i = 0; i < scenes.size(); ++i)
            if (ImGui::Selectable(scenes[i].name, static_cast<int>(i) == scene)) {
                s.scene = scenes[i].id;
                s.choice.reset();
                s.choiceSearched = false;
            }
        ImGui::EndCombo();
    }
}

} // namespace

void measure(ChartsPanelState& s) {
    switch (s.view) {
    case ChartsView::WorkPrecision: s.points = runWorkPrecision(liveSweep(s.scene)); break;
    case ChartsView::Stability:
        s.stability = runStability();
        s.growth = energyGrowthCurves(1e-2, 10.0, 13);
        break;
    case ChartsView::Scaling: {
        // Where and under what load: the heading says so (bench_charts.h), as the bench's
        // chart does, for figures that move with both.
        s.scaling.loadAtStart = loadNow();
        s.scaling.machine = thisMachine().describe();
        ScalingDef d;
        d.sizes = {1000, 4000, 16000};
        d.steps = 5;
        d.repeats = 1;
        ScalingDef piles = d;
        piles.sizes = {250, 500, 1000};
        s.scaling.points = measureScaling("flight", flightWorkload, d);
        for (auto* w : {&clothWorkload}) {
            auto p = measureScaling("cloth", *w, d);
            s.scaling.points.insert(s.scaling.points.end(), p.begin(), p.end());
        }
        auto p = measureScaling("pile", pileWorkload, piles);
        s.scaling.points.insert(s.scaling.points.end(), p.begin(), p.end());
        p = measureScaling("box2d", rigidPileWorkload, piles);
        s.scaling.points.insert(s.scaling.points.end(), p.begin(), p.end());
        p = measureScaling("box2d-tuned", tunedRigidPileWorkload, piles);
        s.scaling.points.insert(s.scaling.points.end(), p.begin(), p.end());
        s.scaling.pile = comparePiles(1000, 10, 1);
        s.scaling.clothMs = clothFrameMs(64, 5);
        break;
    }
    }
}

void choose(ChartsPanelState& s) {
    if (s.points.empty() || s.points.front().scene != s.scene)
        s.points = runWorkPrecision(liveSweep(s.scene));
    s.choice = chooseCheapest(s.scene, s.tolerance, s.points);
    s.choiceSearched = true;
}

ChartsPanelRequests chartsControls(ChartsPanelState& s) {
    ChartsPanelRequests req;
    if (!s.open) return req;
    const char* views[] = {"work-precision", "stability", "scaling"};
    int view = static_cast<int>(s.view);
    if (ImGui::Combo("chart", &view, views, 3)) s.view = static_cast<ChartsView>(view);
    // The stability and scaling charts have no scene: there the scene belongs to the
    // search below alone, so it sits with it.
    const bool chartHasScene = s.view == ChartsView::WorkPrecision;
    if (chartHasScene) sceneCombo(s);
    if (ImGui::Button(hasData(s) ? "Measure again" : "Measure")) measure(s);
    ImGui::Separator();
    ImGui::TextUnformatted("Accurate enough, fastest");
    if (!chartHasScene) sceneCombo(s);
    float logTol = static_cast<float>(std::log10(s.tolerance));
    if (ImGui::SliderFloat("tolerance", &logTol, -9.0f, 0.0f, "1e%.1f m")) {
        s.tolerance = std::pow(10.0, static_cast<double>(logTol));
        s.choiceSearched = false;
    }
    if (ImGui::Button("Find cheapest")) choose(s);
    if (s.choice) {
        const auto& c = *s.choice;
        // Wrapped: the controls sit in the Stats panel, about 330 px wide.
        const int substeps = c.substepsPerTick(1.0 / 120.0);
        ImGui::TextWrapped("%s, dt %.3g s (%d sub-step%s at 120 Hz)", phys::info(c.integrator).name,
                           c.dt, substeps, substeps == 1 ? "" : "s");
        ImGui::TextWrapped("measured error %.3g m, %.3g ms CPU per sim s", c.error,
                           1e3 * c.cpuSecondsPerSimSecond);
        req.applyChoice = ImGui::Button("Use it");
    } else if (s.choiceSearched) {
        ImGui::TextWrapped("No integrator and dt of the sweep is within 1e%.1f m.", logTol);
    }
    return req;
}

void drawChartsPanel(Renderer2D& r, const ChartsPanelState& s, Rect area) {
    if (!s.open) return;
    switch (s.view) {
    case ChartsView::WorkPrecision: {
        std::vector<WorkPrecisionPoint> mine;
        for (const auto& p : s.points)
            if (p.scene == s.scene) mine.push_back(p);
        auto charts = workPrecisionCharts(mine);
        for (auto& c : charts) c.legend = true;
        if (charts.empty()) {
            Chart empty;
            empty.title = std::string(info(s.scene).name) + ": not measured yet (Measure)";
            empty.x = {"CPU seconds per simulated second", Scale::Log};
            empty.y = {"error, m", Scale::Log};
            charts.push_back(empty);
        }
        if (s.choice && s.choice->scene == s.scene && !charts.empty()) {
            Series pick;
            pick.name = "accurate enough, fastest";
            pick.color = Color::hex(0xffffff);
            pick.marker = Marker::Diamond;
            pick.line = false;
            pick.points = {{s.choice->cpuSecondsPerSimSecond, s.choice->error}};
            charts.front().series.push_back(pick);
            charts.front().marks.push_back({s.tolerance, false, "tolerance", Color::hex(0xffffff, 0.6f)});
        }
        drawChart(r, charts.front(), area);
        break;
    }
    case ChartsView::Stability: drawStability(r, area, s.stability, s.growth); break;
    case ChartsView::Scaling: drawScaling(r, area, s.scaling); break;
    }
}

} // namespace ui::charts
