// Where the shell went into the water: a view of the match that looks at the shell after
// each tick and reports the point where it crossed the water line going down since its
// last look (linear between the two looks). The splash's picture (Effects) and its sound
// (audio::Synthesizer) both come from it, so they agree on where and how hard.
#pragma once

#include "game/match.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace game {

struct WaterEntry {
    phys::Vec2 point;     ///< on the water line, m
    double downSpeed = 0; ///< the shell's downward speed at the last look above it, m/s
};

class WaterEntryWatch {
  public:
    /// Looks at the match's shell now; the entry when it crossed the water line since the
    /// last look. No shell (or no water) forgets the last look.
    std::optional<WaterEntry> look(const Match& m) {
        const auto shell = m.shell();
        if (!shell || !m.level().physics.water) {
            seen_ = false;
            return std::nullopt;
        }
        const phys::Vec2 p = m.world().particles.position(*shell);
        const double level = m.level().physics.waterLevel;
        std::optional<WaterEntry> entry;
        if (seen_ && at_.y > level && p.y <= level) {
            const double f = (at_.y - level) / std::max(1e-12, at_.y - p.y);
            entry = WaterEntry{at_ + (p - at_) * f, std::abs(vy_)};
        }
        seen_ = true;
        at_ = p;
        vy_ = m.world().particles.vy[*shell];
        return entry;
    }
    void forget() { seen_ = false; }

  private:
    bool seen_ = false;
    phys::Vec2 at_;
    double vy_ = 0.0;
};

} // namespace game
