#include "ui/game/player_settings.h"

#include "game/files/file_lock.h"
#include "game/files/json_reader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace ui {

namespace {

/// More results than any levels folder holds: a hostile file cannot grow the map.
constexpr std::size_t kMaxLevelResults = 10'000;

/// The draw toggles by their names in the file, in the panel's order.
std::array<std::pair<const char*, bool*>, 9> drawFlags(DrawChoices& d) {
    return {{{"trails", &d.trails},
             {"labels", &d.labels},
             {"velocities", &d.velocities},
             {"forces", &d.forces},
             {"ghosts", &d.ghosts},
             {"contacts", &d.contacts},
             {"cells", &d.cells},
             {"sleeping", &d.sleeping},
             {"models", &d.models}}};
}
} // namespace

std::string configFolder() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
        return (std::filesystem::path(xdg) / "artillery").string();
    if (const char* home = std::getenv("HOME"); home && *home)
        return (std::filesystem::path(home) / ".config" / "artillery").string();
    return "";
}

PlayerSettings parsePlayerSettings(const std::string& file, const std::string& text) {
    const nlohmann::json doc = game::parseJson(file, text);
    const game::Node root(doc, file);
    PlayerSettings s;
    root.integer("format", 1, 1, 1);
    const std::string difficulty = root.string("difficulty", "normal");
    const auto d = game::difficultyFromName(difficulty);
    if (!d) root.at("difficulty").fail("expected \"easy\", \"normal\" or \"hard\", got \"" + difficulty + "\"");
    s.difficulty = *d;
    s.hotseat = root.boolean("hotseat", s.hotseat);
    s.trajectoryPreview = root.boolean("trajectory_preview", s.trajectoryPreview);
    s.solutionHint = root.boolean("solution_hint", s.solutionHint);
    s.fullPreview = root.boolean("full_preview", s.fullPreview);
    s.cameraFollow = root.boolean("camera_follow", s.cameraFollow);
    s.screenShake = root.boolean("screen_shake", s.screenShake);
    s.physicsPanel = root.boolean("physics_panel", s.physicsPanel);
    if (const auto draw = root.find("draw")) {
        if (!draw->isObject()) draw->fail("expected an object of draw toggles (true or false)");
        for (auto& [name, flag] : drawFlags(s.draw)) *flag = draw->boolean(name, *flag);
        draw->finish();
    }
    if (const auto sound = root.find("sound")) {
        if (!sound->isObject()) sound->fail("expected an object with master, effects, ui (0..1) and mute");
        s.sound.master = sound->number("master", s.sound.master, 0.0, 1.0);
        s.sound.effects = sound->number("effects", s.sound.effects, 0.0, 1.0);
        s.sound.ui = sound->number("ui", s.sound.ui, 0.0, 1.0);
        s.sound.mute = sound->boolean("mute", s.sound.mute);
        sound->finish();
    }
    // Results moved to the progress file; an older file's are read to migrate them.
    if (const auto levels = root.find("levels")) {
        if (!levels->isObject()) levels->fail("expected an object of results by level file name");
        if (levels->json().size() > kMaxLevelResults)
            levels->fail("expected at most " + std::to_string(kMaxLevelResults) + " levels");
        for (const auto& [name, value] : levels->json().items()) {
            const game::Node r(value, file, levels->path() + "." + name);
            if (!r.isObject()) r.fail("expected an object with best_score, stars, plays, won, assisted");
            LevelResult lr;
            lr.bestScore = static_cast<int>(r.integer("best_score", 0, 0, 1'000'000'000));
            lr.stars = static_cast<int>(r.integer("stars", 0, 0, 3));
            lr.plays = static_cast<int>(r.integer("plays", 0, 0, 1'000'000'000));
            lr.won = r.boolean("won", false);
            lr.assisted = r.boolean("assisted", false);
            r.finish();
            s.results[name] = lr;
        }
    }
    root.finish();
    return s;
}

PlayerSettings loadPlayerSettings(const std::string& file, std::string& warning) {
    warning.clear();
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return {}; // first run
    try {
        return parsePlayerSettings(file, game::readFile(file));
    } catch (const std::exception& e) {
        // A damaged settings file must not stop the game, and must not be overwritten:
        // the caller plays on with the defaults and saves nothing this run.
        warning = std::string(e.what()) + " (playing with the defaults; the file is left as it is)";
        return {};
    }
}

namespace {

nlohmann::json settingsJson(const PlayerSettings& s) {
    nlohmann::json j;
    j["format"] = 1;
    j["difficulty"] = game::difficultyName(s.difficulty);
    j["hotseat"] = s.hotseat;
    j["trajectory_preview"] = s.trajectoryPreview;
    j["solution_hint"] = s.solutionHint;
    j["full_preview"] = s.fullPreview;
    j["camera_follow"] = s.cameraFollow;
    j["screen_shake"] = s.screenShake;
    j["physics_panel"] = s.physicsPanel;
    DrawChoices draw = s.draw;
    for (const auto& [name, flag] : drawFlags(draw))
        j["draw"][name] = *flag;
    j["sound"] = {{"master", s.sound.master},
                  {"effects", s.sound.effects},
                  {"ui", s.sound.ui},
                  {"mute", s.sound.mute}};
    return j;
}

std::string writeSettings(const std::string& file, const nlohmann::json& j) {
    try {
        std::filesystem::create_directories(std::filesystem::path(file).parent_path());
        game::writeFileAtomically(file, j.dump(2) + "\n");
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

/// Key by key (into objects): `mine`'s value where it differs from `base`'s (this run
/// changed it), else `disk`'s (another window may have).
nlohmann::json changedKeysOver(const nlohmann::json& disk, const nlohmann::json& base,
                               const nlohmann::json& mine) {
    if (!mine.is_object()) return mine != base ? mine : disk;
    nlohmann::json out = disk.is_object() ? disk : nlohmann::json::object();
    for (const auto& [key, value] : mine.items()) {
        const nlohmann::json& was = base.contains(key) ? base.at(key) : value;
        out[key] = disk.contains(key) ? changedKeysOver(disk.at(key), was, value) : value;
    }
    return out;
}

} // namespace

std::string savePlayerSettings(const std::string& file, const PlayerSettings& s) {
    return writeSettings(file, settingsJson(s));
}

std::string savePlayerSettingsMerged(const std::string& file, PlayerSettings& base,
                                     PlayerSettings& mine) {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(file).parent_path(), ec);
    const game::FileLock lock(game::lockFileOf(file), 5.0);
    if (!lock.locked()) return lock.why();
    nlohmann::json merged = settingsJson(mine);
    if (std::filesystem::exists(file, ec)) {
        PlayerSettings onDisk;
        try {
            onDisk = parsePlayerSettings(file, game::readFile(file));
        } catch (const std::exception& e) {
            return std::string(e.what()) + " (left as it is)";
        }
        merged = changedKeysOver(settingsJson(onDisk), settingsJson(base), merged);
    }
    PlayerSettings whole;
    try { // what the merge made is read back as the file will be: whole, or not written
        whole = parsePlayerSettings(file, merged.dump());
    } catch (const std::exception& e) {
        return std::string(e.what()) + " (the merged settings; nothing written)";
    }
    if (std::string err = writeSettings(file, merged); !err.empty()) return err;
    whole.results = mine.results; // an older file's results are read once, never written
    base = mine = whole;
    return "";
}

game::audio::SoundMix playerSoundMix(bool checkRun) {
    const std::string folder = configFolder();
    if (checkRun || folder.empty()) return {};
    std::string warning; // a damaged file: the game says so when it opens; here, the defaults
    return loadPlayerSettings((std::filesystem::path(folder) / "settings.json").string(), warning)
        .sound;
}

} // namespace ui
