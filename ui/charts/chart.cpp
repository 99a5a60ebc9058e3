#include "ui/charts/chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ui::charts {

namespace {

constexpr float kFontPx = 16.0f; // the ImGui font size the labels scale (imgui_layer.cpp)

// ---- small geometry in pixels ---------------------------------------------------------

/// Everything is laid out in pixels; the renderer's camera maps world to pixels, so the
/// chart goes through its inverse and lands where it should under any camera.
struct Pen {
    Renderer2D& r;
    Vec2 w(Vec2 px) const { return r.camera().toWorld(px); }
    void line(Vec2 a, Vec2 b, Color c, float width = 1.0f) { r.line(w(a), w(b), c, width); }
    void rect(Rect q, Color c) {
        const Vec2 p[4] = {w({q.x, q.y}), w({q.x + q.w, q.y}), w({q.x + q.w, q.y + q.h}),
                           w({q.x, q.y + q.h})};
        r.fillConvex(p, c);
    }
    void frame(Rect q, Color c, float width = 1.0f) {
        const Vec2 p[4] = {w({q.x, q.y}), w({q.x + q.w, q.y}), w({q.x + q.w, q.y + q.h}),
                           w({q.x, q.y + q.h})};
        r.polyline(p, c, width, true);
    }
    /// Text whose top edge is at px.y; alignX 0 left, 0.5 centred, 1 right.
    void text(Vec2 px, const std::string& s, Color c, float scale, float alignX = 0.0f) {
        r.screenLabel(px, s, c, scale, alignX);
    }
    void marker(Vec2 px, Marker m, Color c, double size) {
        const double s = size;
        switch (m) {
        case Marker::None: break;
        case Marker::Circle: r.fillCircle(w(px), r.camera().metres(s), c); break;
        case Marker::Square: rect({px.x - s * 0.85, px.y - s * 0.85, 1.7 * s, 1.7 * s}, c); break;
        case Marker::Triangle: {
            const Vec2 p[3] = {w({px.x, px.y - 1.2 * s}), w({px.x - 1.1 * s, px.y + 0.8 * s}),
                               w({px.x + 1.1 * s, px.y + 0.8 * s})};
            r.fillConvex(p, c);
            break;
        }
        case Marker::Diamond: {
            const Vec2 p[4] = {w({px.x, px.y - 1.3 * s}), w({px.x + 1.1 * s, px.y}),
                               w({px.x, px.y + 1.3 * s}), w({px.x - 1.1 * s, px.y})};
            r.fillConvex(p, c);
            break;
        }
        case Marker::Cross:
            line({px.x - s, px.y - s}, {px.x + s, px.y + s}, c, 2.0f);
            line({px.x - s, px.y + s}, {px.x + s, px.y - s}, c, 2.0f);
            break;
        }
    }
};

/// Liang-Barsky: clips the segment a-b to the rectangle; false when nothing is inside.
bool clip(Vec2& a, Vec2& b, const Rect& q) {
    double t0 = 0.0, t1 = 1.0;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double p[4] = {-dx, dx, -dy, dy};
    const double d[4] = {a.x - q.x, q.x + q.w - a.x, a.y - q.y, q.y + q.h - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (d[i] < 0.0) return false;
            continue;
        }
        const double t = d[i] / p[i];
        if (p[i] < 0.0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    const Vec2 a0 = a;
    a = {a0.x + t0 * dx, a0.y + t0 * dy};
    b = {a0.x + t1 * dx, a0.y + t1 * dy};
    return true;
}

bool inside(Vec2 p, const Rect& q, double slack = 0.5) {
    return p.x >= q.x - slack && p.x <= q.x + q.w + slack && p.y >= q.y - slack &&
           p.y <= q.y + q.h + slack;
}

double toAxis(double v, Scale s) { return s == Scale::Log ? std::log10(v) : v; }

bool usable(double v, Scale s) { return std::isfinite(v) && (s == Scale::Linear || v > 0.0); }

/// Range of the axis: the given one, else the data's, widened to whole decades on log
/// axes and by 5 % on linear ones.
void resolve(const Axis& axis, std::vector<double> values, double& lo, double& hi) {
    double a = std::numeric_limits<double>::infinity(), b = -a;
    for (double v : values)
        if (usable(v, axis.scale)) a = std::min(a, v), b = std::max(b, v);
    if (!std::isfinite(a)) a = axis.scale == Scale::Log ? 0.1 : 0.0, b = axis.scale == Scale::Log ? 10.0 : 1.0;
    if (axis.scale == Scale::Log) {
        a = std::pow(10.0, std::floor(std::log10(a) + 1e-9));
        b = std::pow(10.0, std::ceil(std::log10(b) - 1e-9));
        if (b <= a) b = a * 10.0;
    } else {
        const double pad = (b > a) ? 0.05 * (b - a) : std::max(1.0, std::abs(a) * 0.1);
        a -= pad;
        b += pad;
    }
    lo = std::isnan(axis.min) ? a : axis.min;
    hi = std::isnan(axis.max) ? b : axis.max;
    if (!(hi > lo)) hi = lo + 1.0;
}

float textScale(const ChartStyle& s) { return s.textScale; }
double lineHeight(const ChartStyle& s) { return kFontPx * s.textScale + 2.0; }
/// Rough width of a label (DejaVu Sans averages a little over half the font size).
double textWidth(const std::string& t, float scale) { return 0.56 * kFontPx * scale * t.size(); }

} // namespace

// ---- mapping ----------------------------------------------------------------------------

double ChartMapping::xPixel(double x) const {
    const double a = toAxis(xMin, xScale), b = toAxis(xMax, xScale);
    return plot.x + (toAxis(x, xScale) - a) / (b - a) * plot.w;
}

double ChartMapping::yPixel(double y) const {
    const double a = toAxis(yMin, yScale), b = toAxis(yMax, yScale);
    return plot.y + plot.h - (toAxis(y, yScale) - a) / (b - a) * plot.h;
}

Vec2 ChartMapping::toPixel(Vec2 d) const { return {xPixel(d.x), yPixel(d.y)}; }

ChartMapping layoutChart(const Chart& chart, Rect area) {
    const ChartStyle style;
    ChartMapping m;
    const double lh = lineHeight(style);
    // Title (and subtitle) above, tick labels and the axis label below, tick labels (or
    // bar categories) at the left.
    const double top = 8.0 + lh * 1.15 + (chart.subtitle.empty() ? 0.0 : lh) + 8.0;
    const double bottom = lh * 2.0 + 14.0;
    double left = 62.0;
    if (chart.kind == ChartKind::Bars) {
        double widest = 0.0;
        for (const Bar& b : chart.bars) widest = std::max(widest, textWidth(b.category, textScale(style)));
        left = widest + 18.0;
    } else if (!chart.y.label.empty()) {
        left = 66.0;
    }
    m.plot = {area.x + left, area.y + top, std::max(10.0, area.w - left - 18.0),
              std::max(10.0, area.h - top - bottom)};
    m.xScale = chart.x.scale;
    m.yScale = chart.kind == ChartKind::Bars ? Scale::Linear : chart.y.scale;
    std::vector<double> xs, ys;
    for (const Series& s : chart.series)
        for (const Vec2& p : s.points) {
            // A point only counts toward a range when the other coordinate is plottable.
            if (usable(p.y, m.yScale)) xs.push_back(p.x);
            if (usable(p.x, m.xScale)) ys.push_back(p.y);
        }
    for (const Bar& b : chart.bars) xs.push_back(b.value), xs.push_back(b.reference);
    resolve(chart.x, xs, m.xMin, m.xMax);
    if (chart.kind == ChartKind::Bars) {
        m.yMin = 0.0;
        m.yMax = std::max<double>(1.0, static_cast<double>(chart.bars.size()));
    } else {
        resolve(chart.y, ys, m.yMin, m.yMax);
    }
    return m;
}

// ---- ticks ------------------------------------------------------------------------------

std::vector<double> ticks(double lo, double hi, Scale scale) {
    std::vector<double> out;
    if (!(hi > lo)) return out;
    if (scale == Scale::Log) {
        if (!(lo > 0.0)) return out;
        const int a = static_cast<int>(std::ceil(std::log10(lo) - 1e-9));
        const int b = static_cast<int>(std::floor(std::log10(hi) + 1e-9));
        const int every = (b - a) > 14 ? 3 : (b - a) > 7 ? 2 : 1;
        for (int k = a; k <= b; ++k)
            if ((k - a) % every == 0) out.push_back(std::pow(10.0, k));
        return out;
    }
    const double raw = (hi - lo) / 6.0;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double f : {1.0, 2.0, 5.0, 10.0})
        if (f * mag >= raw) {
            step = f * mag;
            break;
        }
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step)
        out.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
    return out;
}

