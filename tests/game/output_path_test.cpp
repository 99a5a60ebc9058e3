// Outputs are checked before the work (game/files/output_path.h): a probe file in the
// folder, removed, so a folder is judged by what it does. The tests run as root in CI,
// which ignores permission bits: the folders that refuse here refuse root too (/proc, a
// path through a regular file).
#include "game/files/output_path.h"
#include "scratch.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

/// before 'PATH' after, as the messages quote a path (appended piece by piece: g++ 12
/// warns of a bogus overflow in "..." + std::string here).
std::string quoted(const std::string& before, const fs::path& path, const std::string& after) {
    std::string q = before;
    q += "'";
    q += path.string();
    q += "'";
    q += after;
    return q;
}

fs::path freshFolder(const std::string& name) { return scratchFolder("output-" + name); }

TEST(OutputPath, AWritableFolderTakesTheFileAndTheProbeLeavesNothing) {
    const fs::path dir = freshFolder("ok");
    EXPECT_EQ(game::unwritableFile((dir / "x.json").string()), "");
    EXPECT_TRUE(fs::is_empty(dir)) << "the probe file is removed";
    std::ofstream((dir / "there.json").string()) << "{}";
    EXPECT_EQ(game::unwritableFile((dir / "there.json").string()), "") << "replaced, when written";
    fs::remove_all(dir);
}

TEST(OutputPath, AMissingFolderIsNamed) {
    EXPECT_EQ(game::unwritableFile("/nonexistent-artillery/dir/x.json"),
              "the folder '/nonexistent-artillery/dir' does not exist");
}

TEST(OutputPath, APathThroughARegularFileIsNoFolder) {
    const fs::path dir = freshFolder("file");
    const fs::path file = dir / "plain.txt";
    std::ofstream(file.string()) << "text";
    EXPECT_EQ(game::unwritableFile((file / "x.json").string()),
              quoted("", file, " is not a folder"));
    EXPECT_EQ(game::unwritableFile((file / "sub" / "x.json").string()),
              quoted("", file, " is not a folder"));
    fs::remove_all(dir);
}

TEST(OutputPath, AFolderThatTakesNoNewFileIsRefusedEvenForRoot) {
    const std::string why = game::unwritableFile("/proc/x.json");
    EXPECT_EQ(why.rfind("the folder '/proc' does not take new files: ", 0), 0u) << why;
}

TEST(OutputPath, AFolderOrADeviceIsNoFileToWrite) {
    const fs::path dir = freshFolder("dir");
    EXPECT_EQ(game::unwritableFile(dir.string()), quoted("", dir, " is a folder, not a file"));
    EXPECT_EQ(game::unwritableFile("/dev/null"), "'/dev/null' is not a regular file");
    EXPECT_EQ(game::unwritableFile(""), "an empty file name");
    fs::remove_all(dir);
}

TEST(OutputPath, AnOutputFolderIsMadeFirstWhereItCanBe) {
    const fs::path dir = freshFolder("made");
    EXPECT_EQ(game::unwritableFolder((dir / "a" / "b").string(), true), "");
    EXPECT_TRUE(fs::is_directory(dir / "a" / "b"));
    EXPECT_EQ(game::unwritableFolder((dir / "c").string(), false),
              quoted("the folder ", dir / "c", " does not exist"));
    EXPECT_EQ(game::unwritableFolder("/proc/artillery-frames", true).rfind(
                  "the folder '/proc/artillery-frames' cannot be made: ", 0),
              0u);
    EXPECT_FALSE(fs::exists("/proc/artillery-frames"));
    fs::remove_all(dir);
}

} // namespace
