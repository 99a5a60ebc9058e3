// The campaign: the shipped levels/campaign.json loads and is sound against the levels
// folder (every level exists and loads, every shipped level is in exactly one chapter or
// listed outside); bad files are refused naming the file and the JSON path; the unlock
// rules (level k+1 after one star on level k, a chapter after N stars in the one before).
#include "game/campaign.h"
#include "game/files/text_file.h"
#include "game/level.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using namespace game;

namespace {
const fs::path kSource = ARTILLERY_SOURCE_DIR;

std::string refusal(const std::string& text) {
    try {
        parseCampaign("c.json", text);
    } catch (const LoadError& e) {
        return e.what();
    }
    return "accepted";
}

/// A levels folder of this test's own holding shipped levels, each under the name given:
/// {shipped file in levels/, name in the folder}.
fs::path levelsFolder(const std::string& name,
                      const std::vector<std::pair<std::string, std::string>>& levels) {
    const fs::path dir = fs::temp_directory_path() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& [shipped, as] : levels) fs::copy_file(kSource / "levels" / shipped, dir / as);
    return dir;
}

/// Two chapters of two levels; the second opens with 4 stars in the first.
Campaign twoChapters() {
    return parseCampaign("c.json", R"({"format": 1, "chapters": [
        {"id": "a", "title": "First", "lesson": "l", "formula": "f", "levels": ["1.json", "2.json"]},
        {"id": "b", "title": "Second", "lesson": "l", "formula": "f", "stars_to_open": 4,
         "levels": ["3.json", "4.json"]}], "outside": ["sandbox.json"]})");
}
} // namespace

TEST(Campaign, ShippedCampaignIsSound) {
    const Campaign c = loadCampaign((kSource / "levels/campaign.json").string());
    EXPECT_EQ(c.chapters.size(), 9u);
    std::size_t levels = 0;
    for (const Chapter& ch : c.chapters) {
        EXPECT_GE(ch.levels.size(), 3u) << ch.id;
        EXPECT_LE(ch.levels.size(), 8u) << ch.id << ": one page of tiles";
        EXPECT_FALSE(ch.lesson.empty()) << ch.id;
        EXPECT_FALSE(ch.formula.empty()) << ch.id;
        EXPECT_FALSE(ch.picture.empty()) << ch.id << ": every lesson has its picture";
        levels += ch.levels.size();
    }
    EXPECT_GE(levels, 44u) << "the campaign has the arsenal's eight levels besides the rest";
    const std::vector<std::string> problems = campaignProblems(c, (kSource / "levels").string());
    for (const std::string& p : problems)
        ADD_FAILURE() << p;
    // From the closed-form parabola to stiff springs; the arsenal once drag and restitution
    // have been taught.
    const char* order[] = {"flight",  "worlds", "drag",      "bounce", "arsenal",
                           "springs", "rigid",  "stability", "finals"};
    for (std::size_t i = 0; i < c.chapters.size() && i < std::size(order); ++i)
        EXPECT_EQ(c.chapters[i].id, order[i]);
}

namespace {

std::size_t characters(const std::string& s) {
    std::size_t n = 0;
    for (const unsigned char ch : s) n += (ch & 0xC0) != 0x80; // not a UTF-8 continuation byte
    return n;
}

/// Sentences: ". " ("e.g." and decimals have no space after the point), "! ", "? ", and
/// the end of the text.
std::size_t sentences(const std::string& s) {
    std::size_t n = 1;
    for (std::size_t i = 0; i + 1 < s.size(); ++i)
        n += (s[i] == '.' || s[i] == '!' || s[i] == '?') && s[i + 1] == ' ';
    return n;
}

/// What a lesson must not hold: sources (they belong in docs/references.md), and
/// formulas in ASCII where the symbols exist.
std::string lessonProblem(const std::string& text) {
    for (const char* word : {"notes", "Millington", "section", "theta", "sqrt", "omega", "rho",
                             "^2", "+-", " pi ", "->", "degrees"})
        if (text.find(word) != std::string::npos) return std::string("holds \"") + word + "\"";
    return "";
}

} // namespace

