// Levels: every shipped level loads; every file of the bad corpus is refused with the
// message it must produce, naming the file and the JSON path.
#include "corpus.h"
#include "game/files/text_file.h"
#include "game/level.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace game;

namespace {
const fs::path kSource = ARTILLERY_SOURCE_DIR;
}

TEST(Levels, EveryShippedLevelLoads) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(kSource / "levels")) {
        // campaign.json orders the levels into chapters (campaign_test.cpp); it is no level.
        if (entry.path().extension() != ".json" || entry.path().filename() == "campaign.json")
            continue;
        ++count;
        EXPECT_NO_THROW({
            const Level l = loadLevel(entry.path().string());
            EXPECT_FALSE(l.name.empty());
            EXPECT_FALSE(l.lesson.empty()) << entry.path() << " should say what it shows";
            EXPECT_EQ(l.contentHash.size(), 16u);
        }) << entry.path();
    }
    EXPECT_GE(count, 10) << "the game ships at least ten levels";
}

TEST(Levels, ParsesEveryField) {
    const std::string text = R"({
      "format": 1, "name": "All", "mode": "duel", "lesson": "x",
      "world": {"min": [-5, -5], "max": [100, 50]},
      "physics": {"planet": "mars", "air_density": 0.02, "drag": true,
                  "wind": {"min": -3, "max": 4}, "water_level": -1},
      "terrain": {"points": [[-5, 0], [100, 2]], "destructible": false, "material": "ground"},
      "obstacles": [{"shape": "polygon", "points": [[0, 0], [0, 1], [1, 1], [1, 0]]},
                    {"shape": "circle", "center": [5, 5], "radius": 2}],
      "cannons": [{"position": [1, 1], "player": "1", "projectiles": ["golf-ball"]},
                  {"position": [90, 2], "player": "cpu", "angle_deg": 135}],
      "targets": [{"position": [50, 3], "path": [[50, 3], [60, 3]], "speed_mps": 2}],
      "blocks": [{"position": [40, 1], "size": [2, 1], "target": true}],
      "ropes": [{"from": [10, 10], "to": [20, 10], "segments": 5, "sag": 0.1}],
      "blobs": [{"center": [30, 5], "points": 8}],
      "shots": 3, "seed": 42})";
    const Level l = parseLevel("all.json", text);
    EXPECT_EQ(l.mode, Mode::Duel);
    EXPECT_EQ(l.physics.gravity, 3.71);
    EXPECT_EQ(l.physics.windMin, -3.0);
    EXPECT_TRUE(l.physics.water);
    EXPECT_FALSE(l.terrain.destructible);
    // A clockwise polygon is stored counter-clockwise.
    ASSERT_EQ(l.obstacles[0].points.size(), 4u);
    EXPECT_EQ(l.obstacles[0].points[0], (Vec2{1, 0}));
    EXPECT_EQ(l.obstacles[0].points[1], (Vec2{1, 1}));
    EXPECT_EQ(l.obstacles[1].radius, 2.0);
    EXPECT_EQ(l.cannons[1].player, "cpu");
    EXPECT_EQ(l.cannons[1].projectiles, std::vector<std::string>{"cannonball"});
    EXPECT_EQ(l.targets[0].path.size(), 2u);
    EXPECT_TRUE(l.blocks[0].target);
    EXPECT_EQ(l.ropes[0].segments, 5);
    EXPECT_EQ(l.blobs[0].points, 8);
    EXPECT_EQ(l.seed, 42u);
    EXPECT_EQ(l.contentHash, contentHash(text));
}

TEST(Levels, BadCorpusGivesTheExpectedMessages) {
    const int cases = checkBadCorpus(kSource / "tests/data/bad_levels",
                                     [](const std::string& f) { loadLevel(f); });
    EXPECT_GE(cases, 40);
}

TEST(Levels, MissingFileSaysSo) {
    try {
        loadLevel("/nonexistent/level.json");
        FAIL();
    } catch (const LoadError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot open the file"), std::string::npos);
    }
}

TEST(AtomicWrite, ReplacesWholeFileAndLeavesNoTemporary) {
    const fs::path dir = fs::temp_directory_path() / "artillery_atomic_test";
    fs::create_directories(dir);
    const fs::path file = dir / "settings.json";
    writeFileAtomically(file.string(), "old");
    writeFileAtomically(file.string(), "new contents");
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_EQ(s.str(), "new contents");
    int entries = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        (void)e;
        ++entries;
    }
    EXPECT_EQ(entries, 1) << "no temporary file left behind";
    fs::remove_all(dir);
}