std::string tickLabel(double v, Scale scale) {
    char buf[32];
    if (scale == Scale::Log) {
        const int k = static_cast<int>(std::lround(std::log10(v)));
        if (k >= -3 && k <= 4) std::snprintf(buf, sizeof buf, "%g", std::pow(10.0, k));
        else std::snprintf(buf, sizeof buf, "1e%d", k);
    } else {
        std::snprintf(buf, sizeof buf, "%g", v);
    }
    return buf;
}

// ---- drawing ----------------------------------------------------------------------------

namespace {

void drawSeries(Pen& pen, const Series& s, const ChartMapping& m) {
    // Lines first (clipped to the plot), broken at points that cannot be plotted.
    if (s.line) {
        bool have = false;
        Vec2 prev;
        for (const Vec2& d : s.points) {
            if (!usable(d.x, m.xScale) || !usable(d.y, m.yScale)) {
                have = false;
                continue;
            }
            const Vec2 p = m.toPixel(d);
            if (have) {
                Vec2 a = prev, b = p;
                if (clip(a, b, m.plot)) {
                    if (s.dashed) {
                        const double len = std::hypot(b.x - a.x, b.y - a.y);
                        const int dashes = std::max(1, static_cast<int>(len / 9.0));
                        for (int k = 0; k < dashes; k += 2) {
                            const double t0 = static_cast<double>(k) / dashes;
                            const double t1 = std::min(1.0, (k + 1.0) / dashes);
                            pen.line(a + (b - a) * t0, a + (b - a) * t1, s.color, s.widthPx);
                        }
                    } else {
                        pen.line(a, b, s.color, s.widthPx);
                    }
                }
            }
            prev = p;
            have = true;
        }
    }
    for (const Vec2& d : s.points) {
        if (!usable(d.x, m.xScale) || !usable(d.y, m.yScale)) continue;
        const Vec2 p = m.toPixel(d);
        if (inside(p, m.plot)) pen.marker(p, s.marker, s.color, 3.6);
    }
}

void drawMarks(Pen& pen, const Chart& chart, const ChartMapping& m, const ChartStyle& st) {
    for (const Mark& k : chart.marks) {
        if (k.vertical) {
            if (!usable(k.value, m.xScale)) continue;
            const double x = m.xPixel(k.value);
            if (x < m.plot.x || x > m.plot.x + m.plot.w) continue;
            for (double y = m.plot.y; y < m.plot.y + m.plot.h; y += 10.0)
                pen.line({x, y}, {x, std::min(y + 5.0, m.plot.y + m.plot.h)}, k.color, 1.5f);
            if (!k.text.empty())
                pen.text({x + 4.0, m.plot.y + 4.0}, k.text, k.color, st.textScale * 0.85f);
        } else {
            if (!usable(k.value, m.yScale)) continue;
            const double y = m.yPixel(k.value);
            if (y < m.plot.y || y > m.plot.y + m.plot.h) continue;
            for (double x = m.plot.x; x < m.plot.x + m.plot.w; x += 10.0)
                pen.line({x, y}, {std::min(x + 5.0, m.plot.x + m.plot.w), y}, k.color, 1.5f);
            if (!k.text.empty())
                pen.text({m.plot.x + m.plot.w - 4.0, y - lineHeight(st)}, k.text, k.color,
                         st.textScale * 0.85f, 1.0f);
        }
    }
}

void drawBars(Pen& pen, const Chart& chart, const ChartMapping& m, const ChartStyle& st) {
    const double rowH = m.plot.h / std::max<std::size_t>(1, chart.bars.size());
    const double lh = lineHeight(st);
    for (std::size_t i = 0; i < chart.bars.size(); ++i) {
        const Bar& b = chart.bars[i];
        const double yc = m.plot.y + (i + 0.5) * rowH;
        const double half = std::min(rowH * 0.32, 11.0);
        pen.text({m.plot.x - 8.0, yc - 0.5 * lh}, b.category, st.text, st.textScale, 1.0f);
        double end = m.plot.x;
        const bool infinite = std::isinf(b.value) && b.value > 0;
        if (infinite) {
            end = m.plot.x + m.plot.w - 14.0;
        } else if (usable(b.value, m.xScale) && b.value > m.xMin) {
            end = std::min(m.xPixel(b.value), m.plot.x + m.plot.w);
        }
        if (end > m.plot.x + 0.5) {
            pen.rect({m.plot.x, yc - half, end - m.plot.x, 2.0 * half}, b.color.withAlpha(0.85f));
            if (infinite) { // an arrow head: the bar goes on for ever
                const Vec2 p[3] = {pen.w({end, yc - half - 3.0}), pen.w({end + 12.0, yc}),
                                   pen.w({end, yc + half + 3.0})};
                pen.r.fillConvex(p, b.color);
            }
        }
        if (usable(b.reference, m.xScale)) {
            const double x = m.xPixel(b.reference);
            if (x >= m.plot.x && x <= m.plot.x + m.plot.w)
                pen.line({x, yc - half - 5.0}, {x, yc + half + 5.0}, st.text, 3.0f);
        }
        if (!b.note.empty()) {
            // After the bar (callers leave room on the axis); inside only for bars that
            // run off the end.
            const bool after = !infinite;
            // Inside a bar (when it does not fit after it) the note is dark on the colour.
            pen.text({after ? end + 8.0 : m.plot.x + m.plot.w - 20.0, yc - 0.45 * lh}, b.note,
                     after ? st.dimText : st.background, st.textScale * 0.85f, after ? 0.0f : 1.0f);
        }
    }
}

} // namespace