TEST(Campaign, LessonsAreReadInTenSeconds) {
    const Campaign c = loadCampaign((kSource / "levels/campaign.json").string());
    for (const Chapter& ch : c.chapters) {
        EXPECT_LE(characters(ch.lesson), 400u) << ch.id;
        EXPECT_LE(sentences(ch.lesson), 3u) << ch.id << ": " << ch.lesson;
        EXPECT_EQ(lessonProblem(ch.lesson), "") << ch.id << ": " << ch.lesson;
        EXPECT_EQ(lessonProblem(ch.formula), "") << ch.id << ": " << ch.formula;
    }
}

TEST(Campaign, EveryChapterLevelTeachesOneIdea) {
    const Campaign c = loadCampaign((kSource / "levels/campaign.json").string());
    std::vector<std::string> files = c.outside;
    for (const Chapter& ch : c.chapters) files.insert(files.end(), ch.levels.begin(), ch.levels.end());
    for (const std::string& file : files) {
        const Level l = loadLevel((kSource / "levels" / file).string());
        EXPECT_FALSE(l.lesson.empty()) << file;
        EXPECT_LE(characters(l.lesson), 200u) << file << ": a lesson is one line";
        EXPECT_LE(sentences(l.lesson), 3u) << file << ": " << l.lesson;
        EXPECT_EQ(lessonProblem(l.lesson), "") << file << ": " << l.lesson;
        EXPECT_EQ(l.description.find("notes"), std::string::npos) << file << ": " << l.description;
    }
}

TEST(Campaign, ALessonPictureIsOneTheRendererDraws) {
    const std::string chapter = R"({"format": 1, "chapters": [{"id": "a", "title": "A",
        "lesson": "l", "formula": "f", "levels": ["1.json"])";
    const Campaign c = parseCampaign("c.json", chapter + R"(, "picture": "bounce"}]})");
    EXPECT_EQ(c.chapters[0].picture, "bounce");
    EXPECT_EQ(parseCampaign("c.json", chapter + "}]}").chapters[0].picture, "")
        << "a chapter without one draws none";
    const std::string refused = refusal(chapter + R"(, "picture": "sunset"}]})");
    EXPECT_NE(refused.find("c.json: $.chapters[0].picture: expected one of \"firing-solution\""),
              std::string::npos)
        << refused;
    EXPECT_NE(refused.find("\"sunset\""), std::string::npos) << refused;
    for (const LessonPicture& p : lessonPictures()) EXPECT_GT(std::string(p.shows).size(), 20u) << p.name;
}

TEST(Campaign, AChapterLessonPastFourHundredCharactersIsRefused) {
    const std::string longLesson(401, 'x');
    const std::string refused = refusal(R"({"format": 1, "chapters": [{"id": "a", "title": "A",
        "lesson": ")" + longLesson + R"(", "formula": "f", "levels": ["1.json"]}]})");
    EXPECT_NE(refused.find("$.chapters[0].lesson: expected a string of at most 400 characters"),
              std::string::npos)
        << refused;
}

TEST(Campaign, ProblemsNameTheFileAndPath) {
    const fs::path dir = levelsFolder("artillery-campaign-test",
                                      {{"01_earth_basics.json", "01_earth_basics.json"},
                                       {"02_moon.json", "02_moon.json"},
                                       {"11_sandbox.json", "11_sandbox.json"}});
    const Campaign c = parseCampaign("c.json", R"({"format": 1, "chapters": [
        {"id": "a", "title": "A", "lesson": "l", "formula": "f",
         "levels": ["01_earth_basics.json", "99_missing.json"]},
        {"id": "b", "title": "B", "lesson": "l", "formula": "f", "stars_to_open": 7,
         "levels": ["11_sandbox.json"]}]})");
    const std::vector<std::string> p = campaignProblems(c, dir.string());
    ASSERT_EQ(p.size(), 4u);
    EXPECT_NE(p[0].find("c.json: $.chapters[0].levels[1]: the level does not load"),
              std::string::npos)
        << p[0];
    EXPECT_NE(p[1].find("c.json: $.chapters[1].stars_to_open: expected at most 3"),
              std::string::npos)
        << p[1];
    EXPECT_NE(p[2].find("$.chapters[1].levels[0]: a sandbox"), std::string::npos) << p[2];
    EXPECT_NE(p[3].find("the level 02_moon.json is in no chapter"), std::string::npos) << p[3];
    fs::remove_all(dir);
}

