// Levels from a seed: terrain from fractal value noise, cannons on flattened pads,
// targets (practice) or the second cannon (duel), structures of blocks, a rope and a
// soft blob at the harder settings, a wind range and a name with the seed. Everything
// comes from the generator's own SeededRandom and exact double operations, so a seed
// gives the same file on every build.
//
// A candidate is only offered once it is known to be playable: a practice map must give
// the solver three stars, a duel map must let each side hit the other with one shot
// (the solver's shot under the first turn's wind). A candidate that fails is replaced
// by the next one derived from the same seed.
#pragma once

#include "game/ai.h"
#include "game/level.h"
#include "game/solver.h"

#include <cstdint>
#include <string>

namespace game::generate {

struct GenerateDef {
    std::uint64_t seed = 1;
    Mode mode = Mode::Practice; ///< Practice or Duel
    Difficulty difficulty = Difficulty::Normal;
    int maxCandidates = 8; ///< candidates tried before giving up
};

/// Candidate `index` (0, 1, ...) of a seed, unchecked: the level as written to a file
/// (contentHash of that text, file empty). Each candidate draws from its own generator,
/// seeded from the seed and the index.
Level candidateLevel(const GenerateDef& def, int index);

struct Generated {
    Level level;           ///< the level offered (the last candidate tried when !playable)
    std::string text;      ///< its file, in the level format
    int candidates = 0;    ///< how many were tried, this one included
    bool playable = false; ///< three stars (practice) or a hit each way (duel)
    int stars = 0;         ///< practice: the solver's stars on it
    int shots = 0;         ///< practice: shots the solver needed
    bool hitByFirst = false, hitBySecond = false; ///< duel: each side's test shot hit
};

/// The first playable candidate of the seed, trying at most def.maxCandidates.
Generated generateLevel(const GenerateDef& def);

/// Whether each duel cannon can hit the other with one shot: the solver's shot for the
/// first cannon at the start, and for the second with the cannons' order swapped.
std::pair<bool, bool> duelHitsEachWay(const Level& level);

} // namespace game::generate