ChartMapping drawChart(Renderer2D& r, const Chart& chart, Rect area, const ChartStyle& st) {
    Pen pen{r};
    const ChartMapping m = layoutChart(chart, area);
    const double lh = lineHeight(st);
    pen.rect(area, st.background);
    pen.rect(m.plot, st.plot);

    // Title and subtitle.
    pen.text({area.x + 12.0, area.y + 6.0}, chart.title, st.text, st.textScale * 1.12f);
    if (!chart.subtitle.empty())
        pen.text({area.x + 12.0, area.y + 8.0 + lh * 1.15}, chart.subtitle, st.dimText,
                 st.textScale * 0.85f);

    // Grid and tick labels. Log axes also get faint minor lines at 2..9 x 10^k.
    const auto xt = ticks(m.xMin, m.xMax, m.xScale);
    if (m.xScale == Scale::Log && std::log10(m.xMax / m.xMin) <= 7.5)
        for (double d = std::pow(10.0, std::floor(std::log10(m.xMin))); d < m.xMax; d *= 10.0)
            for (int k = 2; k <= 9; ++k) {
                const double x = m.xPixel(k * d);
                if (x > m.plot.x && x < m.plot.x + m.plot.w)
                    pen.line({x, m.plot.y}, {x, m.plot.y + m.plot.h}, st.grid.withAlpha(0.45f), 1.0f);
            }
    for (double v : xt) {
        const double x = m.xPixel(v);
        pen.line({x, m.plot.y}, {x, m.plot.y + m.plot.h}, st.grid, 1.0f);
        pen.line({x, m.plot.y + m.plot.h}, {x, m.plot.y + m.plot.h + 5.0}, st.axis, 1.5f);
        pen.text({x, m.plot.y + m.plot.h + 7.0}, tickLabel(v, m.xScale), st.dimText,
                 st.textScale * 0.9f, 0.5f);
    }
    if (chart.kind == ChartKind::Lines) {
        const auto yt = ticks(m.yMin, m.yMax, m.yScale);
        for (double v : yt) {
            const double y = m.yPixel(v);
            pen.line({m.plot.x, y}, {m.plot.x + m.plot.w, y}, st.grid, 1.0f);
            pen.line({m.plot.x - 5.0, y}, {m.plot.x, y}, st.axis, 1.5f);
            pen.text({m.plot.x - 8.0, y - 0.5 * lh}, tickLabel(v, m.yScale), st.dimText,
                     st.textScale * 0.9f, 1.0f);
        }
    }

    // Data, reference marks, then the axes on top so lines never hide them.
    drawMarks(pen, chart, m, st);
    if (chart.kind == ChartKind::Bars) drawBars(pen, chart, m, st);
    for (const Series& s : chart.series) drawSeries(pen, s, m);
    pen.line({m.plot.x, m.plot.y + m.plot.h}, {m.plot.x + m.plot.w, m.plot.y + m.plot.h}, st.axis, 2.0f);
    pen.line({m.plot.x, m.plot.y}, {m.plot.x, m.plot.y + m.plot.h}, st.axis, 2.0f);

    // Axis labels: x centred below the tick labels; y above the axis, left-aligned (the
    // renderer draws no rotated text).
    pen.text({m.plot.x + 0.5 * m.plot.w, m.plot.y + m.plot.h + 8.0 + lh}, chart.x.label, st.text,
             st.textScale, 0.5f);
    if (chart.kind == ChartKind::Lines && !chart.y.label.empty())
        pen.text({m.plot.x + 6.0, m.plot.y + 4.0}, chart.y.label, st.text, st.textScale * 0.9f);

    // Series without a name (guides) stay out of the legend.
    std::vector<Series> named;
    for (const Series& s : chart.series)
        if (!s.name.empty()) named.push_back(s);
    if (chart.legend && !named.empty()) {
        const double rows = static_cast<double>(named.size());
        double widest = 0.0;
        for (const Series& s : named) widest = std::max(widest, textWidth(s.name, st.textScale));
        const Rect box{m.plot.x + m.plot.w - widest - 52.0, m.plot.y + m.plot.h - rows * lh - 18.0,
                       widest + 44.0, rows * lh + 12.0};
        drawLegend(r, named, box, st);
    }
    if (chart.kind == ChartKind::Bars && !chart.bars.empty() &&
        std::any_of(chart.bars.begin(), chart.bars.end(),
                    [](const Bar& b) { return std::isfinite(b.reference); })) {
        // Key for the reference tick, bottom right of the title line.
        const double x = area.x + area.w - 18.0 - textWidth(chart.referenceName, st.textScale * 0.85f);
        pen.line({x - 12.0, area.y + 8.0}, {x - 12.0, area.y + 8.0 + lh}, st.text, 3.0f);
        pen.text({x - 4.0, area.y + 8.0}, chart.referenceName, st.text, st.textScale * 0.85f);
    }
    return m;
}

