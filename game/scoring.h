// A practice level's scoring, in numbers and in words: what each target is worth, the
// bonus for shots left, the largest score the rules allow, the least score each star
// needs, and a finished game's breakdown (targets, bonus, total) for the end card.
//
// The rules: a disc scores by how close to its centre the shell passes, its full points
// at the centre and half at its rim; a target block or blob knocked off its place scores
// a fixed amount; once every target is down, each shot left earns a bonus. One star needs
// every target down; two and three stars need a score, set against the level's par
// (every target down at full points with one shot each and the bonus for the rest) and
// at least one shot's bonus above the star before.
#pragma once

#include "game/level.h"

#include <array>
#include <string>
#include <vector>

namespace game {

class Match;

inline constexpr int kTargetBlockPoints = 100; ///< knocking a target block off its place
inline constexpr int kTargetBlobPoints = 150;  ///< knocking a target blob off its place
inline constexpr int kShotBonus = 50;          ///< per shot left once every target is down
/// The share of par two and three stars need (percent).
inline constexpr int kTwoStarPercent = 60;
inline constexpr int kThreeStarPercent = 85;

/// A disc's points for a pass `closeness` (1 at its centre, 0 at its rim) into it.
int discPoints(int points, double closeness);

struct LevelScoring {
    std::vector<int> discs; ///< each disc's points at its centre
    int blocks = 0;         ///< target blocks
    int blobs = 0;          ///< target blobs
    int shots = 0;          ///< the shot budget

    int targets() const { return static_cast<int>(discs.size()) + blocks + blobs; }
    /// Every target down, each disc at its centre, no bonus.
    int fullPoints() const;
    /// Every target down, each disc at its rim, no bonus: the least score of a won game.
    int leastAllDown() const;
    /// Every target down at full points with one shot each, the bonus for the rest.
    int par() const;
    /// The largest score the rules allow: full points, and the bonus for every shot but
    /// the one that downed them all.
    int maxScore() const;
    /// The least score that earns one, two and three stars (ascending).
    std::array<int, 3> starScores() const;
    /// Stars for a game that ends at `score` (0 unless every target is down).
    int stars(int score, bool allDown) const;
};

LevelScoring levelScoring(const Level& level);

/// The level's scoring in words, a line each: what the targets are worth, the bonus for
/// shots left, and what each star needs (the last three lines, one star first).
std::vector<std::string> scoringLines(const LevelScoring& s);

/// What a finished (or running) practice game has scored, by source.
struct ScoreBreakdown {
    std::vector<int> hits; ///< each disc hit's points, in order
    int toppled = 0;       ///< blocks and blobs knocked down
    int toppledPoints = 0;
    int shotsLeft = 0;
    bool over = false;     ///< the game is over
    bool allDown = false;  ///< every target down and the game over: the bonus is counted
    int bonus = 0;
    int total = 0;
};

ScoreBreakdown breakdownOf(const Match& match);

/// The breakdown in words, a line each: the targets hit and their points, the toppled,
/// the bonus and the total, e.g. "targets hit: 3 = 150 + 120 + 77 = 347".
std::vector<std::string> breakdownLines(const ScoreBreakdown& b, const LevelScoring& s);

/// What each star needs, in words ("every target down", "560 points"), one to three.
std::array<std::string, 3> starNeeds(const LevelScoring& s);

} // namespace game
