// Charts: ticks and the data-to-pixel mapping are right, and a chart rendered headless
// has its axes, its line and its markers exactly where the mapping says.
#include "ui/charts/bench_charts.h"
#include "ui/charts/chart.h"
#include "ui/charts/chart_png.h"
#include "ui/charts/charts_panel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace {

using namespace ui::charts;
using phys::Color;
using phys::Vec2;

struct Rgb {
    int r, g, b;
};
Rgb at(const ui::Image& img, Vec2 px) {
    const auto* p = img.pixel(static_cast<int>(px.x), static_cast<int>(px.y));
    return {p[0], p[1], p[2]};
}
Rgb rgb(Color c) {
    return {static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)),
            static_cast<int>(std::lround(c.b * 255))};
}
bool near(Rgb a, Rgb b, int tol = 12) {
    return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol;
}
/// True when some pixel within `radius` of px has colour c (lines are anti-aliased and
/// a pixel centre may sit on an edge).
bool colourNear(const ui::Image& img, Vec2 px, Rgb c, int radius = 1, int tol = 12) {
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx)
            if (near(at(img, {px.x + dx, px.y + dy}), c, tol)) return true;
    return false;
}

const Color kRed = Color::hex(0xff2020);

Chart lineChart() {
    Chart c;
    c.title = "test";
    c.x = {"x", Scale::Log, 1.0, 1000.0};
    c.y = {"y", Scale::Log, 1e-3, 1.0};
    c.legend = false;
    Series s;
    s.name = "line";
    s.color = kRed;
    s.marker = Marker::Square;
    s.widthPx = 3.0f;
    // From (1, 1e-3) to (1000, 1): a straight diagonal on log-log axes.
    s.points = {{1.0, 1e-3}, {1000.0, 1.0}};
    c.series.push_back(s);
    return c;
}

} // namespace

TEST(ChartTicks, LogAxesTickEveryDecadeAndLinearOnesOnNiceSteps) {
    const auto t = ticks(1e-3, 1e2, Scale::Log);
    ASSERT_EQ(t.size(), 6u);
    EXPECT_DOUBLE_EQ(t.front(), 1e-3);
    EXPECT_DOUBLE_EQ(t.back(), 1e2);
    // 20 decades: every third one so labels do not collide.
    EXPECT_EQ(ticks(1e-16, 1e4, Scale::Log).size(), 7u);
    const auto l = ticks(0.0, 10.0, Scale::Linear);
    ASSERT_EQ(l.size(), 6u);
    EXPECT_DOUBLE_EQ(l[1], 2.0);
    EXPECT_EQ(tickLabel(1e-2, Scale::Log), "0.01");
    EXPECT_EQ(tickLabel(1e-6, Scale::Log), "1e-6");
    EXPECT_EQ(tickLabel(2.5, Scale::Linear), "2.5");
}

TEST(ChartMapping, LogAxesMapDecadesToEqualSteps) {
    const ChartMapping m = layoutChart(lineChart(), {0, 0, 800, 600});
    // Corners of the data range are the corners of the plot (y down in pixels).
    EXPECT_NEAR(m.xPixel(1.0), m.plot.x, 1e-9);
    EXPECT_NEAR(m.xPixel(1000.0), m.plot.x + m.plot.w, 1e-9);
    EXPECT_NEAR(m.yPixel(1e-3), m.plot.y + m.plot.h, 1e-9);
    EXPECT_NEAR(m.yPixel(1.0), m.plot.y, 1e-9);
    // 10 is a third of the way along three decades.
    EXPECT_NEAR(m.xPixel(10.0), m.plot.x + m.plot.w / 3.0, 1e-9);
    // Auto ranges widen to whole decades around the data.
    Chart c = lineChart();
    c.x.min = c.x.max = c.y.min = c.y.max = NAN;
    c.series[0].points = {{3.0, 0.002}, {420.0, 0.5}};
    const ChartMapping a = layoutChart(c, {0, 0, 800, 600});
    EXPECT_DOUBLE_EQ(a.xMin, 1.0);
    EXPECT_DOUBLE_EQ(a.xMax, 1000.0);
    EXPECT_NEAR(a.yMin, 1e-3, 1e-18);
    EXPECT_DOUBLE_EQ(a.yMax, 1.0);
}