void drawLegend(Renderer2D& r, std::span<const Series> series, Rect area, const ChartStyle& st,
                const std::string& title) {
    Pen pen{r};
    const double lh = lineHeight(st);
    pen.rect(area, st.background.withAlpha(0.88f));
    pen.frame(area, st.grid, 1.0f);
    double y = area.y + 6.0;
    if (!title.empty()) {
        pen.text({area.x + 10.0, y}, title, st.text, st.textScale);
        y += lh * 1.3;
    }
    for (const Series& s : series) {
        const double yc = y + 0.5 * lh;
        if (s.line) pen.line({area.x + 8.0, yc}, {area.x + 32.0, yc}, s.color, s.widthPx);
        pen.marker({area.x + 20.0, yc}, s.marker, s.color, 3.6);
        pen.text({area.x + 40.0, y}, s.name, st.text, st.textScale);
        y += lh;
    }
}

void drawChartGrid(Renderer2D& r, std::span<const Chart> charts, Rect area, int columns,
                   std::span<const Series> legend, const std::string& heading,
                   const std::string& legendTitle, const ChartStyle& st) {
    Pen pen{r};
    pen.rect(area, st.background);
    double top = area.y;
    if (!heading.empty()) {
        pen.text({area.x + 14.0, area.y + 10.0}, heading, st.text, st.textScale * 1.3f);
        top += lineHeight(st) * 1.3 + 18.0;
    }
    const int cells = static_cast<int>(charts.size()) + (legend.empty() ? 0 : 1);
    const int cols = std::max(1, std::min(columns, cells));
    const int rows = (cells + cols - 1) / cols;
    const double cw = area.w / cols, ch = (area.y + area.h - top) / rows;
    const double gap = 6.0;
    for (int i = 0; i < cells; ++i) {
        const Rect cell{area.x + (i % cols) * cw + gap, top + (i / cols) * ch + gap, cw - 2 * gap,
                        ch - 2 * gap};
        if (i < static_cast<int>(charts.size())) {
            drawChart(r, charts[i], cell, st);
        } else {
            double widest = 0.0;
            for (const Series& s : legend) widest = std::max(widest, textWidth(s.name, st.textScale));
            const double h = lineHeight(st) * (legend.size() + 1.3) + 14.0;
            const double w = widest + 60.0;
            drawLegend(r, legend, {cell.x + 0.5 * (cell.w - w), cell.y + 0.5 * (cell.h - h), w, h}, st,
                       legendTitle);
        }
    }
}

} // namespace ui::charts
