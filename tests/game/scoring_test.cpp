// A level's scoring (game/scoring.h): the largest score the rules allow, the least score
// of each star, the scoring and a game's breakdown in words, against a level computed by
// hand and against every shipped level.
#include "game/ai.h"
#include "game/match.h"
#include "game/scoring.h"

#include "shots.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace game;
using namespace shots;

namespace {

/// Two discs (200 and 100 points), a target block and a block that is none, four shots.
LevelScoring handLevel() {
    Level l;
    l.targets.resize(2);
    l.targets[0].points = 200;
    l.targets[1].points = 100;
    l.blocks.resize(2);
    l.blocks[0].target = true;
    l.shots = 4;
    return levelScoring(l);
}

} // namespace

// By hand: full points 200 + 100 + 100 = 400; at the discs' rims 100 + 50 + 100 = 250;
// par, one shot a target and the bonus for the fourth, 400 + 50 = 450; the most, every
// target down with the first shot, 400 + 3 x 50 = 550. Two stars need 60 % of par (270)
// but at least a shot's bonus above one star (250 + 50 = 300), three 85 % (382.5, so 383).
TEST(Scoring, AHandComputedLevel) {
    const LevelScoring s = handLevel();
    EXPECT_EQ(s.fullPoints(), 400);
    EXPECT_EQ(s.leastAllDown(), 250);
    EXPECT_EQ(s.par(), 450);
    EXPECT_EQ(s.maxScore(), 550);
    EXPECT_EQ(s.starScores(), (std::array<int, 3>{250, 300, 383}));
    EXPECT_EQ(s.stars(382, true), 2);
    EXPECT_EQ(s.stars(383, true), 3);
    EXPECT_EQ(s.stars(299, true), 1);
    EXPECT_EQ(s.stars(300, true), 2);
    EXPECT_EQ(s.stars(550, false), 0);
}

TEST(Scoring, TheRulesInWords) {
    const std::vector<std::string> expected{
        "2 discs: 200 and 100 points at the centre, half at the rim",
        "1 block to knock down: 100 points",
        "bonus: 50 for each shot left once all are down (best 550)",
        "1 star: every target down",
        "2 stars: down and 300 points",
        "3 stars: down and 383 points",
    };
    EXPECT_EQ(scoringLines(handLevel()), expected);
    LevelScoring same;
    same.discs = {150, 150, 150};
    same.blobs = 2;
    same.shots = 3;
    const std::vector<std::string> lines = scoringLines(same);
    ASSERT_GE(lines.size(), 2u);
    EXPECT_EQ(lines[0], "3 discs: 150 points at the centre, 75 at the rim");
    EXPECT_EQ(lines[1], "2 blobs to knock down: 150 points each");
}

// A level of blocks alone scores its full points and the bonus for the shots left, so
// its stars are shots to spare: four blocks and four shots give 400, 450 and 500, never
// three stars for any clear.
TEST(Scoring, ALevelOfBlocksAloneAsksForShotsToSpare) {
    LevelScoring blocks;
    blocks.blocks = 4;
    blocks.shots = 4;
    EXPECT_EQ(blocks.starScores(), (std::array<int, 3>{400, 450, 500}));
    const std::array<std::string, 3> needs = starNeeds(blocks);
    EXPECT_EQ(needs[0], "every target down");
    EXPECT_EQ(needs[1], "down with 1 shot to spare (450 points)");
    EXPECT_EQ(needs[2], "down with 2 shots to spare (500 points)");
    // Two blobs and five shots: par 450 puts three stars at 383, which only two shots to
    // spare reach.
    LevelScoring blobs;
    blobs.blobs = 2;
    blobs.shots = 5;
    EXPECT_EQ(blobs.starScores(), (std::array<int, 3>{300, 350, 400}));
    blobs.shots = 1; // one shot for two blobs: one result, and it earns all three
    EXPECT_EQ(blobs.starScores(), (std::array<int, 3>{300, 300, 300}));
}

TEST(Scoring, TheBreakdownInWords) {
    ScoreBreakdown b;
    b.hits = {150, 77};
    b.toppled = 1;
    b.toppledPoints = 100;
    b.shotsLeft = 2;
    b.allDown = true;
    b.bonus = 100;
    b.total = 427;
    const std::vector<std::string> expected{
        "2 discs hit: 150 + 77 = 227",
        "1 knocked down x 100 = 100",
        "bonus: 2 shots left x 50 = 100",
        "total: 427 of 550",
    };
    EXPECT_EQ(breakdownLines(b, handLevel()), expected);
    ScoreBreakdown running;
    running.hits = {90};
    running.shotsLeft = 3;
    running.total = 90;
    EXPECT_EQ(breakdownLines(running, handLevel()),
              (std::vector<std::string>{"1 disc hit: 90", "bonus: none until every target is down",
                                        "total: 90 of 550"}));
    running.over = true;
    EXPECT_EQ(breakdownLines(running, handLevel())[1], "bonus: none, not every target was down");
}

// A game played to its end: the breakdown adds up to the score, bonus included.
TEST(Scoring, ABreakdownAddsUpToTheScore) {
    Level l = level("01_earth_basics.json");
    l.physics.windMin = l.physics.windMax = 0.0;
    Match m(l);
    for (std::size_t t = 0; t < m.targets().size() && !m.over(); ++t) {
        const AimSolution aim = aimAt(m, m.targets()[t].position);
        shoot(m, aim.angleDeg, aim.speedMps);
        for (int i = 0; i < 120 * 40 && m.shell(); ++i) m.step();
    }
    ASSERT_TRUE(m.over());
    const ScoreBreakdown b = breakdownOf(m);
    int sum = b.toppledPoints + b.bonus;
    for (const int h : b.hits) sum += h;
    EXPECT_EQ(b.hits.size(), m.targets().size());
    EXPECT_EQ(b.bonus, kShotBonus * m.cannon().shotsLeft);
    EXPECT_EQ(sum, m.score());
    EXPECT_EQ(b.total, m.score());
    EXPECT_LE(m.score(), m.maxScore());
}

// Every shipped practice level: the stars' scores ascend, a shot's bonus apart, up to the largest score, which
// the rules reach only with every bonus, and that score earns three stars.
TEST(Scoring, EveryShippedLevelsStarsAscendToItsMaximum) {
    int practice = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(ARTILLERY_SOURCE_DIR) / "levels")) {
        if (entry.path().extension() != ".json" || entry.path().filename() == "campaign.json") continue;
        const Level l = loadLevel(entry.path().string());
        if (l.mode != Mode::Practice) continue;
        ++practice;
        const LevelScoring s = levelScoring(l);
        const auto need = s.starScores();
        // Each star a shot's bonus above the one before, where the largest score leaves room.
        EXPECT_GE(need[1], std::min(s.maxScore(), need[0] + kShotBonus)) << entry.path();
        EXPECT_GE(need[2], std::min(s.maxScore(), need[1] + kShotBonus)) << entry.path();
        EXPECT_LE(need[2], s.maxScore()) << entry.path();
        EXPECT_EQ(s.maxScore(), s.fullPoints() + kShotBonus * (l.shots - 1)) << entry.path();
        EXPECT_EQ(s.stars(s.maxScore(), true), 3) << entry.path();
        EXPECT_EQ(s.stars(need[2] - 1, true), need[2] - 1 >= need[1] ? 2 : 1) << entry.path();
    }
    EXPECT_GT(practice, 30);
}
