// The game's data folder from a build: the source tree's levels, whatever the working
// folder (the installed layout, ../share/artillery beside the executable, is run from `/`
// by tests/package/installed_package.cmake); a replay's relative level is found there.
#include "game/files/data_folder.h"
#include "game/replay.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace {

const fs::path kSource = ARTILLERY_SOURCE_DIR;

/// Runs `body` with the working folder set to an empty scratch folder, then restores it.
template <class F> void fromAnEmptyFolder(F body) {
    const fs::path before = fs::current_path();
    const fs::path scratch = fs::temp_directory_path() / "artillery_data_folder_test";
    fs::create_directories(scratch);
    fs::current_path(scratch);
    body();
    fs::current_path(before);
}

} // namespace

TEST(DataFolder, ABuildFindsTheSourceTreesLevelsFromAnyFolder) {
    fromAnEmptyFolder([] {
        EXPECT_TRUE(fs::equivalent(game::dataFolder(), kSource));
        EXPECT_TRUE(fs::equivalent(game::levelsFolder(), kSource / "levels"));
        EXPECT_TRUE(
            fs::equivalent(game::shippedLevel("10_duel.json"), kSource / "levels/10_duel.json"));
    });
}

TEST(DataFolder, FromTheSourceTreeTheLevelsFolderIsWrittenRelative) {
    const fs::path before = fs::current_path();
    fs::current_path(kSource);
    EXPECT_EQ(game::levelsFolder(), "levels") << "so a game recorded here names levels/NAME.json";
    fs::current_path(before);
}

TEST(DataFolder, AReplayOutsideTheTreeFindsItsShippedLevel) {
    // The golden names "levels/05_castle.json": not beside the copy, nor above it.
    const fs::path copy =
        fs::temp_directory_path() / "artillery_data_folder_test_castle.replay.json";
    fs::copy_file(kSource / "tests/replays/05_castle.replay.json", copy,
                  fs::copy_options::overwrite_existing);
    fromAnEmptyFolder([&] {
        const game::Replay r = game::loadReplay(copy.string());
        const game::Level level = game::levelForReplay(copy.string(), r);
        EXPECT_TRUE(game::verifyReplay(level, r).ok);
    });
    fs::remove(copy);
}
