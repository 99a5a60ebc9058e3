// The progress file: results and lessons read round trip; the best result keeps whether
// it was assisted; a damaged file is kept aside as FILE.damaged and no progress is used;
// saving is atomic (no temporary file left, an unwritable folder is reported); two
// windows' saves merge under a lock, so neither loses the other's results.
#include "game/files/text_file.h"
#include "game/progress.h"
#include "processes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace game;

namespace {
fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}
} // namespace

TEST(Progress, RoundTrip) {
    const fs::path dir = scratch("artillery-progress-roundtrip");
    const std::string file = (dir / "progress.json").string();
    Progress p;
    EXPECT_TRUE(p.record("levels/05_castle.json", 300, 2, false, true));
    EXPECT_TRUE(p.record("levels/10_duel.json", 0, 0, true));
    p.lessonsSeen = {"flight", "drag"};
    ASSERT_EQ(saveProgress(file, p), "");
    std::string warning;
    const Progress back = loadProgress(file, warning);
    EXPECT_EQ(warning, "");
    ASSERT_NE(back.result("05_castle.json"), nullptr);
    EXPECT_EQ(back.result("05_castle.json")->bestScore, 300);
    EXPECT_EQ(back.result("05_castle.json")->stars, 2);
    EXPECT_EQ(back.result("05_castle.json")->plays, 1);
    EXPECT_TRUE(back.result("05_castle.json")->assisted);
    EXPECT_TRUE(back.result("10_duel.json")->won);
    EXPECT_EQ(back.lessonsSeen, p.lessonsSeen);
    const std::string bytes = readFile(file);
    ASSERT_EQ(saveProgress(file, back), "");
    EXPECT_EQ(readFile(file), bytes) << "what is read is written back byte for byte";
    fs::remove_all(dir);
}

// Out of shots with no star, or a duel lost, is never a new best: not the first time,
// not with a higher score than before; the next game that earns a star is.
TEST(Progress, NothingEarnedIsNoNewBest) {
    Progress p;
    EXPECT_FALSE(p.record("levels/25_tower.json", 200, 0, false));
    EXPECT_FALSE(p.record("levels/25_tower.json", 300, 0, false));
    EXPECT_EQ(p.result("25_tower.json")->bestScore, 300);
    EXPECT_FALSE(p.record("levels/10_duel.json", 0, 0, false));
    EXPECT_TRUE(p.record("levels/25_tower.json", 250, 1, true));
}

// The best result remembers whether it was assisted (the level select says so); an
// unassisted result as good clears the mark, as do more stars without help.
TEST(Progress, AssistedMarkFollowsTheBestResult) {
    Progress p;
    EXPECT_TRUE(p.record("levels/01_earth_basics.json", 100, 1, true, true));
    EXPECT_TRUE(p.record("levels/01_earth_basics.json", 90, 1, true, false));
    EXPECT_FALSE(p.result("01_earth_basics.json")->assisted) << "as many stars without help";
    EXPECT_TRUE(p.record("levels/05_castle.json", 300, 2, true, true));
    EXPECT_FALSE(p.record("levels/05_castle.json", 200, 1, true, false));
    EXPECT_TRUE(p.result("05_castle.json")->assisted) << "one star unassisted is not as good";
    EXPECT_TRUE(p.record("levels/05_castle.json", 350, 3, true, false));
    EXPECT_FALSE(p.result("05_castle.json")->assisted);
    EXPECT_EQ(p.result("05_castle.json")->plays, 3);
    EXPECT_EQ(p.result("05_castle.json")->bestScore, 350);
}