TEST(Campaign, BadFilesAreRefusedWithThePath) {
    EXPECT_NE(refusal(R"({"format": 2, "chapters": []})").find("c.json: $.format"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"format": 1, "chapters": []})")
                  .find("$.chapters: expected at least 1 element(s)"),
              std::string::npos);
    const std::string chapter =
        R"({"id": "a", "title": "A", "lesson": "l", "formula": "f", "levels": ["1.json"]})";
    EXPECT_NE(refusal(R"({"format": 1, "chapters": [)" + chapter + "," + chapter + "]}")
                  .find("$.chapters[1].id: chapter id \"a\" is already used at $.chapters[0]"),
              std::string::npos)
        << refusal(R"({"format": 1, "chapters": [)" + chapter + "," + chapter + "]}");
    EXPECT_NE(refusal(R"({"format": 1, "chapters": [)" + chapter + R"(], "outside": ["1.json"]})")
                  .find("$.outside[0]: \"1.json\" is already listed at $.chapters[0].levels[0]"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"format": 1, "chapters": [{"id": "a", "title": "A", "lesson": "l",
              "formula": "f", "levels": ["../x.json"]}]})")
                  .find("$.chapters[0].levels[0]: expected a level file name"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"format": 1, "chapters": [{"id": "a", "title": "A", "lesson": "l",
              "formula": "f", "levels": ["1.json"], "stars": 3}]})")
                  .find("$.chapters[0]"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"format": 1, "chapters": [{"id": "a", "title": "A", "lesson": "l",
              "formula": "f", "stars_to_open": 2, "levels": ["1.json"]}]})")
                  .find("$.chapters[0].stars_to_open: expected 0"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"format": 1, "chapters": [{"id": "a", "title": "A",
              "formula": "f", "levels": ["1.json"]}]})")
                  .find("$.chapters[0]: missing field \"lesson\""),
              std::string::npos);
}

TEST(Campaign, LevelsOpenOneAfterAnotherAndChaptersByStars) {
    const Campaign c = twoChapters();
    Progress p;
    EXPECT_TRUE(levelLock(c, 0, 0, p).open) << "the first level is always open";
    EXPECT_FALSE(levelLock(c, 0, 1, p).open);
    EXPECT_EQ(levelLock(c, 0, 1, p).why, "clear 1.1 first (one star)");
    Campaign withDuel = c;
    withDuel.duels.insert("1.json");
    EXPECT_EQ(levelLock(withDuel, 0, 1, p).why, "win the duel 1.1 first") << "a duel is won, not starred";
    EXPECT_EQ(chapterLock(c, 1, p).why, "4 more stars in Chapter 1");
    p.record("1.json", 100, 0, false); // played, no star: not cleared
    EXPECT_FALSE(levelLock(c, 0, 1, p).open);
    p.record("levels/1.json", 200, 3, false);
    EXPECT_TRUE(levelLock(c, 0, 1, p).open);
    EXPECT_EQ(chapterLock(c, 1, p).why, "1 more star in Chapter 1");
    EXPECT_FALSE(levelLock(c, 1, 0, p).open);
    EXPECT_EQ(levelLock(c, 1, 0, p).why, "1 more star in Chapter 1")
        << "a locked chapter's levels say what opens it";
    p.record("2.json", 100, 1, false);
    EXPECT_EQ(chapterStars(c.chapters[0], p), 4);
    EXPECT_TRUE(chapterLock(c, 1, p).open);
    EXPECT_TRUE(levelLock(c, 1, 0, p).open);
    EXPECT_FALSE(levelLock(c, 1, 1, p).open);
    p.record("3.json", 0, 0, true); // a duel won clears its level
    EXPECT_TRUE(levelLock(c, 1, 1, p).open);
}

