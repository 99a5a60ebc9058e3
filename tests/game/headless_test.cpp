// A headless run without a length (`artillery run LEVEL [--autoplay]`) plays until the
// match is over, or until a minute passes with no command given and no shot fired: an
// autoplayed level of long flights (the Moon: 82 s for four shots) is played to its end,
// and a sandbox, where the computer only passes its turns, stops after its minute.
#include "game/headless.h"
#include "game/level.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace game;

namespace {
const std::filesystem::path kSource = ARTILLERY_SOURCE_DIR;

HeadlessSummary autoplay(const std::string& name) {
    HeadlessOptions o;
    o.session.autoplay = true;
    o.session.difficulty = Difficulty::Hard;
    return runHeadless(loadLevel((kSource / "levels" / name).string()), o);
}
} // namespace

TEST(Headless, AnAutoplayedLevelOfLongFlightsIsPlayedToItsEnd) {
    const HeadlessSummary s = autoplay("02_moon.json");
    EXPECT_TRUE(s.over) << s.shots << " shots in " << s.ticks << " ticks";
    EXPECT_GT(s.ticks, 60u * 120u) << "longer than a minute, which used to cut it short";
    EXPECT_LT(s.ticks, kMaxRunTicks);
}

TEST(Headless, PassedTurnsAloneDoNotKeepARunGoing) {
    const HeadlessSummary s = autoplay("11_sandbox.json");
    EXPECT_FALSE(s.over) << "a sandbox has no end";
    EXPECT_EQ(s.shots, 0);
    EXPECT_EQ(s.ticks, 60u * 120u) << "a minute with no shot";
}
