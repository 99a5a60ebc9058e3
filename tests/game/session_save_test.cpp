// A session saves its recording at every turn's end. A save that fails (a disk that
// filled, a folder removed) stops a headless run with an exception its verb reports
// (exit 3); the game's window gives the session a callback instead, and the match plays
// on with its recording in memory, whole, saved again at the next turn's end. And a
// replay whose commands the match refuses is verified with each refusal as a warning.
#include "game/level.h"
#include "game/replay.h"
#include "game/session.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

using namespace game;

namespace {
const std::filesystem::path kSource = ARTILLERY_SOURCE_DIR;

/// Steps the computer through its first shot of 01_earth_basics to the turn's end.
void playFirstTurn(Session& s) {
    for (int i = 0; i < 120 * 60 && s.match().shotsFired() == 0; ++i) s.step();
    for (int i = 0; i < 120 * 60 && s.match().shell(); ++i) s.step();
    for (int i = 0; i < 120 * 10; ++i) s.step(); // past the turn's end
}

SessionOptions autoplayed() {
    SessionOptions o;
    o.autoplay = true;
    return o;
}

SessionOptions unsaveable() {
    SessionOptions o;
    o.autoplay = true;
    o.recordFile = "/proc/artillery-session.json"; // refuses root too
    return o;
}
} // namespace

TEST(SessionSave, AFailedSaveThrowsWhereNobodyListens) {
    Session s(loadLevel((kSource / "levels/01_earth_basics.json").string()), unsaveable());
    EXPECT_THROW(playFirstTurn(s), std::runtime_error);
}

TEST(SessionSave, AFailedSaveIsToldAndTheMatchPlaysOn) {
    SessionOptions o = unsaveable();
    std::vector<std::string> told;
    o.onSaveFailure = [&](const std::string& why) { told.push_back(why); };
    Session s(loadLevel((kSource / "levels/01_earth_basics.json").string()), o);
    ASSERT_NO_THROW(playFirstTurn(s));
    ASSERT_GE(told.size(), 1u);
    EXPECT_NE(told[0].find("/proc/artillery-session.json"), std::string::npos) << told[0];
    EXPECT_GE(s.match().shotsFired(), 1);
    EXPECT_FALSE(s.recording().commands.empty()) << "the recording is whole, in memory";
    const Level level = loadLevel((kSource / "levels/01_earth_basics.json").string());
    EXPECT_TRUE(verifyReplay(level, s.finishedRecording()).ok);
}

// Selecting a weapon the level lacks changes nothing, so the replay still verifies; the
// refusal is reported instead of passing in silence.
TEST(ReplayVerify, ARefusedCommandIsAWarning) {
    const Level level = loadLevel((kSource / "levels/01_earth_basics.json").string());
    Session s(level, autoplayed());
    for (int i = 0; i < 240; ++i) s.step();
    Replay r = s.finishedRecording();
    EXPECT_TRUE(verifyReplay(level, r).ignored.empty());
    Command nuke;
    nuke.tick = 0;
    nuke.kind = CommandKind::Select;
    nuke.text = "nuke";
    r.commands.insert(r.commands.begin(), nuke);
    const VerifyResult v = verifyReplay(level, r);
    EXPECT_TRUE(v.ok) << "a refused command changes nothing";
    ASSERT_EQ(v.ignored.size(), 1u);
    EXPECT_EQ(v.ignored[0].rfind("tick 0: select 'nuke' refused: ", 0), 0u) << v.ignored[0];
}
