// The level solver: searches aims, powers, weapons and the order of shots through the
// same simulation as the game (Match) and returns the best game it finds, as commands.
// Shot by shot it seeds candidates from the firing solution (exact without drag, wind
// or water; Millington 3.5.3) and from the computer's trial-shot aim, and otherwise
// sweeps a coarse grid of angles and speeds; then it refines the best candidate by a
// pattern search that halves its steps. Every candidate is judged by re-playing the
// whole game so far from the level, so what it reports is what `replay verify` sees.
#pragma once

#include "game/command.h"
#include "game/level.h"
#include "game/replay.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace game {

struct SolveResult {
    bool practice = true; ///< false for duels and sandboxes: nothing to score
    int stars = 0;
    int score = 0;
    int maxScore = 0;      ///< the largest score the rules allow (game/scoring.h)
    std::array<int, 3> starScores{}; ///< the least score of one, two and three stars
    int shots = 0;
    std::vector<Command> commands;
    std::uint64_t ticks = 0; ///< length of the game the commands play
    long evaluations = 0;    ///< candidate shots simulated
};

SolveResult solveLevel(const Level& level);

/// The solver as a player: the shot (select, aim, power, fire at `tick`) for the cannon
/// whose turn it is after `history` (the game's commands so far, all before `tick`),
/// the one that gains most: points, and in a duel 100 for each hit point it takes from
/// the other cannons (it sees the turn's wind, as the simulation does). Empty when
/// nothing can be fired.
std::vector<Command> solverTurn(const Level& level, const std::vector<Command>& history,
                                std::uint64_t tick);

/// The solved game as a replay (checkpoints every 120 ticks, final hash).
Replay replayOf(const Level& level, const SolveResult& result);

} // namespace game
