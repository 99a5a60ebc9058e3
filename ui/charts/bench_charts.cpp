#include "ui/charts/bench_charts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <span>

namespace ui::charts {

using game::bench::AccuracyScene;
using phys::Integrator;

namespace {

std::string format(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

/// Colours for the scaling workloads, by name.
Color workloadColor(const std::string& name) {
    if (name == "flight") return Color::hex(0x4aa3ff);
    if (name == "pile") return Color::hex(0xf0b429);
    if (name == "cloth") return Color::hex(0x57c46a);
    if (name == "box2d") return Color::hex(0xff6b6b);
    if (name == "box2d-tuned") return Color::hex(0xc678dd);
    return Color::hex(0xb0b7c3);
}

Marker workloadMarker(const std::string& name) {
    if (name == "flight") return Marker::Circle;
    if (name == "pile") return Marker::Square;
    if (name == "cloth") return Marker::Triangle;
    return Marker::Diamond;
}

std::string workloadName(const std::string& name) {
    if (name == "flight") return "particles in flight";
    if (name == "pile") return "particle pile (contacts)";
    if (name == "cloth") return "cloth springs (8 sub-steps)";
    if (name == "box2d") return "Box2D circles pile";
    if (name == "box2d-tuned") return "Box2D pile at its tuned size";
    return name;
}

} // namespace

Color integratorColor(Integrator m) {
    switch (m) {
    case Integrator::ExplicitEuler: return Color::hex(0xe5534b);
    case Integrator::SymplecticEuler: return Color::hex(0x4aa3ff);
    case Integrator::Verlet: return Color::hex(0x57c46a);
    case Integrator::VelocityVerlet: return Color::hex(0x2dd4bf);
    case Integrator::Leapfrog: return Color::hex(0xa78bfa);
    case Integrator::Midpoint: return Color::hex(0xf0b429);
    case Integrator::RK4: return Color::hex(0xff7ab6);
    case Integrator::ImplicitEuler: return Color::hex(0xc4cad4);
    }
    return Color::hex(0xffffff);
}

Marker integratorMarker(Integrator m) {
    switch (m) {
    case Integrator::ExplicitEuler: return Marker::Cross;
    case Integrator::SymplecticEuler: return Marker::Circle;
    case Integrator::Verlet: return Marker::Square;
    case Integrator::VelocityVerlet: return Marker::Diamond;
    case Integrator::Leapfrog: return Marker::Triangle;
    case Integrator::Midpoint: return Marker::Square;
    case Integrator::RK4: return Marker::Circle;
    case Integrator::ImplicitEuler: return Marker::Triangle;
    }
    return Marker::Circle;
}

std::vector<Series> integratorLegend() {
    std::vector<Series> out;
    for (const auto& i : phys::integrators()) {
        Series s;
        s.name = i.name;
        s.color = integratorColor(i.id);
        s.marker = integratorMarker(i.id);
        out.push_back(s);
    }
    return out;
}

std::vector<Chart> workPrecisionCharts(const std::vector<game::bench::WorkPrecisionPoint>& points) {
    std::vector<Chart> out;
    for (const auto& scene : game::bench::accuracyScenes()) {
        Chart c;
        c.title = scene.name;
        c.subtitle = std::string("error vs ") + scene.reference + ", " +
                     format("%g s simulated", scene.seconds);
        c.x = {"CPU seconds per simulated second", Scale::Log};
        c.y = {"error, m", Scale::Log};
        c.legend = false;
        double largest = 0.0;
        for (const auto& i : phys::integrators()) {
            Series s;
            s.name = i.name;
            s.color = integratorColor(i.id);
            s.marker = integratorMarker(i.id);
            for (const auto& p : points)
                if (p.scene == scene.id && p.integrator == i.id) {
                    // A run that blew up is drawn off the top, where it failed.
                    const double e = std::isfinite(p.error) ? p.error : 1e300;
                    largest = std::max(largest, e);
                    s.points.push_back({p.cpuSecondsPerSimSecond, std::max(e, 1e-16)});
                }
            // Cheapest first, so the line runs from big dt (left) to small dt (right).
            std::sort(s.points.begin(), s.points.end(),
                      [](Vec2 a, Vec2 b) { return a.x < b.x; });
            if (!s.points.empty()) c.series.push_back(std::move(s));
        }
        if (c.series.empty()) continue;
        // Errors beyond 100 m mean the run diverged; the chart stops there.
        if (largest > 1e2) c.y.max = 1e2;
        out.push_back(std::move(c));
    }
    return out;
}

std::vector<Chart> stabilityCharts(const std::vector<game::bench::StabilityRow>& rows,
                                   const std::vector<game::bench::GrowthCurve>& curves) {
    std::vector<Chart> out;
    if (!curves.empty()) {
        Chart g;
        g.title = "energy growth on an undamped spring";
        g.subtitle = "mean energy, 2nd half / 1st half of >= 20 periods; above 1 = unstable";
        g.x = {"w dt", Scale::Log};
        g.y = {"energy growth", Scale::Log, 1e-2, 1e3};
        g.legend = false;
        for (const auto& c : curves) {
            Series s;
            s.name = phys::info(c.integrator).name;
            s.color = integratorColor(c.integrator);
            s.marker = integratorMarker(c.integrator);
            for (std::size_t k = 0; k < c.omegaDt.size(); ++k)
                // Overflowed energy is drawn far above the top, so the line leaves the plot.
                s.points.push_back({c.omegaDt[k], std::isfinite(c.growth[k]) ? c.growth[k] : 1e30});
            g.series.push_back(std::move(s));
        }
        const Color mark = Color::hex(0xe7eaf0, 0.7f);
        g.marks.push_back({2.0, true, "2", mark});
        g.marks.push_back({2.0 * std::sqrt(2.0), true, "2.83", mark});
        g.marks.push_back({1.0, false, "stable", mark});
        out.push_back(std::move(g));
    }
    Chart w;
    w.kind = ChartKind::Bars;
    w.title = "largest stable w dt";
    w.subtitle = "bisection on the energy criterion; white tick: theory";
    w.x = {"w dt (spring of w = sqrt(k/m) stepped at dt)", Scale::Log, game::bench::kMinOmegaDt,
           game::bench::kMaxOmegaDt};
    Chart k;
    k.kind = ChartKind::Bars;
    k.title = "stiffest rope spring at the game tick";
    k.subtitle = "20 links of 0.1 m and 0.1 kg, released horizontal, dt = 1/120 s";
    k.x = {"spring stiffness, N/m", Scale::Log, 1.0, 1e12};
    for (const auto& row : rows) {
        const char* name = phys::info(row.integrator).name;
        Bar b{name, row.maxOmegaDt, row.theoryOmegaDt, integratorColor(row.integrator), ""};
        if (row.maxOmegaDt == 0.0) b.note = "unstable at any dt";
        else if (std::isinf(row.maxOmegaDt)) b.note = "never unstable";
        else if (row.theoryOmegaDt == 0.0)
            b.note = format("%.3g: grows too slowly below it for the test", row.maxOmegaDt);
        else b.note = format("%.3g", row.maxOmegaDt);
        if (std::isinf(row.theoryOmegaDt) || row.theoryOmegaDt == 0.0) b.reference = NAN;
        w.bars.push_back(b);
        Bar r{name, row.ropeStiffness, NAN, integratorColor(row.integrator), ""};
        if (row.ropeStiffness == 0.0) r.note = "fails even at 1 N/m";
        else if (std::isinf(row.ropeStiffness)) r.note = "survives 1e12 N/m";
        else r.note = format("%.3g N/m", row.ropeStiffness);
        k.bars.push_back(r);
    }
    out.push_back(std::move(w));
    out.push_back(std::move(k));
    return out;
}

namespace {

/// Step cost against N (with a slope-1 guide through each workload's first point), and
/// the cost per item: the two line charts of the scaling report.
std::pair<Chart, Chart> costCharts(const game::bench::ScalingReport& report) {
    std::map<std::string, std::vector<const game::bench::ScalingPoint*>> byWorkload;
    std::vector<std::string> order;
    for (const auto& p : report.points) {
        if (!byWorkload.count(p.workload)) order.push_back(p.workload);
        byWorkload[p.workload].push_back(&p);
    }
    Chart cost;
    cost.title = "step cost against N";
    cost.subtitle = "median wall time of one 1/120 s step; dashed: linear growth";
    cost.x = {"particles or bodies, N", Scale::Log};
    cost.y = {"time per step, us", Scale::Log};
    Chart per;
    per.title = "cost per item";
    per.subtitle = "flat = linear in N";
    per.x = {"particles or bodies, N", Scale::Log};
    per.y = {"ns per item per step", Scale::Log};
    per.legend = false;
    for (const auto& name : order) {
        Series s;
        s.name = workloadName(name);
        s.color = workloadColor(name);
        s.marker = workloadMarker(name);
        Series q = s;
        for (const auto* p : byWorkload[name]) {
            s.points.push_back({static_cast<double>(p->items), p->usPerStep});
            q.points.push_back({static_cast<double>(p->items), p->nsPerItem});
        }
        // A slope-1 guide through the first point of the workload.
        if (!s.points.empty()) {
            Series guide;
            guide.name = "";
            guide.color = s.color.withAlpha(0.45f);
            guide.marker = Marker::None;
            guide.dashed = true;
            guide.widthPx = 1.5f;
            const Vec2 a = s.points.front();
            const double nMax = s.points.back().x;
            guide.points = {a, {nMax, a.y * nMax / a.x}};
            cost.series.push_back(std::move(guide));
        }
        cost.series.push_back(std::move(s));
        per.series.push_back(std::move(q));
    }
    return {cost, per};
}

const Color kParticleBar = Color::hex(0x4aa3ff), kRigidBar = Color::hex(0xff6b6b),
            kStreamBar = Color::hex(0x8d97ab), kClothBar = Color::hex(0x57c46a);

/// The pile of columns and its heap in staggered rows: particles, Box2D, Box2D tuned.
void pileBars(const game::bench::ScalingReport& report, std::vector<Bar>& bars) {
    const auto& pile = report.pile;
    char note[96];
    if (pile.balls > 0) {
        const double balls = static_cast<double>(pile.balls);
        std::snprintf(note, sizeof note, "%.3g ms, %.1fx / %.1fx faster", pile.particleMs,
                      pile.speedup(), pile.speedupOverTuned());
        bars.push_back({format("pile of %.0f: particles", balls), pile.particleMs,
                        pile.rigidMs / 10.0, kParticleBar, note});
        bars.push_back({format("pile of %.0f: Box2D", balls), pile.rigidMs, NAN, kRigidBar,
                        format("%.3g ms", pile.rigidMs)});
        bars.push_back({format("pile of %.0f: Box2D tuned", balls), pile.tunedRigidMs, NAN,
                        workloadColor("box2d-tuned"),
                        format("%.3g ms (x10, no TOI)", pile.tunedRigidMs)});
    }
    // The same balls poured in staggered rows: the lead where each ball touches four to
    // six others, beside the columns' (no target).
    for (const auto& heap : report.heaps) {
        if (heap.balls != pile.balls) continue;
        const double balls = static_cast<double>(heap.balls);
        std::snprintf(note, sizeof note, "%.3g ms, %.1fx / %.1fx faster", heap.particleMs,
                      heap.speedup(), heap.speedupOverTuned());
        bars.push_back({format("heap of %.0f: particles", balls), heap.particleMs, NAN,
                        kParticleBar, note});
        bars.push_back({format("heap of %.0f: Box2D tuned", balls), heap.tunedRigidMs, NAN,
                        workloadColor("box2d-tuned"),
                        format("%.3g ms (x10, no TOI)", heap.tunedRigidMs)});
    }
}

/// The million particles in flight against the reference kernel and a memcpy, and the
/// cloth frame.
void flightAndClothBars(const game::bench::ScalingReport& report, std::vector<Bar>& bars) {
    char note[96];
    for (const auto& f : report.flights) {
        if (f.n < 1000000) continue; // the 1M figures: out of cache, the memory's limit
        const char* who = f.integrator == "velocity-verlet" ? "Verlet" : "sympl.";
        std::snprintf(note, sizeof note, "%.3g ms, %.2fx the reference", f.updateMs, f.ratio());
        bars.push_back({format("%.0fM in flight, ", f.n / 1e6) + who, f.updateMs,
                        1.5 * f.referenceMs, kParticleBar, note});
    }
    for (const auto& f : report.flights)
        if (f.n >= 1000000 && f.integrator != "velocity-verlet") {
            std::snprintf(note, sizeof note, "%.3g ms, %.3g GB/s", f.referenceMs, f.referenceGBs());
            bars.push_back({format("%.0fM: reference kernel", f.n / 1e6), f.referenceMs, NAN,
                            kStreamBar, note});
            std::snprintf(note, sizeof note, "%.3g ms, %.3g GB/s", f.copyMs, f.copyGBs());
            bars.push_back({format("%.0fM: memcpy, same bytes", f.n / 1e6), f.copyMs, NAN,
                            kStreamBar, note});
        }
    if (report.clothMs > 0)
        bars.push_back({"cloth 64x64, 8 sub-steps", report.clothMs, 2.0, kClothBar,
                        format("%.3g ms per frame", report.clothMs)});
}

} // namespace

std::vector<Chart> scalingCharts(const game::bench::ScalingReport& report) {
    auto [cost, per] = costCharts(report);
    Chart ratios;
    ratios.kind = ChartKind::Bars;
    ratios.title = "side by side, in one process";
    ratios.subtitle = "ms per step (per frame for cloth); white tick: the target";
    ratios.referenceName = "target";
    ratios.x = {"milliseconds", Scale::Log};
    pileBars(report, ratios.bars);
    flightAndClothBars(report, ratios.bars);
    // One spare decade on the right so every note fits after its bar; one below the
    // cheapest workload so the legend (bottom right) covers no line.
    double largest = 0.0, cheapest = INFINITY;
    for (const Bar& b : ratios.bars) largest = std::max(largest, b.value);
    for (const auto& p : report.points) cheapest = std::min(cheapest, p.usPerStep);
    if (largest > 0.0) ratios.x.max = std::pow(10.0, std::ceil(std::log10(largest)) + 1.0);
    if (std::isfinite(cheapest) && cheapest > 0.0)
        cost.y.min = std::pow(10.0, std::floor(std::log10(cheapest)) - 1.0);
    std::vector<Chart> out{cost, per};
    if (!ratios.bars.empty()) out.push_back(std::move(ratios));
    return out;
}

void drawWorkPrecision(Renderer2D& r, Rect area,
                       const std::vector<game::bench::WorkPrecisionPoint>& points) {
    const auto charts = workPrecisionCharts(points);
    const auto legend = integratorLegend();
    const int columns = charts.size() <= 1 ? 2 : 3;
    drawChartGrid(r, charts, area, columns, legend,
                  "Work-precision: error against cost, one line per integrator (dt halves "
                  "along each line, left to right)");
}

void drawStability(Renderer2D& r, Rect area, const std::vector<game::bench::StabilityRow>& rows,
                   const std::vector<game::bench::GrowthCurve>& curves) {
    const auto charts = stabilityCharts(rows, curves);
    const auto legend = integratorLegend();
    drawChartGrid(r, charts, area, 2, legend, "Stability: where each integrator fails");
}

std::string scalingTitle(const game::bench::ScalingReport& report, bool narrow) {
    std::string load;
    if (report.underLoad && std::isfinite(report.loadAtStart))
        load = format("taken under load %.2f", report.loadAtStart);
    else if (report.underLoad)
        load = "taken under load";
    else if (std::isfinite(report.loadAtStart))
        load = format("load %.2f", report.loadAtStart);
    std::string where = report.machine;
    if (!where.empty() && !load.empty()) where += ", ";
    where += load;
    const std::string what = "Scaling: step cost against the size of the scene";
    if (where.empty()) return what;
    return narrow ? "Scaling on " + where : what + " (" + where + ")";
}

void drawScaling(Renderer2D& r, Rect area, const game::bench::ScalingReport& report) {
    const auto charts = scalingCharts(report);
    // Side by side the three need about kRoomy pixels each: the bars' labels and notes
    // alone take some 330. Narrower (the in-game panel), the two line charts share the
    // top, and the bars share the bottom with the legend, which would cover most of a
    // line chart that small; the title then gives its line to the machine and the load
    // (the line charts' own titles say what they show).
    constexpr double kRoomy = 380.0;
    const bool narrow = charts.size() >= 3 && area.w < 3.0 * kRoomy;
    const std::string title = scalingTitle(report, narrow);
    if (!narrow) {
        drawChartGrid(r, charts, area, 3, {}, title);
        return;
    }
    std::vector<Chart> lines(charts.begin(), charts.begin() + 2);
    std::vector<Series> legend;
    for (const Series& s : lines.front().series)
        if (!s.name.empty()) legend.push_back(s); // (the dashed guides have none)
    lines.front().legend = false;
    const double top = std::round(0.56 * area.h);
    drawChartGrid(r, lines, {area.x, area.y, area.w, top}, 2, {}, title);
    drawChartGrid(r, std::span(charts).subspan(2), {area.x, area.y + top, area.w, area.h - top},
                  2, legend, "", "workloads");
}

} // namespace ui::charts
