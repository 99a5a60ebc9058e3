#include "game/progress.h"

#include "game/files/file_lock.h"
#include "game/files/json_reader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

namespace game {

namespace {

/// More results than any levels folder holds: a hostile file cannot grow the map.
constexpr std::size_t kMaxLevelResults = 10'000;
constexpr std::size_t kMaxLessons = 1'000;

std::string key(const std::string& levelFile) {
    return std::filesystem::path(levelFile).filename().string();
}

} // namespace

bool Progress::record(const std::string& levelFile, int score, int stars, bool won, bool assisted) {
    LevelResult& r = results[key(levelFile)];
    const bool better = r.plays == 0 || score > r.bestScore || stars > r.stars || (won && !r.won) ||
                        (stars == r.stars && r.assisted && !assisted);
    // Assisted while every result at the best star count so far was.
    if (r.plays == 0 || stars > r.stars)
        r.assisted = assisted;
    else if (stars == r.stars)
        r.assisted = r.assisted && assisted;
    ++r.plays;
    r.bestScore = std::max(r.bestScore, score);
    r.stars = std::max(r.stars, stars);
    r.won = r.won || won;
    // A game that earned nothing (out of shots, no star; a duel lost) is no best to
    // announce, even the first time.
    return better && (stars > 0 || won);
}

const LevelResult* Progress::result(const std::string& levelFile) const {
    const auto it = results.find(key(levelFile));
    return it == results.end() ? nullptr : &it->second;
}

bool adoptOlderResults(Progress& progress, const std::map<std::string, LevelResult>& older) {
    bool taken = false;
    for (const auto& [name, result] : older)
        taken |= progress.results.emplace(key(name), result).second;
    return taken;
}

Progress parseProgress(const std::string& file, const std::string& text) {
    const nlohmann::json doc = parseJson(file, text);
    const Node root(doc, file);
    if (!root.isObject()) root.fail("expected an object with format, levels and lessons_seen");
    root.integer("format", 1, 1, 1);
    Progress p;
    if (const auto levels = root.find("levels")) {
        if (!levels->isObject()) levels->fail("expected an object of results by level file name");
        if (levels->json().size() > kMaxLevelResults)
            levels->fail("expected at most " + std::to_string(kMaxLevelResults) + " levels");
        for (const auto& [name, value] : levels->json().items()) {
            const Node r(value, file, levels->path() + "." + name);
            if (!r.isObject())
                r.fail("expected an object with best_score, stars, plays, won, assisted");
            LevelResult lr;
            lr.bestScore = static_cast<int>(r.integer("best_score", 0, 0, 1'000'000'000));
            lr.stars = static_cast<int>(r.integer("stars", 0, 0, 3));
            lr.plays = static_cast<int>(r.integer("plays", 0, 0, 1'000'000'000));
            lr.won = r.boolean("won", false);
            lr.assisted = r.boolean("assisted", false);
            r.finish();
            p.results[name] = lr;
        }
    }
    if (const auto seen = root.find("lessons_seen"))
        for (const Node& id : seen->elements(kMaxLessons))
            p.lessonsSeen.insert(id.string(40));
    root.finish();
    return p;
}

Progress loadProgress(const std::string& file, std::string& warning) {
    warning.clear();
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return {}; // first run
    try {
        return parseProgress(file, readFile(file));
    } catch (const std::exception& e) {
        // A damaged file must not stop the game nor be lost: it is kept aside for the
        // player (and a bug report), and the game starts from no progress.
        const std::string aside = file + ".damaged";
        // Only a file is moved: a device or a folder given as the progress file stays put.
        if (std::filesystem::is_regular_file(file, ec))
            std::filesystem::rename(file, aside, ec);
        else
            ec = std::make_error_code(std::errc::not_supported);
        warning = std::string(e.what()) +
                  (ec ? " (starting with no progress; the file could not be moved aside: " +
                            ec.message() + ")"
                      : " (starting with no progress; the damaged file is kept as " + aside + ")");
        return {};
    }
}

std::string saveProgress(const std::string& file, const Progress& p) {
    nlohmann::json j;
    j["format"] = 1;
    nlohmann::json levels = nlohmann::json::object();
    for (const auto& [name, r] : p.results)
        levels[name] = {{"best_score", r.bestScore},
                        {"stars", r.stars},
                        {"plays", r.plays},
                        {"won", r.won},
                        {"assisted", r.assisted}};
    j["levels"] = levels;
    j["lessons_seen"] =
        nlohmann::json(std::vector<std::string>(p.lessonsSeen.begin(), p.lessonsSeen.end()));
    try {
        const std::filesystem::path parent = std::filesystem::path(file).parent_path();
        if (!parent.empty()) std::filesystem::create_directories(parent);
        writeFileAtomically(file, j.dump(2) + "\n");
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

LevelResult bestOf(const LevelResult& a, const LevelResult& b) {
    LevelResult r;
    r.bestScore = std::max(a.bestScore, b.bestScore);
    r.stars = std::max(a.stars, b.stars);
    r.won = a.won || b.won;
    r.assisted = a.stars != b.stars ? (a.stars > b.stars ? a.assisted : b.assisted)
                                    : a.assisted && b.assisted;
    r.plays = std::max(a.plays, b.plays);
    return r;
}

Progress mergeProgress(const Progress& onDisk, const Progress& base, const Progress& mine) {
    Progress merged = onDisk;
    for (const auto& [name, result] : mine.results) {
        const auto was = base.results.find(name);
        const int before = was == base.results.end() ? 0 : was->second.plays;
        const auto there = merged.results.find(name);
        if (there == merged.results.end()) {
            merged.results[name] = result; // the file has lost it, or never had it
            continue;
        }
        // The file's plays already count this run's earlier ones (it saved them): only
        // the plays since are added.
        const int added = std::max(0, result.plays - before);
        LevelResult best = bestOf(there->second, result);
        best.plays = there->second.plays + added;
        there->second = best;
    }
    merged.lessonsSeen.insert(mine.lessonsSeen.begin(), mine.lessonsSeen.end());
    return merged;
}

std::string saveProgressMerged(const std::string& file, Progress& base, Progress& mine,
                               std::string& warning) {
    warning.clear();
    std::error_code ec;
    const std::filesystem::path parent = std::filesystem::path(file).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    const FileLock lock(lockFileOf(file), 5.0);
    if (!lock.locked()) return lock.why();
    const Progress merged = mergeProgress(loadProgress(file, warning), base, mine);
    if (std::string err = saveProgress(file, merged); !err.empty()) return err;
    base = mine = merged;
    return "";
}

} // namespace game