TEST(ChartRender, AxesLineAndMarkersLandWhereTheMappingSays) {
    const Chart chart = lineChart();
    const ChartStyle style;
    const Rect area{0, 0, 640, 480};
    std::string error;
    ChartMapping m;
    const ui::Image img = renderChartImage(
        640, 480, [&](ui::Renderer2D& r, Rect a) { m = drawChart(r, chart, a, style); }, error);
    ASSERT_EQ(error, "") << "headless GL (OSMesa, else EGL) must work here";
    ASSERT_EQ(img.width, 640);
    EXPECT_EQ(m.plot.x, layoutChart(chart, area).plot.x);

    // Axes: the x axis runs along the bottom of the plot, the y axis up its left side,
    // in the axis colour (away from the line and the tick marks).
    const Rgb axis = rgb(style.axis);
    EXPECT_TRUE(colourNear(img, {m.plot.x + 0.62 * m.plot.w, m.plot.y + m.plot.h}, axis));
    EXPECT_TRUE(colourNear(img, {m.plot.x, m.plot.y + 0.55 * m.plot.h}, axis));
    // Left of the y tick labels, the chart background; inside the plot, away from the
    // line, grid and labels, the plot fill.
    EXPECT_TRUE(near(at(img, {4.0, m.plot.y + 0.5 * m.plot.h}), rgb(style.background), 4));
    EXPECT_TRUE(near(at(img, {m.plot.x + 0.8 * m.plot.w + 3, m.plot.y + 0.72 * m.plot.h + 3}),
                     rgb(style.plot), 4));

    // The line: red on the diagonal at data points the mapping places, e.g. (10, 0.01)
    // and (31.6, 0.0316), and not red a little off it.
    for (double x : {10.0, 31.6227766, 100.0}) {
        const Vec2 p = m.toPixel({x, x * 1e-3});
        EXPECT_TRUE(colourNear(img, p, rgb(kRed))) << "line missing at x = " << x;
        EXPECT_FALSE(colourNear(img, p + Vec2{0.0, 12.0}, rgb(kRed), 1, 60))
            << "red below the line at x = " << x;
    }
    // A square marker at the lower-left end: red 2 px off the point in both directions
    // (a bare 3 px line would not cover that corner).
    const Vec2 end = m.toPixel({1.0, 1e-3});
    EXPECT_TRUE(colourNear(img, end + Vec2{2.0, -2.0}, rgb(kRed), 0, 30));
}

TEST(ChartRender, PointsOutsideTheRangeAreClippedToThePlot) {
    Chart chart = lineChart();
    chart.series[0].points = {{10.0, 1e-2}, {1e6, 1e4}}; // leaves through the top right
    std::string error;
    ChartMapping m;
    const ui::Image img = renderChartImage(
        400, 300, [&](ui::Renderer2D& r, Rect a) { m = drawChart(r, chart, a); }, error);
    ASSERT_EQ(error, "");
    int redOutside = 0, redInside = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const auto* p = img.pixel(x, y);
            if (!(p[0] > 200 && p[1] < 80 && p[2] < 80)) continue;
            const bool in = x >= m.plot.x - 2 && x <= m.plot.x + m.plot.w + 2 &&
                            y >= m.plot.y - 2 && y <= m.plot.y + m.plot.h + 2;
            (in ? redInside : redOutside)++;
        }
    EXPECT_GT(redInside, 50);
    EXPECT_EQ(redOutside, 0);
}

TEST(BenchCharts, WorkPrecisionDrawsOneChartPerSceneWithALinePerIntegrator) {
    using game::bench::AccuracyScene;
    std::vector<game::bench::WorkPrecisionPoint> pts;
    for (const auto& m : phys::integrators())
        for (double dt : {0.01, 0.005}) {
            pts.push_back({AccuracyScene::Spring, m.id, dt, 0, dt * dt, 1.0 / dt, 0});
            pts.push_back({AccuracyScene::Orbit, m.id, dt, 0, INFINITY, 1.0 / dt, 0});
        }
    const auto charts = workPrecisionCharts(pts);
    ASSERT_EQ(charts.size(), 2u);
    EXPECT_EQ(charts[0].title, "spring");
    EXPECT_EQ(charts[0].series.size(), phys::integrators().size());
    // Sorted by cost, so the line runs from big dt (cheap, left) to small dt.
    EXPECT_LT(charts[0].series[0].points[0].x, charts[0].series[0].points[1].x);
    // Blown-up runs are kept (drawn off the top) and the axis stops at 100 m.
    EXPECT_EQ(charts[1].y.max, 1e2);
}

