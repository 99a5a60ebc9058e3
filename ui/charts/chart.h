// Charts drawn with the game's own Renderer2D: line charts (log or linear axes, ticks,
// labels, lines with markers, reference marks) and horizontal bar charts, placed in a
// pixel rectangle of whatever the renderer draws into. The bench PNGs (headless) and
// the in-game Charts panel run this same code.
//
// Sections: data model (Axis, Series, Bar, Mark, Chart) - mapping (ChartMapping:
// data -> pixels, exposed so tests can check where a point must land) - ticks -
// drawing (drawChart, drawLegend, drawChartGrid).
#pragma once

#include "ui/render/renderer2d.h"

#include <span>
#include <string>
#include <vector>

namespace ui::charts {

/// A rectangle in pixels, origin top-left, y down (as screenshots and ImGui).
struct Rect {
    double x = 0, y = 0, w = 0, h = 0;
    Vec2 lo() const { return {x, y}; }
    Vec2 hi() const { return {x + w, y + h}; }
};

enum class Scale { Linear, Log };

struct Axis {
    std::string label;
    Scale scale = Scale::Linear;
    /// Range in data units; NaN = fit the data (log axes widen to whole decades).
    double min = NAN, max = NAN;
};

enum class Marker { None, Circle, Square, Triangle, Diamond, Cross };

/// One line: points in data units, drawn in order. Non-finite points (a run that blew
/// up) break the line, so a method that fails stops visibly where it failed.
struct Series {
    std::string name;
    Color color;
    std::vector<Vec2> points;
    Marker marker = Marker::Circle;
    bool line = true;
    bool dashed = false;
    float widthPx = 2.0f;
};

/// A horizontal bar of a bar chart: one category, its value and an optional reference
/// value (theory) drawn as a tick across the bar. value 0 draws no bar and `note`;
/// infinity runs off the end with an arrow.
struct Bar {
    std::string category;
    double value = 0;
    double reference = NAN;
    Color color;
    std::string note; ///< text after the bar ("never unstable", "unstable at any dt")
};

/// A reference line across the plot at a data value (vertical: at x; else at y).
struct Mark {
    double value = 0;
    bool vertical = true;
    std::string text;
    Color color;
};

enum class ChartKind { Lines, Bars };

struct Chart {
    ChartKind kind = ChartKind::Lines;
    std::string title;
    std::string subtitle; ///< a smaller line under the title (what is measured)
    Axis x, y;            ///< for Bars only x is used (the value axis)
    std::vector<Series> series;
    std::vector<Bar> bars;
    std::vector<Mark> marks;
    std::string referenceName = "theory"; ///< legend word for Bar::reference ticks
    bool legend = true;   ///< draw the legend inside the plot (top-left)
};

/// The colours of the chart frame (dark, like the game's panels).
struct ChartStyle {
    Color background = Color::hex(0x0f131b);
    Color plot = Color::hex(0x161c27);
    Color grid = Color::hex(0x263042);
    Color axis = Color::hex(0x8d97ab);
    Color text = Color::hex(0xe7eaf0);
    Color dimText = Color::hex(0xa3acbd);
    float textScale = 0.9f;
};

/// Resolved axes and the plot area for one chart in one rectangle.
struct ChartMapping {
    Rect plot;              ///< the area inside the axes, px
    double xMin = 0, xMax = 1, yMin = 0, yMax = 1;
    Scale xScale = Scale::Linear, yScale = Scale::Linear;

    /// Pixel of a data point (may lie outside the plot when the point is out of range).
    Vec2 toPixel(Vec2 data) const;
    double xPixel(double x) const;
    double yPixel(double y) const;
};

/// Where `chart` puts its plot inside `area` and which ranges its axes show.
ChartMapping layoutChart(const Chart& chart, Rect area);

/// Tick positions in data units: decades (or every other decade on wide ranges) on log
/// axes; 1, 2, 5 x 10^k steps on linear ones.
std::vector<double> ticks(double lo, double hi, Scale scale);
/// A short label for a tick value: "0.01", "1", "100", "1e-06", "1e+05".
std::string tickLabel(double value, Scale scale);

/// Draws the chart into `area` (pixels of the renderer's viewport, whatever its camera).
ChartMapping drawChart(Renderer2D& r, const Chart& chart, Rect area,
                       const ChartStyle& style = {});

/// A legend of series (line + marker + name) in `area`, in rows.
void drawLegend(Renderer2D& r, std::span<const Series> series, Rect area,
                const ChartStyle& style = {}, const std::string& title = "");

/// Several charts in a grid of `columns`, with an optional legend taking the next free
/// cell (or none when `legend` is empty), titled `legendTitle`, and a heading above the
/// grid.
void drawChartGrid(Renderer2D& r, std::span<const Chart> charts, Rect area, int columns,
                   std::span<const Series> legend = {}, const std::string& heading = "",
                   const std::string& legendTitle = "integrators", const ChartStyle& style = {});

} // namespace ui::charts
