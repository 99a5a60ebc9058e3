// Fixed-step clock (frame-rate independence, as in Claypool, "Basic Game Physics"): wall time is poured into an
// accumulator and drained in whole ticks of a fixed length, so the world's result after
// N ticks never depends on the frame rate. The left-over fraction is the interpolation
// factor the renderer blends the last two states with.
#pragma once

#include <cstdint>

namespace phys {

struct ClockDef {
    double tickSeconds = 1.0 / 120.0; ///< simulated seconds per tick, > 0
    double timeScale = 1.0;           ///< simulated seconds per wall second (slow motion < 1)
    int maxTicksPerFrame = 32;        ///< cap, so a long stall cannot spiral into catch-up
};

class FixedClock {
  public:
    explicit FixedClock(const ClockDef& def = {}) : def_(def) {}

    /// Feeds one frame's wall time; returns how many ticks to simulate now.
    int advance(double frameSeconds);
    /// Fraction of a tick left in the accumulator, in [0, 1): the render blend factor.
    double alpha() const { return accumulator_ / def_.tickSeconds; }

    void setPaused(bool paused) { paused_ = paused; }
    bool paused() const { return paused_; }
    /// While paused, the next advance() returns exactly one tick.
    void requestSingleStep() { singleStep_ = true; }
    void setTimeScale(double scale) { def_.timeScale = scale; }
    void setTickSeconds(double seconds) { def_.tickSeconds = seconds; accumulator_ = 0.0; }
    const ClockDef& def() const { return def_; }
    /// Ticks handed out so far.
    std::uint64_t ticks() const { return ticks_; }
    /// Frames whose catch-up was capped (time was dropped, not simulated).
    std::uint64_t droppedFrames() const { return dropped_; }
    /// The caller ran `n` fewer of the ticks the last advance() handed out (its frame ran
    /// out of time): they are dropped, as a capped catch-up drops them.
    void dropTicks(int n);

  private:
    ClockDef def_;
    double accumulator_ = 0.0;
    std::uint64_t ticks_ = 0;
    std::uint64_t dropped_ = 0;
    bool paused_ = false;
    bool singleStep_ = false;
};

} // namespace phys
