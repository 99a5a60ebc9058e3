// The player's files (ui/game/player_files.h) when two windows of the game share them,
// and when the settings folder cannot be written:
// - settings merge key by key: each window's own changes win, another window's change
//   of a key this one did not touch is kept; two processes changing different keys
//   against one file both find theirs;
// - a settings folder that cannot be written (a file where it should be; /proc: both
//   refuse root too) is said once, nothing is written, and the game plays on: a level
//   opens, a shot is fired and its turn's replay goes to the temporary folder named.
#include "../game/processes.h"
#include "../game/scratch.h"
#include "headless_game.h"

#include "game/files/text_file.h"
#include "ui/game/player_files.h"
#include "ui/game/player_settings.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace fs = std::filesystem;

namespace {

fs::path freshFolder(const std::string& name) { return scratchFolder("files-" + name); }

TEST(PlayerFiles, SettingsMergeKeyByKeyTheLastChangeWinning) {
    const fs::path dir = freshFolder("merge");
    const std::string file = (dir / "settings.json").string();
    ui::PlayerSettings baseA, baseB; // two windows open on no file: the defaults
    ui::PlayerSettings mineA = baseA, mineB = baseB;
    mineA.difficulty = game::Difficulty::Hard; // window A changes the difficulty
    mineA.sound.master = 0.25;
    ASSERT_EQ(ui::savePlayerSettingsMerged(file, baseA, mineA), "");
    mineB.screenShake = false; // window B, which never touched the difficulty
    ASSERT_EQ(ui::savePlayerSettingsMerged(file, baseB, mineB), "");
    EXPECT_EQ(mineB.difficulty, game::Difficulty::Hard) << "A's change, taken in by B";
    std::string warning;
    ui::PlayerSettings back = ui::loadPlayerSettings(file, warning);
    EXPECT_EQ(back.difficulty, game::Difficulty::Hard);
    EXPECT_EQ(back.sound.master, 0.25);
    EXPECT_FALSE(back.screenShake);
    // A changes the difficulty again, later: the last change of the key wins.
    mineB.difficulty = game::Difficulty::Easy;
    ASSERT_EQ(ui::savePlayerSettingsMerged(file, baseB, mineB), "");
    mineA.difficulty = game::Difficulty::Normal;
    ASSERT_EQ(ui::savePlayerSettingsMerged(file, baseA, mineA), "");
    back = ui::loadPlayerSettings(file, warning);
    EXPECT_EQ(back.difficulty, game::Difficulty::Normal);
    EXPECT_FALSE(back.screenShake) << "B's choice, which A never changed, is kept";
    // A file another program damaged is left as it is.
    game::writeFileAtomically(file, "{\"format\": 7}");
    EXPECT_NE(ui::savePlayerSettingsMerged(file, baseA, mineA), "");
    EXPECT_EQ(game::readFile(file), "{\"format\": 7}");
    fs::remove_all(dir);
}

TEST(PlayerFiles, TwoProcessesChangingDifferentSettingsKeepBoth) {
    const fs::path dir = freshFolder("two");
    const std::string file = (dir / "settings.json").string();
    constexpr int kSaves = 30;
    auto change = [&](bool first) {
        ui::PlayerSettings base, mine;
        for (int i = 0; i < kSaves; ++i) {
            if (first)
                mine.sound.master = 0.01 * (i + 1);
            else
                mine.sound.effects = 0.02 * (i + 1);
            if (!ui::savePlayerSettingsMerged(file, base, mine).empty()) return 1;
        }
        return 0;
    };
    runInProcesses(2, [&](int k) { return change(k == 0); });
    std::string warning;
    const ui::PlayerSettings back = ui::loadPlayerSettings(file, warning);
    EXPECT_EQ(warning, "");
    EXPECT_EQ(back.sound.master, 0.01 * kSaves);
    EXPECT_EQ(back.sound.effects, 0.02 * kSaves);
    fs::remove_all(dir);
}

TEST(PlayerFiles, AnUnwritableFolderIsSaidOnceAndNothingIsWritten) {
    const fs::path dir = freshFolder("unwritable");
    std::ofstream((dir / "config").string()) << "a file where the folder should be";
    const std::string folder = (dir / "config" / "artillery").string();
    testing::internal::CaptureStderr();
    ui::PlayerFiles files({folder, "", false});
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_NE(files.warning().find("nothing will be saved in " + folder), std::string::npos)
        << files.warning();
    EXPECT_EQ(said.find("artillery: "), said.rfind("artillery: ")) << "said once: " << said;
    files.progress().record("01_earth_basics.json", 100, 1, false);
    testing::internal::CaptureStderr();
    files.save(ui::ViewControls{});
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << "nothing to save to, and nothing more to say";
    ASSERT_NE(files.replaysFolder(), "");
    EXPECT_TRUE(fs::is_directory(files.replaysFolder()));
    fs::remove_all(files.replaysFolder());
    fs::remove_all(dir);
}

// The case that closed the game: a level chosen with the settings folder on /proc. It
// opens, a shot is fired, and the turn's replay is saved in the temporary folder named.
TEST(PlayerFiles, TheGamePlaysOverAFolderItCannotWrite) {
    testing::internal::CaptureStderr();
    test_game::HeadlessGame game("01_earth_basics.json", 320, 200, "/proc/artillery");
    const std::string said = testing::internal::GetCapturedStderr();
    ASSERT_NE(game.screen, nullptr);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(said, m, std::regex("replays go to (\\S+) for this run")))
        << said;
    const fs::path replays = m[1].str();
    EXPECT_NE(said.find("nothing will be saved in /proc/artillery"), std::string::npos) << said;
    ui::GameScreen& screen = *game.screen;
    test_game::tap(screen, SDLK_RETURN); // fire at the cannon's aim
    const game::Match& live = screen.session()->match();
    // The flight and the turn's end simulated without drawing (the window's own warm-up).
    for (int i = 0; i < 240 && (live.shotsFired() == 0 || live.shell()); ++i)
        screen.warmUp(0.25);
    screen.warmUp(5.0); // past the turn's end
    screen.frame(1.0 / 60.0);
    EXPECT_EQ(live.shotsFired(), 1);
    EXPECT_TRUE(fs::exists(replays / "01_earth_basics-last.json"))
        << "the turn's replay, in the temporary folder";
    game.screen.reset();
    fs::remove_all(replays);
}

} // namespace
