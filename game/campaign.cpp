#include "game/campaign.h"

#include "game/files/json_reader.h"
#include "game/level.h"

#include <algorithm>
#include <filesystem>
#include <map>

namespace game {

namespace {

constexpr std::size_t kMaxChapters = 64;
constexpr std::size_t kMaxLevelsPerChapter = 64;
/// A lesson a player reads in ten seconds: three short sentences at most.
constexpr std::size_t kMaxLessonCharacters = 400;
constexpr int kStarsPerLevel = 3;
/// The campaign's own file name: the levels folder lists it beside the levels.
constexpr const char* kCampaignFileName = "campaign.json";

/// A level file name: "NN_name.json", no folder (the campaign lives beside its levels).
std::string levelFileName(const Node& n) {
    const std::string name = n.string(120);
    const std::filesystem::path p(name);
    if (name.empty() || p.filename().string() != name || p.extension() != ".json" ||
        name == kCampaignFileName)
        n.fail("expected a level file name in the levels folder (like \"01_earth_basics.json\"), "
               "got \"" +
               printable(name) + "\"");
    return name;
}

Chapter parseChapter(const Node& n) {
    if (!n.isObject())
        n.fail("expected a chapter object with id, title, lesson, formula and levels");
    Chapter c;
    c.id = n.at("id").string(40);
    if (c.id.empty()) n.at("id").fail("expected a non-empty id");
    c.title = n.at("title").string(80);
    c.lesson = n.at("lesson").string(kMaxLessonCharacters);
    c.formula = n.at("formula").string(200);
    if (const auto picture = n.find("picture")) {
        std::vector<std::string> names;
        for (const LessonPicture& p : lessonPictures()) names.emplace_back(p.name);
        c.picture = picture->choice(names);
    }
    c.starsToOpen = static_cast<int>(n.integer("stars_to_open", 0, 0, 1000));
    for (const Node& level : n.at("levels").elements(kMaxLevelsPerChapter, 1))
        c.levels.push_back(levelFileName(level));
    n.finish();
    return c;
}

} // namespace

const std::vector<LessonPicture>& lessonPictures() {
    static const std::vector<LessonPicture> pictures{
        {"firing-solution",
         "the two trajectories of the firing solution from the cannon to one target: the flat "
         "one and the steep one"},
        {"moon-vs-earth", "the same shot (same speed and angle) on the Moon and on Earth: six "
                          "times the range and the height"},
        {"drag-vs-vacuum", "the same shot in vacuum, in still air and into a headwind: each "
                           "shorter and steeper at the end"},
        {"bounce", "a ball dropped from H bouncing, each apex lower by e²: H, e²H, e⁴H"},
        {"arsenal", "the eight weapons' moves in a row: the mortar's near-vacuum arc, the "
                    "airburst bursting 5 m up, the cluster splitting at its apex, the bouncer's "
                    "three bounces, the grenade's fuse, the roller rolling, the sticky charge "
                    "stuck to a wall, the digger's tunnel"},
        {"spring", "a mass bobbing on a spring, with the period 2π/ω of ω = √(k/m)"},
        {"topple", "a block tipping over once its centre of mass passes the edge of its base"},
        {"step-size", "explicit Euler's steps drifting off the exact parabola at a large step, "
                      "and hugging it at a small one"},
        {"models", "one scene with each object labelled by its model: the closed-form "
                   "parabola, the integrated shell in air, the rope of rods, the rigid block"},
    };
    return pictures;
}

Campaign parseCampaign(const std::string& file, const std::string& text) {
    const nlohmann::json doc = parseJson(file, text);
    const Node root(doc, file);
    if (!root.isObject()) root.fail("expected an object with format, chapters and outside");
    root.integer("format", 1, 1, 1);
    Campaign c;
    c.file = file;
    // Where each level file was first named, so a second mention can point at both.
    std::map<std::string, std::string> namedAt;
    auto once = [&](const std::string& name, const std::string& path, const Node& n) {
        const auto [it, fresh] = namedAt.emplace(name, path);
        if (!fresh) n.fail("\"" + name + "\" is already listed at " + it->second);
    };
    std::map<std::string, std::string> ids;
    const std::vector<Node> chapters = root.at("chapters").elements(kMaxChapters, 1);
    for (const Node& n : chapters) {
        Chapter ch = parseChapter(n);
        if (const auto [it, fresh] = ids.emplace(ch.id, n.path()); !fresh)
            n.at("id").fail("chapter id \"" + ch.id + "\" is already used at " + it->second);
        const std::vector<Node> levels = n.at("levels").elements(kMaxLevelsPerChapter, 1);
        for (std::size_t i = 0; i < ch.levels.size(); ++i)
            once(ch.levels[i], levels[i].path(), levels[i]);
        c.chapters.push_back(std::move(ch));
    }
    if (c.chapters.front().starsToOpen != 0)
        chapters.front().at("stars_to_open").fail("expected 0: the first chapter is always open");
    if (const auto outside = root.find("outside"))
        for (const Node& n : outside->elements(kMaxLevelsPerChapter)) {
            c.outside.push_back(levelFileName(n));
            once(c.outside.back(), n.path(), n);
        }
    root.finish();
    return c;
}

Campaign loadCampaign(const std::string& file) {
    return parseCampaign(file, readFile(file));
}

std::vector<MissingLevel> missingLevels(const Campaign& campaign, const std::string& levelsFolder) {
    namespace fs = std::filesystem;
    std::vector<MissingLevel> missing;
    for (std::size_t c = 0; c < campaign.chapters.size(); ++c)
        for (std::size_t l = 0; l < campaign.chapters[c].levels.size(); ++l) {
            const std::string& name = campaign.chapters[c].levels[l];
            const fs::path file = fs::path(levelsFolder) / name;
            std::error_code ec;
            if (!fs::exists(file, ec)) {
                missing.push_back({c, l, name, "no such level file in " + levelsFolder});
                continue;
            }
            try {
                loadLevel(file.string());
            } catch (const std::exception& e) {
                missing.push_back({c, l, name, e.what()});
            }
        }
    return missing;
}

std::string describe(const Campaign& campaign, const MissingLevel& m) {
    return campaign.file + ": $.chapters[" + std::to_string(m.chapter) + "].levels[" +
           std::to_string(m.level) + "]: names " + m.file + ", which cannot be played (" + m.why +
           "): the levels after it open without it";
}

std::vector<std::string> campaignProblems(const Campaign& campaign,
                                          const std::string& levelsFolder) {
    namespace fs = std::filesystem;
    std::vector<std::string> problems;
    std::map<std::string, bool> listed;
    std::map<std::string, std::string> unplayable;
    for (const MissingLevel& m : missingLevels(campaign, levelsFolder))
        unplayable[m.file] = m.why;
    for (std::size_t c = 0; c < campaign.chapters.size(); ++c) {
        const Chapter& ch = campaign.chapters[c];
        const std::string at = "$.chapters[" + std::to_string(c) + "]";
        int practiceLevels = 0;
        for (std::size_t l = 0; l < ch.levels.size(); ++l) {
            listed[ch.levels[l]] = true;
            const std::string where =
                campaign.file + ": " + at + ".levels[" + std::to_string(l) + "]: ";
            if (const auto it = unplayable.find(ch.levels[l]); it != unplayable.end()) {
                problems.push_back(where + "the level does not load: " + it->second);
                continue;
            }
            const Level level = loadLevel((fs::path(levelsFolder) / ch.levels[l]).string());
            if (level.mode == Mode::Sandbox)
                problems.push_back(where + "a sandbox has no result to unlock the next level; "
                                           "list it in \"outside\"");
            if (level.mode == Mode::Practice) ++practiceLevels;
        }
        if (c + 1 < campaign.chapters.size() &&
            campaign.chapters[c + 1].starsToOpen > kStarsPerLevel * practiceLevels)
            problems.push_back(campaign.file + ": $.chapters[" + std::to_string(c + 1) +
                               "].stars_to_open: expected at most " +
                               std::to_string(kStarsPerLevel * practiceLevels) +
                               " (3 stars for each "
                               "practice level of \"" +
                               ch.title + "\"), got " +
                               std::to_string(campaign.chapters[c + 1].starsToOpen));
    }
    for (std::size_t i = 0; i < campaign.outside.size(); ++i) {
        listed[campaign.outside[i]] = true;
        if (!fs::exists(fs::path(levelsFolder) / campaign.outside[i]))
            problems.push_back(campaign.file + ": $.outside[" + std::to_string(i) +
                               "]: no such level file in " + levelsFolder);
    }
    std::vector<std::string> files;
    std::error_code ec;
    for (const auto& f : fs::directory_iterator(levelsFolder, ec))
        if (f.path().extension() == ".json" && f.path().filename() != kCampaignFileName)
            files.push_back(f.path().filename().string());
    std::sort(files.begin(), files.end());
    for (const std::string& f : files)
        if (!listed.count(f))
            problems.push_back(campaign.file + ": $.chapters: the level " + f +
                               " is in no chapter (add it to one, or to \"outside\")");
    return problems;
}

std::optional<LevelPlace> findLevel(const Campaign& campaign, const std::string& levelFile) {
    const std::string name = std::filesystem::path(levelFile).filename().string();
    for (std::size_t c = 0; c < campaign.chapters.size(); ++c)
        for (std::size_t l = 0; l < campaign.chapters[c].levels.size(); ++l)
            if (campaign.chapters[c].levels[l] == name) return LevelPlace{c, l};
    return std::nullopt;
}

std::optional<LevelPlace> nextLevel(const Campaign& campaign, const std::string& levelFile) {
    const auto at = findLevel(campaign, levelFile);
    if (!at) return std::nullopt;
    if (at->level + 1 < campaign.chapters[at->chapter].levels.size())
        return LevelPlace{at->chapter, at->level + 1};
    if (at->chapter + 1 < campaign.chapters.size()) return LevelPlace{at->chapter + 1, 0};
    return std::nullopt;
}

bool cleared(const Progress& progress, const std::string& levelFile) {
    const LevelResult* r = progress.result(levelFile);
    return r && (r->stars >= 1 || r->won);
}

int chapterStars(const Chapter& chapter, const Progress& progress) {
    int stars = 0;
    for (const std::string& level : chapter.levels)
        if (const LevelResult* r = progress.result(level)) stars += r->stars;
    return stars;
}

Lock chapterLock(const Campaign& campaign, std::size_t chapter, const Progress& progress) {
    if (chapter == 0) return {};
    const Chapter& before = campaign.chapters[chapter - 1];
    // The stars a level that cannot be played could have given are not asked for.
    int unplayable = 0;
    for (const std::string& level : before.levels)
        unplayable += static_cast<int>(campaign.missing.count(level));
    const int missing = campaign.chapters[chapter].starsToOpen - kStarsPerLevel * unplayable -
                        chapterStars(before, progress);
    if (missing <= 0) return {};
    return {false, std::to_string(missing) + " more star" + (missing == 1 ? "" : "s") +
                       " in Chapter " + std::to_string(chapter)};
}

Lock levelLock(const Campaign& campaign, std::size_t chapter, std::size_t level,
               const Progress& progress) {
    if (Lock l = chapterLock(campaign, chapter, progress); !l.open) return l;
    // The level before it that must be cleared: levels that cannot be played are passed.
    const std::vector<std::string>& levels = campaign.chapters[chapter].levels;
    std::size_t before = level;
    while (before > 0 && campaign.missing.count(levels[before - 1])) --before;
    if (before == 0) return {};
    if (cleared(progress, levels[before - 1])) return {};
    const bool duel = campaign.duels.count(levels[before - 1]) > 0;
    const std::string which = std::to_string(chapter + 1) + "." + std::to_string(before);
    return {false, duel ? "win the duel " + which + " first" : "clear " + which + " first (one star)"};
}

Lock levelLock(const Campaign& campaign, std::size_t chapter, std::size_t level,
               const Progress& progress, Mode mode) {
    if (mode == Mode::Duel) return {};
    return levelLock(campaign, chapter, level, progress);
}

} // namespace game