TEST(Campaign, ADuelIsOpenFromTheStartWhereverItStands) {
    const Campaign c = twoChapters();
    const Progress none;
    // The last level of a locked chapter: closed as practice, open as a duel.
    EXPECT_FALSE(levelLock(c, 1, 1, none, Mode::Practice).open);
    EXPECT_EQ(levelLock(c, 1, 1, none, Mode::Practice).why, "4 more stars in Chapter 1");
    EXPECT_TRUE(levelLock(c, 1, 1, none, Mode::Duel).open);
    EXPECT_TRUE(levelLock(c, 0, 1, none, Mode::Duel).open);
    // Played and lost, a duel is not cleared: what follows it stays closed.
    Progress p;
    p.record("1.json", 0, 0, false);
    EXPECT_FALSE(cleared(p, "1.json"));
    EXPECT_FALSE(levelLock(c, 0, 1, p, Mode::Practice).open);
}

TEST(Campaign, NextLevelGoesOnAcrossChapters) {
    const Campaign c = twoChapters();
    EXPECT_EQ(findLevel(c, "levels/2.json"), (LevelPlace{0, 1}));
    EXPECT_EQ(nextLevel(c, "1.json"), (LevelPlace{0, 1}));
    EXPECT_EQ(nextLevel(c, "some/folder/2.json"), (LevelPlace{1, 0})) << "into the next chapter";
    EXPECT_EQ(nextLevel(c, "3.json"), (LevelPlace{1, 1}));
    EXPECT_FALSE(nextLevel(c, "4.json")) << "the last level";
    EXPECT_FALSE(nextLevel(c, "sandbox.json")) << "outside the chapters";
    EXPECT_FALSE(findLevel(c, "5.json"));
}

// A chapter that names a level the folder lacks: `check` refuses the campaign, and the
// game still plays it honestly. The missing level is reported as data (chapter, level,
// file, why) for the level select to show, and it locks nothing: the level after it
// opens as if it were cleared, and its stars are not asked of the chapter.
TEST(Campaign, AMissingLevelIsNamedAndLocksNothing) {
    const fs::path dir = levelsFolder("artillery-campaign-missing-test",
                                      {{"01_earth_basics.json", "1.json"},
                                       {"02_moon.json", "3.json"},
                                       {"05_castle.json", "4.json"}});
    std::ofstream((dir / "broken.json").string()) << "{";
    Campaign c = twoChapters(); // 2.json is not there
    const std::vector<MissingLevel> missing = missingLevels(c, dir.string());
    ASSERT_EQ(missing.size(), 1u);
    EXPECT_EQ(missing[0].chapter, 0u);
    EXPECT_EQ(missing[0].level, 1u);
    EXPECT_EQ(missing[0].file, "2.json");
    EXPECT_EQ(missing[0].why, "no such level file in " + dir.string());
    EXPECT_EQ(describe(c, missing[0]),
              "c.json: $.chapters[0].levels[1]: names 2.json, which cannot be played (no such "
              "level file in " + dir.string() + "): the levels after it open without it");
    for (const MissingLevel& m : missing) c.missing[m.file] = m.why;

    Progress p;
    p.record("1.json", 100, 1, false);
    EXPECT_TRUE(levelLock(c, 0, 1, p).open) << "the missing level itself is not behind a lock";
    // The second chapter asks 4 stars of the first; 2.json could have given 3 of them.
    EXPECT_TRUE(chapterLock(c, 1, p).open) << chapterLock(c, 1, p).why;
    EXPECT_TRUE(levelLock(c, 1, 0, p).open);

    // A level that is there but does not load is as unplayable, with the loader's reason.
    Campaign broken = parseCampaign("c.json", R"({"format": 1, "chapters": [
        {"id": "a", "title": "A", "lesson": "l", "formula": "f",
         "levels": ["broken.json", "1.json"]}]})");
    const std::vector<MissingLevel> unloadable = missingLevels(broken, dir.string());
    ASSERT_EQ(unloadable.size(), 1u);
    EXPECT_NE(unloadable[0].why.find("broken.json"), std::string::npos) << unloadable[0].why;
    broken.missing[unloadable[0].file] = unloadable[0].why;
    EXPECT_TRUE(levelLock(broken, 0, 1, Progress{}).open);
    fs::remove_all(dir);
}
