// The measuring tools as a mode (M): while one is on, the mouse measures instead of
// aiming, and a label at the pointer says which tool it is. The probe (click near any
// recorded path: its time, position, speed, kinetic and potential energy there), the tape
// measure (drag between two points: distance and angle) and the stopwatch (the last
// shot's time of flight, running while it flies). The figures are game/measure.h's; this
// draws them and takes the mouse. The wheel and a right drag still move the camera.
#pragma once

#include "game/measure.h"
#include "ui/render/renderer2d.h"

#include <SDL.h>

#include <optional>
#include <string>

namespace ui {

enum class MeasureTool { Off, Probe, Tape, Stopwatch };
const char* measureToolName(MeasureTool tool);

class MeasureTools {
  public:
    MeasureTool tool() const { return tool_; }
    bool on() const { return tool_ != MeasureTool::Off; }
    /// M: off, probe, tape, stopwatch, off again.
    void next();
    /// After every tick of the match shown.
    void observe(const game::Match& match) { recorder_.observe(match); }
    /// Forgets the recorded paths and the readings (a new match).
    void reset();
    /// A left press, drag or release over the field at `at` (m); a press probes the paths
    /// within `reach` (m) of it. Returns true when it measured (the caller leaves aiming
    /// alone).
    bool press(phys::Vec2 at, double reach);
    bool move(phys::Vec2 at);
    bool lift(phys::Vec2 at);
    /// The readings and the pointer's label, through the match's camera.
    void draw(Renderer2D& r) const;

    const std::optional<game::ProbeReading>& probeReading() const { return probe_; }
    std::optional<game::TapeReading> tapeReading() const;
    const game::ShotRecorder& recorder() const { return recorder_; }

  private:
    MeasureTool tool_ = MeasureTool::Off;
    game::ShotRecorder recorder_;
    std::optional<game::ProbeReading> probe_;
    std::optional<phys::Vec2> tapeFrom_, tapeTo_;
    bool dragging_ = false;
    std::optional<phys::Vec2> pointer_; ///< m, where the mouse is over the field
};

} // namespace ui
