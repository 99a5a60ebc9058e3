// Wall time a frame may spend running ticks. A window that runs every tick its fixed-step
// clock hands out freezes once a tick costs more wall time than it simulates (a heavy
// sandbox, a level of many small blocks): the clock's catch-up cap of 32 ticks at 100 ms
// a tick is a 3 s frame. Past the budget the frame's remaining ticks are dropped instead
// (FixedClock::dropTicks), so the game runs in slow motion at a frame rate the player can
// still steer and read. Only how many ticks a frame runs changes, never what a tick does:
// the match, its replay and its hash are the same. Headless runs have no budget, so
// their frames are the same on every machine.
#pragma once

#include "physics/clock.h"

#include <algorithm>
#include <chrono>
#include <optional>

namespace ui {

/// The window's budget: a little more than a frame at 60 Hz, so a light level never
/// meets it, and a heavy one still draws some 25 frames a second.
inline constexpr double kWindowTickBudgetSeconds = 0.025;

struct TicksRun {
    int ran = 0;
    double seconds = 0.0; ///< wall time they took
};

/// Runs `step` for up to `ticks` ticks, the first always, the others while the frame has
/// spent less than `budgetSeconds` (none: no limit); the ticks left are dropped from
/// `clock`.
template <class Step>
TicksRun runTicksWithin(phys::FixedClock& clock, int ticks, std::optional<double> budgetSeconds,
                        Step&& step) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto spent = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    TicksRun run;
    for (; run.ran < ticks; ++run.ran) {
        if (run.ran > 0 && budgetSeconds && spent() >= *budgetSeconds) break;
        step();
    }
    run.seconds = spent();
    if (run.ran < ticks) clock.dropTicks(ticks - run.ran);
    return run;
}

/// Whether the budget cut a frame lately, and what a tick took then: a screen says
/// "SLOW MOTION" for a second after the last frame the budget cut (not per frame, so the
/// line does not flicker), with what a tick costs in wall time.
class SlowMotion {
  public:
    /// One frame: `run` of the `wanted` ticks, in `wallSeconds` of the frame.
    void frame(const TicksRun& run, int wanted, double wallSeconds) {
        if (run.ran < wanted) {
            shownSeconds_ = 1.0;
            tickWallMs_ = 1000.0 * run.seconds / run.ran;
        } else {
            shownSeconds_ = std::max(0.0, shownSeconds_ - wallSeconds);
        }
    }
    bool shown() const { return shownSeconds_ > 0.0; }
    double tickWallMs() const { return tickWallMs_; } ///< when the budget last cut a frame

  private:
    double shownSeconds_ = 0.0;
    double tickWallMs_ = 0.0;
};

} // namespace ui
