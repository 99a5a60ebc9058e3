#include "ui/game/player_files.h"

#include "game/files/text_file.h"
#include "ui/game/random_map.h"

#include <imgui.h>

#include <filesystem>
#include <iostream>

namespace ui {

namespace {

std::string inFolder(const std::string& folder, const char* name) {
    return (std::filesystem::path(folder) / name).string();
}

} // namespace

PlayerFiles::PlayerFiles(const PlayerFilesDef& def) : def_(def), folder_(def.settingsFolder) {
    if (!folder_.notice().empty()) say(folder_.notice());
    if (!def_.settingsFolder.empty()) loadSettings();
    if (!def_.settingsFolder.empty() || !def_.progressFile.empty()) loadProgress();
}

/// Said once, when the game opens: on the terminal, and the first one in the window.
void PlayerFiles::say(const std::string& message) {
    std::cerr << "artillery: " << message << "\n";
    if (warning_.empty()) warning_ = message;
}

void PlayerFiles::loadSettings() {
    settingsFile_ = folder_.fileToWrite("settings.json");
    iniFile_ = folder_.fileToWrite("imgui.ini");
    std::string warning;
    settings_ = settingsBase_ = loadPlayerSettings(inFolder(def_.settingsFolder, "settings.json"), warning);
    if (!warning.empty()) {
        // The damaged file is kept as it is, so this run saves no settings over it.
        say(warning);
        settingsFile_.clear();
    }
    const std::string ini = inFolder(def_.settingsFolder, "imgui.ini");
    std::error_code ec;
    if (!std::filesystem::exists(ini, ec)) return;
    try {
        const std::string text = game::readFile(ini);
        ImGui::LoadIniSettingsFromMemory(text.data(), text.size());
    } catch (const std::exception&) {
        // A layout that cannot be read is the default layout.
    }
}

/// The progress file beside the settings. A damaged one is kept aside by the reader and
/// the player is told once; results an older settings file kept move into it (saved
/// before the settings, which no longer write them, are saved without them).
void PlayerFiles::loadProgress() {
    const std::string file = !def_.progressFile.empty() ? def_.progressFile
                                                        : inFolder(def_.settingsFolder, "progress.json");
    std::error_code ec;
    if (def_.progressReadOnly) { // a check run: read, never move nor write
        try {
            if (std::filesystem::exists(file, ec))
                progress_ = progressBase_ = game::parseProgress(file, game::readFile(file));
        } catch (const std::exception& e) {
            std::cerr << "artillery: " << e.what() << "\n";
        }
        return;
    }
    progressFile_ = !def_.progressFile.empty() ? def_.progressFile : folder_.fileToWrite("progress.json");
    std::string warning;
    progress_ = progressBase_ = game::loadProgress(file, warning);
    if (!warning.empty()) say(warning);
    if (game::adoptOlderResults(progress_, settings_.results)) saveProgress();
}

void PlayerFiles::saveProgress() {
    if (progressFile_.empty()) return;
    std::string warning;
    if (const std::string err = game::saveProgressMerged(progressFile_, progressBase_, progress_, warning);
        !err.empty())
        std::cerr << "artillery: progress not saved: " << err << "\n";
    if (!warning.empty()) std::cerr << "artillery: " << warning << "\n";
}

void PlayerFiles::save(const ViewControls& view) {
    saveProgress();
    if (settingsFile_.empty()) return;
    settings_.draw = drawChoices(view);
    if (const std::string err = savePlayerSettingsMerged(settingsFile_, settingsBase_, settings_); !err.empty())
        std::cerr << "artillery: settings not saved: " << err << "\n";
    std::size_t size = 0;
    const char* ini = ImGui::SaveIniSettingsToMemory(&size);
    try {
        game::writeFileAtomically(iniFile_, std::string(ini, size));
    } catch (const std::exception& e) {
        std::cerr << "artillery: window layout not saved: " << e.what() << "\n";
    }
}

bool PlayerFiles::recordResult(const std::string& levelFile, int score, int stars, bool won,
                               bool assisted, const ViewControls& view) {
    const bool newBest = progress_.record(levelFile, score, stars, won, assisted);
    save(view);
    return newBest;
}

std::string PlayerFiles::recordFileFor(const std::string& name) const {
    const std::string folder = replaysFolder();
    if (folder.empty()) return "";
    std::error_code ec; // made when the game opened; a folder removed since is made again
    std::filesystem::create_directories(folder, ec);
    return (std::filesystem::path(folder) / name).string();
}

std::string PlayerFiles::mapsFolder() const { return randomMapsFolder(def_.settingsFolder); }

ViewControls openingView(ViewControls flags, const DrawChoices& stored) {
    DebugOverlays& d = flags.draw;
    flags.trails = flags.trails && stored.trails;
    flags.labels = flags.labels && stored.labels;
    d.velocities = d.velocities || stored.velocities;
    d.forces = d.forces || stored.forces;
    d.ghosts = d.ghosts || stored.ghosts;
    d.contacts = d.contacts || stored.contacts;
    d.cells = d.cells || stored.cells;
    d.sleeping = d.sleeping || stored.sleeping;
    d.models = d.models || stored.models;
    return flags;
}

DrawChoices drawChoices(const ViewControls& v) {
    const DebugOverlays& d = v.draw;
    return {v.trails,   v.labels, d.velocities, d.forces, d.ghosts,
            d.contacts, d.cells,  d.sleeping,   d.models};
}

} // namespace ui
