#include "ui/game/compare_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ui {

Color compareColor(phys::Integrator m) {
    // In phys::integrators() order.
    static const Color kPalette[] = {
        Color(0.95f, 0.25f, 0.25f), // explicit-euler: red
        Color(1.00f, 0.60f, 0.10f), // symplectic-euler: orange
        Color(0.95f, 0.90f, 0.20f), // verlet: yellow
        Color(0.30f, 0.85f, 0.30f), // velocity-verlet: green
        Color(0.20f, 0.85f, 0.85f), // leapfrog: cyan
        Color(0.35f, 0.50f, 1.00f), // midpoint: blue
        Color(0.80f, 0.40f, 0.95f), // rk4: violet
        Color(0.95f, 0.45f, 0.75f), // implicit-euler: pink
    };
    const auto i = static_cast<std::size_t>(m);
    return i < std::size(kPalette) ? kPalette[i] : Color(0.7f, 0.7f, 0.7f);
}

Color compareColor(const game::IntegratorPath& p) {
    return p.isReference ? Color(1.0f, 1.0f, 1.0f) : compareColor(p.integrator);
}

charts::Chart shotWorkChart(const game::ShotWork& work) {
    charts::Chart c;
    c.title = "this shot: landing error (m) against cost";
    char sub[96];
    const std::vector<game::ShotWorkPoint> none;
    const auto& points = work.lines.empty() ? none : work.lines.front().points;
    const double slow = points.empty() ? 0.0 : 1.0 / points.front().tickSeconds;
    const double fast = points.empty() ? 0.0 : 1.0 / points.back().tickSeconds;
    std::snprintf(sub, sizeof sub, "%.4g to %.4g Hz (tick %.4g Hz), vs %s", slow, fast,
                  1.0 / work.tickSeconds, game::landingReferenceName(work.reference));
    c.subtitle = sub;
    c.x = {"force evaluations to the landing", charts::Scale::Log};
    c.y = {"", charts::Scale::Log}; // in the title: a label here would stand in the plot
    c.legend = false;
    for (const game::ShotWorkLine& l : work.lines) {
        charts::Series s;
        s.name = l.name;
        s.color = compareColor(l.integrator);
        s.widthPx = 1.5f;
        for (const game::ShotWorkPoint& p : l.points)
            s.points.push_back(
                {p.evaluations, std::isfinite(p.error) ? std::max(p.error, kShotWorkFloor) : NAN});
        c.series.push_back(std::move(s));
    }
    return c;
}

} // namespace ui