// In a panel too narrow for three charts side by side (the in-game one is some 850 px
// wide), the scaling view puts the line charts on top and the bars below, beside the
// workloads' legend: the Box2D bar gets a real length, not the sliver of a third column
// whose labels take its width.
TEST(BenchCharts, ScalingInANarrowPanelGivesTheBarsTheLowerLeftAndTheLegendTheLowerRight) {
    game::bench::ScalingReport report;
    for (const char* w : {"flight", "pile", "box2d", "box2d-tuned"})
        for (long n : {250L, 1000L, 4000L})
            report.points.push_back({w, n, 0.4 * n, 400.0, 0.5});
    report.pile.balls = 1000;
    report.pile.particleMs = 0.3, report.pile.rigidMs = 1.5, report.pile.tunedRigidMs = 1.0;
    report.clothMs = 0.6;
    const int w = 845, h = 396;
    std::string error;
    const ui::Image img = renderChartImage(
        w, h, [&](ui::Renderer2D& r, Rect a) { drawScaling(r, a, report); }, error);
    ASSERT_EQ(error, "");
    // The longest run of a colour along a row, within x0..x1 and the lower part (bars are
    // drawn a little translucent, so within 40 of it).
    auto longestRun = [&](Rgb c, int x0, int x1) {
        int best = 0;
        for (int y = static_cast<int>(0.56 * h); y < h; ++y)
            for (int x = x0, run = 0; x < x1; ++x) {
                run = near(at(img, {double(x), double(y)}), c, 40) ? run + 1 : 0;
                best = std::max(best, run);
            }
        return best;
    };
    const Rgb box2d = rgb(Color::hex(0xff6b6b)), tuned = rgb(Color::hex(0xc678dd));
    EXPECT_GT(longestRun(box2d, 0, w / 2), 60) << "the Box2D bar, lower left";
    EXPECT_GT(longestRun(tuned, w / 2, w), 10) << "the legend's line, lower right";
    EXPECT_LT(longestRun(tuned, w / 2, w), 60) << "and no bar there";
}

// Scaling figures move with the machine and its load, so the charts' title says both:
// after what they show where a line has room, in place of it in the in-game panel; a run
// marked as taken under load says so instead of the bare load.
TEST(BenchCharts, ScalingTitleNamesTheMachineAndTheLoad) {
    game::bench::ScalingReport report;
    report.machine = "Intel(R) Xeon(R) Processor @ 2.50GHz, 2 logical CPUs, AVX2 lanes";
    report.loadAtStart = 0.42;
    EXPECT_EQ(scalingTitle(report, false),
              "Scaling: step cost against the size of the scene (Intel(R) Xeon(R) Processor @ "
              "2.50GHz, 2 logical CPUs, AVX2 lanes, load 0.42)");
    EXPECT_EQ(scalingTitle(report, true),
              "Scaling on Intel(R) Xeon(R) Processor @ 2.50GHz, 2 logical CPUs, AVX2 lanes, load "
              "0.42");
    report.underLoad = true;
    report.loadAtStart = 1.37;
    EXPECT_EQ(scalingTitle(report, true), "Scaling on Intel(R) Xeon(R) Processor @ 2.50GHz, 2 "
                                          "logical CPUs, AVX2 lanes, taken under load 1.37");
    report.loadAtStart = NAN;
    report.machine.clear();
    EXPECT_EQ(scalingTitle(report, false),
              "Scaling: step cost against the size of the scene (taken under load)");
    report.underLoad = false;
    EXPECT_EQ(scalingTitle(report, true), "Scaling: step cost against the size of the scene")
        << "nothing known, nothing said";
}

// The in-game charts keep clear of a panel open over their left side (the sandbox's
// tools): they start a gap right of it and keep their right edge; a panel elsewhere, or
// one that would leave them under half their width, leaves them as they are.
TEST(ChartsArea, StartsRightOfAPanelOpenOverItsLeftSide) {
    const Rect area = chartsArea(1280, 720, 150);
    EXPECT_DOUBLE_EQ(area.y, 150.0);
    EXPECT_LE(area.y + area.h, 0.70 * 720 + 1e-9) << "above the panels at the bottom";
    const Rect beside = rightOf(area, {12.0, 120.0, 348.0, 306.0}, 12.0);
    EXPECT_DOUBLE_EQ(beside.x, 360.0);
    EXPECT_DOUBLE_EQ(beside.x + beside.w, area.x + area.w);
    EXPECT_DOUBLE_EQ(beside.y, area.y);
    EXPECT_DOUBLE_EQ(beside.h, area.h);
    const Rect below = rightOf(area, {12.0, 600.0, 348.0, 700.0}, 12.0);
    EXPECT_DOUBLE_EQ(below.x, area.x) << "no overlap";
    const Rect wide = rightOf(area, {12.0, 120.0, 700.0, 306.0}, 12.0);
    EXPECT_DOUBLE_EQ(wide.x, area.x) << "it would leave under half";
}
