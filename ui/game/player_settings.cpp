#include "ui/game/player_settings.h"

#include "game/files/json_reader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace ui {

namespace {

std::string key(const std::string& levelFile) {
    return std::filesystem::path(levelFile).filename().string();
}

} // namespace

bool PlayerSettings::record(const std::string& levelFile, int score, int stars, bool won) {
    LevelResult& r = results[key(levelFile)];
    const bool better = r.plays == 0 || score > r.bestScore || stars > r.stars || (won && !r.won);
    ++r.plays;
    r.bestScore = std::max(r.bestScore, score);
    r.stars = std::max(r.stars, stars);
    r.won = r.won || won;
    return better;
}

const LevelResult* PlayerSettings::result(const std::string& levelFile) const {
    const auto it = results.find(key(levelFile));
    return it == results.end() ? nullptr : &it->second;
}

std::string configFolder() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
        return (std::filesystem::path(xdg) / "artillery").string();
    if (const char* home = std::getenv("HOME"); home && *home)
        return (std::filesystem::path(home) / ".config" / "artillery").string();
    return "";
}

PlayerSettings loadPlayerSettings(const std::string& file, std::string& warning) {
    PlayerSettings s;
    warning.clear();
    std::ifstream in(file);
    if (!in) return s; // first run
    try {
        std::stringstream text;
        text << in.rdbuf();
        const nlohmann::json j = nlohmann::json::parse(text.str());
        if (const auto d = game::difficultyFromName(j.value("difficulty", "normal"))) s.difficulty = *d;
        s.hotseat = j.value("hotseat", s.hotseat);
        s.trajectoryPreview = j.value("trajectory_preview", s.trajectoryPreview);
        s.solutionHint = j.value("solution_hint", s.solutionHint);
        s.physicsPanel = j.value("physics_panel", s.physicsPanel);
        if (j.contains("levels") && j["levels"].is_object())
            for (const auto& [name, r] : j["levels"].items()) {
                LevelResult lr;
                lr.bestScore = r.value("best_score", 0);
                lr.stars = std::clamp(r.value("stars", 0), 0, 3);
                lr.plays = r.value("plays", 0);
                lr.won = r.value("won", false);
                s.results[name] = lr;
            }
    } catch (const std::exception& e) {
        // A damaged settings file must not stop the game: start from the defaults.
        warning = file + ": " + e.what() + " (using defaults; the file is rewritten on exit)";
        return PlayerSettings{};
    }
    return s;
}

std::string savePlayerSettings(const std::string& file, const PlayerSettings& s) {
    nlohmann::json j;
    j["format"] = 1;
    j["difficulty"] = game::difficultyName(s.difficulty);
    j["hotseat"] = s.hotseat;
    j["trajectory_preview"] = s.trajectoryPreview;
    j["solution_hint"] = s.solutionHint;
    j["physics_panel"] = s.physicsPanel;
    nlohmann::json levels = nlohmann::json::object();
    for (const auto& [name, r] : s.results)
        levels[name] = {{"best_score", r.bestScore}, {"stars", r.stars}, {"plays", r.plays}, {"won", r.won}};
    j["levels"] = levels;
    try {
        std::filesystem::create_directories(std::filesystem::path(file).parent_path());
        game::writeFileAtomically(file, j.dump(2) + "\n");
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

} // namespace ui
