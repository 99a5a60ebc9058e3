// Settings files: a damaged or hostile file gives one message naming the file, the JSON
// path and what was expected; the game plays on with the defaults and leaves the file
// as it is (nothing saved is lost).
#include "../game/corpus.h"
#include "ui/game/player_settings.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace {
const std::filesystem::path kRoot =
    std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();
} // namespace

TEST(PlayerSettingsFiles, BadCorpusGivesTheExpectedMessages) {
    const int cases = checkBadCorpus(kRoot / "tests/data/bad_settings", [](const std::string& f) {
        ui::parsePlayerSettings(f, game::readFile(f));
    });
    EXPECT_GE(cases, 12);
}

TEST(PlayerSettingsFiles, ADamagedFileIsReportedAndLeftAsItIs) {
    const auto dir = std::filesystem::temp_directory_path() / "artillery-bad-settings-test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string file = (dir / "settings.json").string();
    const std::string damaged =
        R"({"format": 1, "levels": {"01_earth_basics.json": {"stars": 9}}})";
    game::writeFileAtomically(file, damaged);
    std::string warning;
    const ui::PlayerSettings s = ui::loadPlayerSettings(file, warning);
    EXPECT_NE(warning.find("stars: expected a whole number in [0, 3], got 9"), std::string::npos)
        << warning;
    EXPECT_TRUE(s.results.empty());
    EXPECT_EQ(game::readFile(file), damaged) << "loading never writes";
    // Absent is not damaged: the first run has no warning.
    ui::loadPlayerSettings((dir / "none.json").string(), warning);
    EXPECT_EQ(warning, "");
    std::filesystem::remove_all(dir);
}

TEST(PlayerSettingsFiles, DrawTogglesRoundTripAndAreReadStrictly) {
    const auto dir = std::filesystem::temp_directory_path() / "artillery-draw-settings-test";
    std::filesystem::remove_all(dir);
    const std::string file = (dir / "settings.json").string();
    ui::PlayerSettings s;
    s.draw.trails = false;
    s.draw.forces = true;
    s.draw.cells = true;
    s.draw.models = true;
    ASSERT_EQ(ui::savePlayerSettings(file, s), "");
    std::string warning;
    const ui::PlayerSettings back = ui::loadPlayerSettings(file, warning);
    EXPECT_EQ(warning, "");
    EXPECT_EQ(back.draw, s.draw);
    EXPECT_FALSE(back.draw.velocities);
    // A file without "draw" keeps the defaults; a toggle the game does not have, or one
    // that is not a boolean, is refused with its path.
    EXPECT_EQ(ui::parsePlayerSettings("a.json", R"({"format": 1})").draw, ui::DrawChoices{});
    const auto message = [](const std::string& text) {
        try {
            ui::parsePlayerSettings("s.json", text);
        } catch (const game::LoadError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message(R"({"format": 1, "draw": {"force": true}})").find("s.json: $.draw"),
              std::string::npos)
        << message(R"({"format": 1, "draw": {"force": true}})");
    EXPECT_NE(message(R"({"format": 1, "draw": {"cells": 1}})").find("$.draw.cells"),
              std::string::npos)
        << message(R"({"format": 1, "draw": {"cells": 1}})");
    EXPECT_NE(
        message(R"({"format": 1, "draw": [true]})").find("expected an object of draw toggles"),
        std::string::npos);
    std::filesystem::remove_all(dir);
}

// The camera, shake and preview choices persist. Level results moved to the progress
// file (game/progress.h): an older file's are still read, to migrate them, but never
// written back.
TEST(PlayerSettingsFiles, CameraShakePreviewRoundTripAndOldResultsAreReadOnly) {
    const auto dir = std::filesystem::temp_directory_path() / "artillery-fx-settings-test";
    std::filesystem::remove_all(dir);
    const std::string file = (dir / "settings.json").string();
    ui::PlayerSettings s;
    EXPECT_TRUE(s.cameraFollow);
    EXPECT_TRUE(s.screenShake);
    EXPECT_FALSE(s.fullPreview) << "the launch arc by default";
    s.cameraFollow = false;
    s.screenShake = false;
    s.fullPreview = true;
    s.results["05_castle.json"].stars = 2;
    ASSERT_EQ(ui::savePlayerSettings(file, s), "");
    std::string warning;
    const ui::PlayerSettings back = ui::loadPlayerSettings(file, warning);
    EXPECT_EQ(warning, "");
    EXPECT_FALSE(back.cameraFollow);
    EXPECT_FALSE(back.screenShake);
    EXPECT_TRUE(back.fullPreview);
    EXPECT_TRUE(back.results.empty()) << "results live in progress.json now";
    const ui::PlayerSettings old = ui::parsePlayerSettings(
        "old.json", R"({"format": 1, "levels": {"05_castle.json": {"best_score": 350,
                       "stars": 3, "plays": 4, "won": true, "assisted": false}}})");
    ASSERT_EQ(old.results.count("05_castle.json"), 1u);
    EXPECT_EQ(old.results.at("05_castle.json").bestScore, 350);
    EXPECT_EQ(old.results.at("05_castle.json").stars, 3);
    EXPECT_EQ(old.results.at("05_castle.json").plays, 4);
    try {
        ui::parsePlayerSettings("s.json", R"({"format": 1, "camera_follow": "yes"})");
        ADD_FAILURE() << "accepted a string for a boolean";
    } catch (const game::LoadError& e) {
        EXPECT_NE(std::string(e.what()).find("$.camera_follow"), std::string::npos) << e.what();
    }
    std::filesystem::remove_all(dir);
}

// The Sound section's volumes and mute persist; a volume outside 0..1, a mute that is not
// a boolean, or a field the section lacks is refused with its path.
TEST(PlayerSettingsFiles, SoundVolumesRoundTripAndAreReadStrictly) {
    const auto dir = std::filesystem::temp_directory_path() / "artillery-sound-settings-test";
    std::filesystem::remove_all(dir);
    const std::string file = (dir / "settings.json").string();
    ui::PlayerSettings s;
    s.sound = {0.25, 0.5, 0.0, true};
    ASSERT_EQ(ui::savePlayerSettings(file, s), "");
    std::string warning;
    const ui::PlayerSettings back = ui::loadPlayerSettings(file, warning);
    EXPECT_EQ(warning, "");
    EXPECT_EQ(back.sound, s.sound);
    EXPECT_EQ(ui::parsePlayerSettings("a.json", R"({"format": 1})").sound, game::audio::SoundMix{});
    const auto message = [](const std::string& text) {
        try {
            ui::parsePlayerSettings("s.json", text);
        } catch (const game::LoadError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message(R"({"format": 1, "sound": {"ui": -0.1}})").find("$.sound.ui: expected a number in [0, 1]"),
              std::string::npos)
        << message(R"({"format": 1, "sound": {"ui": -0.1}})");
    EXPECT_NE(message(R"({"format": 1, "sound": {"mute": "yes"}})").find("$.sound.mute"),
              std::string::npos);
    EXPECT_NE(message(R"({"format": 1, "sound": {"music": 1}})").find("unknown field \"music\""),
              std::string::npos)
        << message(R"({"format": 1, "sound": {"music": 1}})");
    EXPECT_NE(message(R"({"format": 1, "sound": 0.5})").find("expected an object with master"),
              std::string::npos);
    std::filesystem::remove_all(dir);
}
