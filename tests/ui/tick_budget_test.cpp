// A frame whose ticks cost more wall time than its budget runs fewer of them: the game
// goes on in slow motion, says so, and the match is the same tick for tick.
#include "headless_game.h"

#include "game/session.h"

#include <gtest/gtest.h>

namespace {

std::unique_ptr<ui::GameScreen> castle(ui::GLContext& context, std::optional<double> budget) {
    ui::GameScreenDef def;
    def.levelFile = (test_game::kRoot / "levels/05_castle.json").string();
    def.levelsFolder = (test_game::kRoot / "levels").string();
    def.tickBudgetSeconds = budget;
    return std::make_unique<ui::GameScreen>(context, nullptr, def);
}

} // namespace

TEST(TickBudget, AFrameOverItsBudgetRunsOneTickInSlowMotionAndTheMatchIsTheSame) {
    std::string error;
    auto context = ui::createHeadlessContext(320, 180, ui::HeadlessBackend::Auto, error);
    ASSERT_NE(context, nullptr) << error;
    // No budget (headless): a quarter second of wall time is 30 ticks.
    auto free = castle(*context, std::nullopt);
    free->frame(0.25);
    EXPECT_EQ(free->session()->match().tick(), 30u);
    EXPECT_EQ(free->banner(), "");
    const std::uint64_t hashAt30 = free->session()->match().hash();
    free.reset(); // one screen (one ImGui context) at a time
    // A budget of nothing: each frame runs its first tick only, whatever it was owed.
    auto tight = castle(*context, 0.0);
    for (int frame = 0; frame < 30; ++frame)
        tight->frame(0.25);
    EXPECT_EQ(tight->session()->match().tick(), 30u);
    EXPECT_EQ(tight->banner().rfind("SLOW MOTION: a tick of 8 ms takes ", 0), 0u) << tight->banner();
    EXPECT_EQ(tight->session()->match().hash(), hashAt30)
        << "how many ticks a frame runs never changes what a tick does";
    // Back under budget (a frame owed one tick), the banner goes after a second.
    for (int frame = 0; frame < 130; ++frame)
        tight->frame(1.0 / 120.0);
    EXPECT_EQ(tight->banner(), "");
}

// A replay watched in the window keeps the same budget, and its line says so too: the
// replay's own line, then the slow motion, gone a second after the budget stops cutting.
TEST(TickBudget, AReplayHeldBackByTheBudgetSaysSlowMotion) {
    std::string error;
    auto context = ui::createHeadlessContext(320, 180, ui::HeadlessBackend::Auto, error);
    ASSERT_NE(context, nullptr) << error;
    ui::GameScreenDef def;
    def.levelFile = (test_game::kRoot / "levels/05_castle.json").string();
    def.levelsFolder = (test_game::kRoot / "levels").string();
    def.replayFile = (test_game::kRoot / "tests/replays/05_castle.replay.json").string();
    def.tickBudgetSeconds = 0.0;
    auto screen = std::make_unique<ui::GameScreen>(*context, nullptr, def);
    screen->frame(1.0 / 120.0); // owed one tick: under any budget
    EXPECT_EQ(screen->banner().find("SLOW MOTION"), std::string::npos) << screen->banner();
    for (int frame = 0; frame < 10; ++frame)
        screen->frame(0.25); // owed 30 ticks, runs one
    const std::string slow = screen->banner();
    EXPECT_EQ(slow.rfind("REPLAY x1  0.1 s  SLOW MOTION: a tick of 8 ms takes ", 0), 0u) << slow;
    for (int frame = 0; frame < 130; ++frame)
        screen->frame(1.0 / 120.0);
    EXPECT_EQ(screen->banner().find("SLOW MOTION"), std::string::npos) << screen->banner();
}
