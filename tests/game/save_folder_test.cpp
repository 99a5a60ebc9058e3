// The game's own folder (game/files/save_folder.h): a folder that takes files keeps the
// replays in its replays/ folder and says nothing; one that cannot be written (a file
// where the folder should be, /proc; both refuse root too) says once where and why
// nothing will be saved, and the replays go to a temporary folder it names. And the
// advisory lock two windows share (game/files/file_lock.h).
#include "game/files/file_lock.h"
#include "game/files/save_folder.h"
#include "scratch.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

fs::path freshFolder(const std::string& name) { return scratchFolder("save-" + name); }

TEST(SaveFolder, AFolderThatTakesFilesKeepsEverythingAndSaysNothing) {
    const fs::path dir = freshFolder("ok");
    const game::SaveFolder saves((dir / "artillery").string());
    EXPECT_TRUE(saves.writable());
    EXPECT_EQ(saves.notice(), "");
    EXPECT_EQ(saves.replaysFolder(), (dir / "artillery" / "replays").string());
    EXPECT_TRUE(fs::is_directory(saves.replaysFolder()));
    EXPECT_EQ(saves.fileToWrite("settings.json"), (dir / "artillery" / "settings.json").string());
    fs::remove_all(dir);
}

TEST(SaveFolder, NowhereKeepsNothingAndSaysNothing) {
    const game::SaveFolder saves{""};
    EXPECT_FALSE(saves.writable());
    EXPECT_EQ(saves.notice(), "");
    EXPECT_EQ(saves.replaysFolder(), "");
    EXPECT_EQ(saves.fileToWrite("settings.json"), "");
}

/// $XDG_CONFIG_HOME is a file: the game's folder would be under it.
TEST(SaveFolder, AFolderUnderAFileSaysWhyAndNamesTheTemporaryReplaysFolder) {
    const fs::path dir = freshFolder("file");
    const fs::path config = dir / "config";
    std::ofstream(config.string()) << "not a folder";
    game::SaveFolder saves((config / "artillery").string());
    EXPECT_FALSE(saves.writable());
    EXPECT_EQ(saves.fileToWrite("settings.json"), "");
    const std::string& notice = saves.notice();
    EXPECT_EQ(notice.rfind("nothing will be saved in " + (config / "artillery").string() + " (", 0),
              0u)
        << notice;
    EXPECT_NE(notice.find(config.string() + "' is not a folder)"), std::string::npos) << notice;
    ASSERT_NE(saves.replaysFolder(), "");
    EXPECT_NE(notice.find("replays go to " + saves.replaysFolder() + " for this run"),
              std::string::npos)
        << notice;
    EXPECT_TRUE(fs::is_directory(saves.replaysFolder()));
    std::ofstream((fs::path(saves.replaysFolder()) / "x.json").string()) << "{}";
    EXPECT_TRUE(fs::exists(fs::path(saves.replaysFolder()) / "x.json"));
    EXPECT_NE(saves.failedOnce("the replay", "disk full"), "");
    EXPECT_EQ(saves.failedOnce("the replay", "disk full"), "") << "said once";
    fs::remove_all(saves.replaysFolder());
    fs::remove_all(dir);
}

TEST(SaveFolder, AFolderThatTakesNoFileSaysWhy) {
    const game::SaveFolder saves("/proc/artillery");
    EXPECT_FALSE(saves.writable());
    EXPECT_NE(saves.notice().find("nothing will be saved in /proc/artillery"), std::string::npos)
        << saves.notice();
    ASSERT_NE(saves.replaysFolder(), "");
    EXPECT_TRUE(fs::is_directory(saves.replaysFolder()));
    fs::remove_all(saves.replaysFolder());
}

TEST(FileLock, ASecondHolderWaitsAndIsToldWhoHoldsIt) {
    const fs::path dir = freshFolder("lock");
    const std::string lockFile = game::lockFileOf((dir / "progress.json").string());
    EXPECT_EQ(lockFile, (dir / "progress.json.lock").string());
    {
        const game::FileLock first(lockFile, 1.0);
        ASSERT_TRUE(first.locked()) << first.why();
        const game::FileLock second(lockFile, 0.05);
        EXPECT_FALSE(second.locked());
        EXPECT_NE(second.why().find("another process has held " + lockFile), std::string::npos)
            << second.why();
    }
    const game::FileLock again(lockFile, 0.05);
    EXPECT_TRUE(again.locked()) << "released with its holder";
    const game::FileLock nowhere("/proc/artillery.lock", 0.05);
    EXPECT_FALSE(nowhere.locked());
    EXPECT_NE(nowhere.why().find("cannot open the lock file /proc/artillery.lock"),
              std::string::npos)
        << nowhere.why();
    fs::remove_all(dir);
}

} // namespace
