// The solver as a duel player: its shot, played in the match, takes a hit point from the
// other cannon; and its practice games are what the commands replay.
#include "game/match.h"
#include "game/solver.h"

#include <gtest/gtest.h>

#include <string>

using namespace game;

namespace {
Level shipped(const std::string& name) {
    return loadLevel(std::string(ARTILLERY_SOURCE_DIR) + "/levels/" + name);
}
} // namespace

TEST(Solver, DuelTurnHitsTheOtherCannon) {
    const Level level = shipped("10_duel.json");
    const std::vector<Command> shot = solverTurn(level, {}, 0);
    ASSERT_EQ(shot.size(), 4u);
    EXPECT_EQ(shot.back().kind, CommandKind::Fire);
    Match m(level);
    const int before = m.cannons()[1].hitPoints;
    runCommands(m, shot, 1);
    for (int i = 0; i < 120 * 30 && m.shell(); ++i)
        m.step();
    EXPECT_EQ(m.cannons()[1].hitPoints, before - 1);
}

TEST(Solver, PracticeResultIsWhatItsCommandsPlay) {
    const Level level = shipped("04_bank_shots.json");
    const SolveResult r = solveLevel(level);
    ASSERT_EQ(r.stars, 3);
    Match m(level);
    runCommands(m, r.commands, r.ticks);
    EXPECT_TRUE(m.over());
    EXPECT_EQ(m.score(), r.score);
    EXPECT_EQ(m.stars(), r.stars);
    EXPECT_EQ(m.shotsFired(), r.shots);
}