TEST(Progress, ADamagedFileIsKeptAsideAndNoProgressIsUsed) {
    const fs::path dir = scratch("artillery-progress-damaged");
    const std::string file = (dir / "progress.json").string();
    const std::string damaged =
        R"({"format": 1, "levels": {"01_earth_basics.json": {"stars": 9}}})";
    writeFileAtomically(file, damaged);
    std::string warning;
    const Progress p = loadProgress(file, warning);
    EXPECT_TRUE(p.results.empty());
    EXPECT_NE(warning.find("progress.json: $.levels.01_earth_basics.json.stars: expected a whole "
                           "number in [0, 3], got 9"),
              std::string::npos)
        << warning;
    EXPECT_NE(warning.find("kept as " + file + ".damaged"), std::string::npos) << warning;
    EXPECT_FALSE(fs::exists(file)) << "moved aside, so the next save starts clean";
    EXPECT_EQ(readFile(file + ".damaged"), damaged) << "nothing the player had is lost";
    // Told once: the next load finds no file and starts quietly.
    loadProgress(file, warning);
    EXPECT_EQ(warning, "");
    // Truncated JSON is damaged too.
    writeFileAtomically(file, R"({"format": 1, "levels": {)");
    loadProgress(file, warning);
    EXPECT_NE(warning.find("progress.json"), std::string::npos) << warning;
    EXPECT_TRUE(fs::exists(file + ".damaged"));
    fs::remove_all(dir);
}

TEST(Progress, SavingIsAtomic) {
    const fs::path dir = scratch("artillery-progress-atomic");
    const std::string file = (dir / "deeper" / "progress.json").string();
    Progress p;
    p.record("02_moon.json", 500, 3, false);
    ASSERT_EQ(saveProgress(file, p), "") << "creates the folder";
    // Only the file itself is left: the temporary was renamed over it.
    int entries = 0;
    for (const auto& e : fs::directory_iterator(dir / "deeper")) {
        ++entries;
        EXPECT_EQ(e.path().filename(), "progress.json");
    }
    EXPECT_EQ(entries, 1);
    const std::string before = readFile(file);
    // A folder where the file should be: the save fails, says so, and the old file in
    // the other place is untouched.
    fs::create_directories(dir / "blocked" / "progress.json");
    const std::string err = saveProgress((dir / "blocked" / "progress.json").string(), p);
    EXPECT_NE(err, "");
    EXPECT_EQ(readFile(file), before);
    fs::remove_all(dir);
}

