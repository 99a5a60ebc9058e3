// The wall clock around a step's phases, for StepProfile. It is read only while profiling
// is on: no result depends on it, and a world of one shell stepped thousands of times
// (the aim preview, the computer's trial shots) would otherwise spend about half its
// time reading the clock (some fifteen reads a step, against half a microsecond of
// physics).
#pragma once

#include <chrono>

namespace phys {

class PhaseClock {
  public:
    using TimePoint = std::chrono::steady_clock::time_point;
    bool on = true;
    TimePoint now() const { return on ? std::chrono::steady_clock::now() : TimePoint{}; }
    /// Microseconds since t0; 0 while off.
    double microsSince(TimePoint t0) const {
        if (!on) return 0.0;
        return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0)
            .count();
    }
};

} // namespace phys
