// The level writer: every shipped level, written and loaded again, is the same level
// field by field; the written file passes the loader `check` uses; writing is a fixed
// point (the written text, loaded and written again, is the same bytes).
#include "game/files/text_file.h"
#include "game/level.h"
#include "game/level_write.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using namespace game;

namespace {
const fs::path kSource = ARTILLERY_SOURCE_DIR;

/// The level without where it came from: what two files with the same content share.
Level content(Level l) {
    l.file.clear();
    l.contentHash.clear();
    return l;
}
} // namespace

TEST(LevelWrite, EveryShippedLevelRoundTrips) {
    const fs::path dir = fs::temp_directory_path() / "artillery_level_write_test";
    fs::create_directories(dir);
    int count = 0;
    for (const auto& entry : fs::directory_iterator(kSource / "levels")) {
        // campaign.json orders the levels; it is not one.
        if (entry.path().extension() != ".json" || entry.path().filename() == "campaign.json")
            continue;
        ++count;
        const Level original = loadLevel(entry.path().string());
        const fs::path written = dir / entry.path().filename();
        saveLevel(written.string(), original);
        Level again;
        ASSERT_NO_THROW(again = loadLevel(written.string())) << written;
        EXPECT_TRUE(content(again) == content(original)) << entry.path();
        EXPECT_EQ(again.contentHash, contentHash(levelToJson(original))) << entry.path();
        EXPECT_EQ(levelToJson(again), levelToJson(original)) << entry.path();
    }
    EXPECT_GE(count, 10);
    fs::remove_all(dir);
}

TEST(LevelWrite, EveryOptionalPartSurvives) {
    // Fields the shipped levels may not use: water, a steady wind, counted projectiles,
    // a moving target, a rope tied to a block, a circle and a polygon obstacle.
    const std::string text = R"({
      "format": 1, "name": "all parts", "mode": "practice", "lesson": "l", "description": "d",
      "world": {"min": [-10, -5], "max": [90, 60]},
      "physics": {"gravity": 3.71, "air_density": 0.02, "drag": false, "wind": 2.5,
                  "water_level": 0.25},
      "terrain": {"points": [[-10, 0], [0.1, 1.3], [90, 0.7]], "destructible": false,
                  "material": "steel"},
      "obstacles": [{"shape": "circle", "center": [30, 20], "radius": 1.5},
                    {"shape": "polygon", "points": [[40, 10], [42, 10], [41, 12]],
                     "material": "ground"},
                    {"shape": "polyline", "points": [[50, 2], [50, 9]]}],
      "cannons": [{"position": [2, 3], "angle_deg": 30, "max_speed_mps": 70,
                   "speed_mps": 12.5, "player": "1",
                   "projectiles": ["cannonball", {"name": "mortar", "count": 2}]}],
      "targets": [{"position": [60, 8], "radius": 0.75, "points": 250,
                   "path": [[60, 8], [60, 20]], "speed_mps": 1.25}],
      "blocks": [{"position": [70, 3], "size": [2, 2], "angle_deg": 5, "material": "stone",
                  "density": 2400, "target": true}],
      "ropes": [{"from": [65, 30], "to": [70, 3.5], "segments": 7, "sag": 0.1,
                 "pin_to": false, "mass_per_segment": 0.3, "to_block": 0}],
      "blobs": [{"center": [80, 5], "radius": 1.2, "points": 9, "stiffness": 500,
                 "mass": 3, "target": true}],
      "shots": 7, "seed": 9007199254740993
    })";
    const Level original = parseLevel("all.json", text);
    const Level again = parseLevel("written.json", levelToJson(original));
    EXPECT_TRUE(content(again) == content(original));
    EXPECT_EQ(again.seed, 9007199254740993ull) << "seeds above 2^53 are written as integers";
    ASSERT_EQ(again.cannons[0].projectileCounts.size(), 2u);
    EXPECT_EQ(again.cannons[0].projectileCounts[1], 2);
    EXPECT_EQ(again.ropes[0].toBlock, 0);
    EXPECT_TRUE(again.physics.water);
}

TEST(LevelWrite, ShortestExactNumbers) {
    // 15.1 and 37/3 read back bit for bit; a point stays on one line.
    Level l = loadLevel((kSource / "levels/01_earth_basics.json").string());
    l.cannons[0].position = {15.1, 37.0 / 3.0};
    const std::string text = levelToJson(l);
    EXPECT_NE(text.find("\"position\": [15.1, 12.333333333333334]"), std::string::npos) << text;
    EXPECT_EQ(parseLevel("w.json", text).cannons[0].position, l.cannons[0].position);
}

TEST(LevelWrite, UnwritableFolderSaysWhere) {
    const Level l = loadLevel((kSource / "levels/01_earth_basics.json").string());
    try {
        saveLevel("/nonexistent/folder/out.json", l);
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/folder/out.json"), std::string::npos);
    }
}
