#include "ui/game/measure_tools.h"

#include <cstdio>

namespace ui {

namespace {

const Color kMeasure = Color::hex(0xffe066); ///< the tools' marks and labels: warm yellow

std::string format(const char* fmt, double a, double b = 0.0, double c = 0.0) {
    char line[96];
    std::snprintf(line, sizeof line, fmt, a, b, c);
    return line;
}

} // namespace

const char* measureToolName(MeasureTool tool) {
    switch (tool) {
    case MeasureTool::Probe: return "probe: click a path";
    case MeasureTool::Tape: return "tape: drag between two points";
    case MeasureTool::Stopwatch: return "stopwatch: the shot's time of flight";
    case MeasureTool::Off: break;
    }
    return "";
}

void MeasureTools::next() {
    tool_ = static_cast<MeasureTool>((static_cast<int>(tool_) + 1) % 4);
    dragging_ = false;
}

void MeasureTools::reset() {
    recorder_.reset();
    probe_.reset();
    tapeFrom_.reset();
    tapeTo_.reset();
    dragging_ = false;
}

bool MeasureTools::press(phys::Vec2 at, double reach) {
    pointer_ = at;
    switch (tool_) {
    case MeasureTool::Probe:
        probe_ = game::probe(recorder_.shots(), at, reach);
        return true;
    case MeasureTool::Tape:
        tapeFrom_ = tapeTo_ = at;
        dragging_ = true;
        return true;
    case MeasureTool::Stopwatch: return true;
    case MeasureTool::Off: break;
    }
    return false;
}

bool MeasureTools::move(phys::Vec2 at) {
    pointer_ = at;
    if (tool_ == MeasureTool::Tape && dragging_) tapeTo_ = at;
    return on();
}

bool MeasureTools::lift(phys::Vec2 at) {
    if (tool_ == MeasureTool::Tape && dragging_) tapeTo_ = at;
    dragging_ = false;
    return on();
}

std::optional<game::TapeReading> MeasureTools::tapeReading() const {
    if (!tapeFrom_ || !tapeTo_) return std::nullopt;
    return game::tape(*tapeFrom_, *tapeTo_);
}

void MeasureTools::draw(Renderer2D& r) const {
    if (!on()) return;
    const Vec2 line{0.0, 16.0}; // px, one label line down
    if (tool_ == MeasureTool::Probe && probe_) {
        const game::ProbeReading& p = *probe_;
        r.strokeCircle(p.position, r.camera().metres(7.0), kMeasure, 2.0f);
        r.label(p.position, format("t %.2f s   x %.2f m   y %.2f m", p.t, p.position.x, p.position.y),
                kMeasure, {12.0, 12.0}, 0.85f);
        r.label(p.position, format("|v| %.2f m/s   KE %.4g J   PE %.4g J", p.speed, p.kinetic, p.potential),
                kMeasure, Vec2{12.0, 12.0} + line, 0.85f);
    }
    if (tool_ == MeasureTool::Tape) {
        if (const auto t = tapeReading(); t && tapeFrom_ && tapeTo_) {
            r.line(*tapeFrom_, *tapeTo_, kMeasure, 2.0f);
            for (const Vec2 end : {*tapeFrom_, *tapeTo_}) r.fillCircle(end, 0.0, kMeasure, 4.0f);
            r.label((*tapeFrom_ + *tapeTo_) * 0.5, format("%.2f m at %.1f°", t->distance, t->angleDeg),
                    kMeasure, {10.0, 10.0}, 0.85f);
        }
    }
    if (pointer_) {
        std::string text = measureToolName(tool_);
        if (tool_ == MeasureTool::Stopwatch) {
            const auto s = game::stopwatch(recorder_.shots());
            const bool running = !recorder_.shots().empty() && recorder_.shots().back().flying;
            text = s ? format(running ? "stopwatch %.2f s" : "stopwatch %.2f s (landed)", *s)
                     : "stopwatch: fire to start it";
        }
        r.label(*pointer_, text, kMeasure, {16.0, -20.0}, 0.8f);
    }
}

} // namespace ui
