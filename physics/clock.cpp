#include "physics/clock.h"

#include <algorithm>

namespace phys {

int FixedClock::advance(double frameSeconds) {
    if (paused_) {
        if (!singleStep_) return 0;
        singleStep_ = false;
        ++ticks_;
        return 1;
    }
    if (frameSeconds > 0.0) accumulator_ += frameSeconds * def_.timeScale;
    int n = 0;
    while (accumulator_ >= def_.tickSeconds) {
        if (n == def_.maxTicksPerFrame) {
            accumulator_ = 0.0; // drop the backlog rather than fall further behind
            ++dropped_;
            break;
        }
        accumulator_ -= def_.tickSeconds;
        ++n;
    }
    ticks_ += static_cast<std::uint64_t>(n);
    return n;
}

void FixedClock::dropTicks(int n) {
    if (n <= 0) return;
    ticks_ -= std::min(ticks_, static_cast<std::uint64_t>(n));
    ++dropped_;
}

} // namespace phys
