#include "game/scoring.h"

#include "game/match.h"

#include <algorithm>
#include <cmath>

namespace game {

namespace {

/// The least integer at or above `percent` % of `x`.
int percentOf(int percent, int x) { return (percent * x + 99) / 100; }

std::string plural(int n, const std::string& one, const std::string& many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// "a, b and c".
std::string listed(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i)
        out += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
    return out;
}

std::string discsLine(const std::vector<int>& discs) {
    const bool same = std::all_of(discs.begin(), discs.end(), [&](int p) { return p == discs[0]; });
    const int n = static_cast<int>(discs.size());
    if (same)
        return plural(n, "disc", "discs") + ": " + std::to_string(discs[0]) +
               " points at the centre, " + std::to_string(discPoints(discs[0], 0.0)) +
               " at the rim";
    std::vector<std::string> points;
    for (const int p : discs) points.push_back(std::to_string(p));
    return plural(n, "disc", "discs") + ": " + listed(points) + " points at the centre, half at the rim";
}

} // namespace

int discPoints(int points, double closeness) {
    return static_cast<int>(std::lround(points * (0.5 + 0.5 * closeness)));
}

int LevelScoring::fullPoints() const {
    int s = blocks * kTargetBlockPoints + blobs * kTargetBlobPoints;
    for (const int p : discs) s += p;
    return s;
}

int LevelScoring::leastAllDown() const {
    int s = blocks * kTargetBlockPoints + blobs * kTargetBlobPoints;
    for (const int p : discs) s += discPoints(p, 0.0);
    return s;
}

int LevelScoring::par() const { return fullPoints() + kShotBonus * std::max(0, shots - targets()); }

int LevelScoring::maxScore() const { return fullPoints() + kShotBonus * std::max(0, shots - 1); }

std::array<int, 3> LevelScoring::starScores() const {
    // Each star asks for at least one shot's bonus more than the star before, so no two
    // stars tie where the par's shares fall below the least won game (a level of blocks
    // alone scores by shots to spare). Capped at the largest score: a level of one shot
    // and one target has a single result, and it earns all three.
    const int one = leastAllDown();
    const int two = std::min(maxScore(), std::max(percentOf(kTwoStarPercent, par()), one + kShotBonus));
    const int three = std::min(maxScore(), std::max(percentOf(kThreeStarPercent, par()), two + kShotBonus));
    return {one, two, three};
}

int LevelScoring::stars(int score, bool allDown) const {
    if (!allDown) return 0;
    const std::array<int, 3> need = starScores();
    return score >= need[2] ? 3 : score >= need[1] ? 2 : 1;
}

LevelScoring levelScoring(const Level& level) {
    LevelScoring s;
    for (const Target& t : level.targets) s.discs.push_back(t.points);
    for (const Block& b : level.blocks) s.blocks += b.target;
    for (const Blob& b : level.blobs) s.blobs += b.target;
    s.shots = level.shots;
    return s;
}

std::vector<std::string> scoringLines(const LevelScoring& s) {
    std::vector<std::string> lines;
    if (!s.discs.empty()) lines.push_back(discsLine(s.discs));
    auto knock = [&](int n, const char* one, const char* many, int points) {
        if (n > 0)
            lines.push_back(plural(n, one, many) + " to knock down: " + std::to_string(points) +
                            (n > 1 ? " points each" : " points"));
    };
    knock(s.blocks, "block", "blocks", kTargetBlockPoints);
    knock(s.blobs, "blob", "blobs", kTargetBlobPoints);
    lines.push_back("bonus: " + std::to_string(kShotBonus) +
                    " for each shot left once all are down (best " + std::to_string(s.maxScore()) + ")");
    const std::array<std::string, 3> needs = starNeeds(s);
    for (int k = 0; k < 3; ++k)
        lines.push_back(plural(k + 1, "star", "stars") + ": " + needs[static_cast<std::size_t>(k)]);
    return lines;
}

ScoreBreakdown breakdownOf(const Match& m) {
    ScoreBreakdown b;
    for (const GameEvent& e : m.events()) {
        const int points = static_cast<int>(std::lround(e.value));
        if (e.kind == EventKind::TargetHit) b.hits.push_back(points);
        if (e.kind == EventKind::Toppled) {
            ++b.toppled;
            b.toppledPoints += points;
        }
    }
    b.shotsLeft = m.cannons().empty() ? 0 : m.cannons()[0].shotsLeft;
    b.over = m.over();
    b.allDown = m.over() && m.winner() == 0;
    if (b.allDown) b.bonus = kShotBonus * b.shotsLeft;
    b.total = m.score();
    return b;
}

std::vector<std::string> breakdownLines(const ScoreBreakdown& b, const LevelScoring& s) {
    std::vector<std::string> lines;
    if (!b.hits.empty()) {
        std::vector<std::string> terms;
        int sum = 0;
        for (const int p : b.hits) {
            terms.push_back(std::to_string(p));
            sum += p;
        }
        std::string line = plural(static_cast<int>(b.hits.size()), "disc hit", "discs hit") + ": ";
        for (std::size_t i = 0; i < terms.size(); ++i) line += (i ? " + " : "") + terms[i];
        lines.push_back(line + (terms.size() > 1 ? " = " + std::to_string(sum) : ""));
    }
    if (b.toppled > 0) {
        const int each = b.toppledPoints / b.toppled;
        lines.push_back(std::to_string(b.toppled) + " knocked down" +
                        (each * b.toppled == b.toppledPoints ? " x " + std::to_string(each) : "") +
                        " = " + std::to_string(b.toppledPoints));
    }
    if (b.allDown)
        lines.push_back("bonus: " + plural(b.shotsLeft, "shot", "shots") + " left x " +
                        std::to_string(kShotBonus) + " = " + std::to_string(b.bonus));
    else
        lines.push_back(b.over ? "bonus: none, not every target was down"
                               : "bonus: none until every target is down");
    lines.push_back("total: " + std::to_string(b.total) + " of " + std::to_string(s.maxScore()));
    return lines;
}

std::array<std::string, 3> starNeeds(const LevelScoring& s) {
    const std::array<int, 3> need = s.starScores();
    // Without discs a won game scores its full points and the bonus for the shots left,
    // so a star's score is a number of shots to spare, which is what the player can aim for.
    auto needOf = [&](int score) {
        if (!s.discs.empty() || score <= s.fullPoints())
            return "down and " + std::to_string(score) + " points";
        const int spare = (score - s.fullPoints() + kShotBonus - 1) / kShotBonus;
        return "down with " + plural(spare, "shot", "shots") + " to spare (" +
               std::to_string(s.fullPoints() + spare * kShotBonus) + " points)";
    };
    return {"every target down", needOf(need[1]), needOf(need[2])};
}

} // namespace game
