#include "ui/charts/bench_verb.h"

#include "game/cli/bench.h"
#include "ui/charts/bench_charts.h"
#include "ui/charts/chart_png.h"

namespace ui {

namespace {

// Picture sizes: wide enough for three panels side by side with readable labels.
constexpr int kWidth = 1800;

game::cli::BenchPlots chartPlots() {
    using namespace charts;
    game::cli::BenchPlots p;
    p.workPrecision = [](const std::vector<game::bench::WorkPrecisionPoint>& points,
                         const std::string& path) {
        const bool one = workPrecisionCharts(points).size() <= 1;
        return renderChartPng(path, one ? 1200 : kWidth, one ? 620 : 1080,
                              [&](Renderer2D& r, Rect area) { drawWorkPrecision(r, area, points); });
    };
    p.stability = [](const game::cli::StabilityReport& report, const std::string& path) {
        return renderChartPng(path, 1500, 1080, [&](Renderer2D& r, Rect area) {
            drawStability(r, area, report.rows, report.curves);
        });
    };
    p.scaling = [](const game::bench::ScalingReport& report, const std::string& path) {
        return renderChartPng(path, kWidth, 620,
                              [&](Renderer2D& r, Rect area) { drawScaling(r, area, report); });
    };
    return p;
}

int runBenchVerb(const game::cli::Args& args, std::ostream& out) {
    static const game::cli::BenchPlots plots = chartPlots();
    return game::cli::runBench(args, out, &plots);
}

} // namespace

const game::cli::Verb& benchVerb() {
    static const game::cli::Verb verb{"bench", "speed against accuracy, stability, scaling; CSV + PNG",
                                      game::cli::kBenchUsage, game::cli::benchFlags(), runBenchVerb};
    return verb;
}

} // namespace ui
