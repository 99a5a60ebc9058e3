// Duels between computer players, for calibrating the difficulties: each side is the
// computer at a difficulty (ComputerPlayer) or the solver as a player (solverTurn, which
// sees the turn's wind). A duel is seeded (the level's seed draws the winds, each
// computer has its own seed), so the same duel gives the same winner on every run.
#pragma once

#include "game/ai.h"
#include "game/level.h"

#include <cstdint>
#include <optional>
#include <string>

namespace game::bench {

/// Who plays a side: the computer at a difficulty, or the solver (no difficulty).
struct DuelPlayer {
    std::optional<Difficulty> difficulty; ///< empty = the solver
    std::string name() const;
};

struct DuelResult {
    int winner = -1;         ///< 0 = side A, 1 = side B, -1 = draw
    int shots = 0;           ///< shots fired by both
    std::uint64_t ticks = 0; ///< length of the duel
};

/// Plays one duel on `level` (a duel level with two cannons): side A fires from the
/// cannon that starts when `aStarts`, else from the other. `seed` seeds the winds and
/// both computers.
DuelResult playDuel(const Level& level, const DuelPlayer& a, const DuelPlayer& b, bool aStarts,
                    std::uint64_t seed);

} // namespace game::bench