TEST(Progress, StrictReader) {
    const auto message = [](const std::string& text) {
        try {
            parseProgress("p.json", text);
        } catch (const LoadError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message(R"({"format": 1})"), "accepted");
    EXPECT_NE(message(R"({"format": 1, "lessons": []})").find("p.json: $"), std::string::npos);
    EXPECT_NE(message(R"({"format": 1, "lessons_seen": [3]})").find("$.lessons_seen[0]"),
              std::string::npos);
    EXPECT_NE(message(R"({"format": 1, "levels": {"a.json": {"stars": 2, "x": 1}}})")
                  .find("$.levels.a.json"),
              std::string::npos);
    EXPECT_NE(message(R"({"format": 2})").find("$.format"), std::string::npos);
}

// Results an older settings file kept move into the progress for the levels it has none
// of; a level played since keeps its own result.
TEST(Progress, AdoptsOlderResults) {
    Progress p;
    p.record("02_moon.json", 500, 3, false);
    std::map<std::string, LevelResult> older;
    older["02_moon.json"].stars = 1;
    older["05_castle.json"].stars = 2;
    older["05_castle.json"].bestScore = 320;
    EXPECT_TRUE(adoptOlderResults(p, older));
    EXPECT_EQ(p.result("02_moon.json")->stars, 3);
    EXPECT_EQ(p.result("05_castle.json")->stars, 2);
    EXPECT_EQ(p.result("05_castle.json")->bestScore, 320);
    EXPECT_FALSE(adoptOlderResults(p, older)) << "taken once";
}

// Two windows of the game share progress.json: each saves what it added merged into what
// the other saved meanwhile. Per level the best result; plays are the file's plus this
// run's new ones; lessons either has read.
TEST(Progress, AMergeKeepsTheBestResultAndAddsThisRunsPlays) {
    Progress base; // what both windows read at the start
    base.record("1.json", 100, 1, false);
    Progress disk = base; // the other window finished 1.json twice more, and 2.json
    disk.record("1.json", 250, 3, false, true);
    disk.record("1.json", 50, 0, false);
    disk.record("2.json", 80, 2, false);
    disk.lessonsSeen.insert("drag");
    Progress mine = base; // this window finished 1.json once, and 3.json
    mine.record("1.json", 200, 3, false, false);
    mine.record("3.json", 10, 0, true);
    mine.lessonsSeen.insert("flight");

    const Progress merged = mergeProgress(disk, base, mine);
    const LevelResult* one = merged.result("1.json");
    ASSERT_NE(one, nullptr);
    EXPECT_EQ(one->plays, 4) << "1 before, 2 in the other window, 1 here";
    EXPECT_EQ(one->bestScore, 250);
    EXPECT_EQ(one->stars, 3);
    EXPECT_FALSE(one->assisted) << "three stars here without an aid";
    ASSERT_NE(merged.result("2.json"), nullptr);
    EXPECT_EQ(merged.result("2.json")->stars, 2);
    ASSERT_NE(merged.result("3.json"), nullptr);
    EXPECT_TRUE(merged.result("3.json")->won);
    EXPECT_EQ(merged.lessonsSeen, (std::set<std::string>{"drag", "flight"}));
    // Merged again with nothing new: the same.
    const Progress again = mergeProgress(merged, merged, merged);
    EXPECT_EQ(again.result("1.json")->plays, 4);
}

TEST(Progress, ASavedMergeTakesInTheOtherWindowsResults) {
    const fs::path dir = scratch("artillery-progress-merge-" + std::to_string(::getpid()));
    const std::string file = (dir / "progress.json").string();
    Progress baseA, mineA, baseB, mineB; // two windows, both started with no file
    std::string warning;
    mineA.record("1.json", 100, 1, false);
    ASSERT_EQ(saveProgressMerged(file, baseA, mineA, warning), "");
    mineB.record("2.json", 200, 2, false);
    ASSERT_EQ(saveProgressMerged(file, baseB, mineB, warning), "");
    EXPECT_NE(mineB.result("1.json"), nullptr) << "window B now shows window A's result";
    mineA.record("1.json", 100, 1, false);
    ASSERT_EQ(saveProgressMerged(file, baseA, mineA, warning), "");
    const Progress back = loadProgress(file, warning);
    ASSERT_NE(back.result("1.json"), nullptr);
    ASSERT_NE(back.result("2.json"), nullptr);
    EXPECT_EQ(back.result("1.json")->plays, 2);
    EXPECT_EQ(back.result("2.json")->plays, 1);
    EXPECT_TRUE(fs::exists(file + ".lock")) << "the lock is on a sibling file, left in place";
    fs::remove_all(dir);
}

// Two processes finishing different levels against one file, each saving after every
// match, as two windows of the game do: the file ends with both levels and every play
// of each (without the lock and the merge, the last writer's whole file wins).
TEST(Progress, TwoProcessesFinishingDifferentLevelsKeepBoth) {
    const fs::path dir = scratch("artillery-progress-two-" + std::to_string(::getpid()));
    const std::string file = (dir / "progress.json").string();
    constexpr int kMatches = 40;
    auto play = [&](const std::string& level) {
        Progress base, mine;
        std::string warning;
        for (int i = 0; i < kMatches; ++i) {
            mine.record(level, 100 + i, 1 + i % 3, false);
            if (!saveProgressMerged(file, base, mine, warning).empty()) return 1;
        }
        return 0;
    };
    const char* levels[2] = {"levels/01_earth_basics.json", "levels/02_moon.json"};
    runInProcesses(2, [&](int k) { return play(levels[k]); });
    std::string warning;
    const Progress back = loadProgress(file, warning);
    EXPECT_EQ(warning, "");
    for (const char* level : levels) {
        const LevelResult* r = back.result(level);
        ASSERT_NE(r, nullptr) << level;
        EXPECT_EQ(r->plays, kMatches) << level;
        EXPECT_EQ(r->bestScore, 100 + kMatches - 1) << level;
        EXPECT_EQ(r->stars, 3) << level;
    }
    fs::remove_all(dir);
}
