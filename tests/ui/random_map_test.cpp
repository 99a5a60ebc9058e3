// The level select's Random map: the map is written into the player's maps folder under
// a name with its mode, seed and difficulty, and is byte for byte what `artillery
// generate` writes for the same seed; a folder that cannot be written says why.
#include "game/files/text_file.h"
#include "game/generate/level_generator.h"
#include "ui/game/random_map.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

namespace {

TEST(RandomMap, WritesTheGeneratedMapIntoThePlayersFolder) {
    const auto settings = std::filesystem::temp_directory_path() /
                          ("artillery-random-map-test-" + std::to_string(::getpid()));
    std::filesystem::remove_all(settings);
    const std::string folder = ui::randomMapsFolder(settings.string());
    EXPECT_EQ(folder, (settings / "maps").string());
    std::string status;
    const auto file = ui::writeRandomMap({12, true}, game::Difficulty::Easy, folder, status);
    ASSERT_TRUE(file) << status;
    EXPECT_EQ(*file, (settings / "maps/random_duel_12_easy.json").string());
    game::generate::GenerateDef def;
    def.seed = 12;
    def.mode = game::Mode::Duel;
    def.difficulty = game::Difficulty::Easy;
    EXPECT_EQ(game::readFile(*file), game::generate::generateLevel(def).text);
    EXPECT_NE(status.find("seed 12 (easy): candidate 1, saved as"), std::string::npos) << status;
    std::filesystem::remove_all(settings);
}

TEST(RandomMap, AnUnwritableFolderSaysWhy) {
    std::string status;
    const auto file =
        ui::writeRandomMap({3, true}, game::Difficulty::Easy, "/proc/no/maps", status);
    EXPECT_FALSE(file);
    EXPECT_EQ(status.rfind("not saved: ", 0), 0u) << status;
}

} // namespace
