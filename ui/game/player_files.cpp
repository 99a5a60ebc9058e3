#include "ui/game/player_files.h"

#include "game/files/text_file.h"
#include "ui/game/random_map.h"

#include <imgui.h>

#include <filesystem>
#include <iostream>

namespace ui {

PlayerFiles::PlayerFiles(const PlayerFilesDef& def) : def_(def) {
    if (!def_.settingsFolder.empty()) loadSettings();
    if (!def_.settingsFolder.empty() || !def_.progressFile.empty()) loadProgress();
}

void PlayerFiles::loadSettings() {
    settingsFile_ = (std::filesystem::path(def_.settingsFolder) / "settings.json").string();
    iniFile_ = (std::filesystem::path(def_.settingsFolder) / "imgui.ini").string();
    std::string warning;
    settings_ = loadPlayerSettings(settingsFile_, warning);
    if (!warning.empty()) {
        // Told on the terminal and in the window; the damaged file is kept as it is,
        // so this run saves no settings over it.
        std::cerr << "artillery: " << warning << "\n";
        warning_ = warning;
        settingsFile_.clear();
    }
    std::error_code ec;
    if (std::filesystem::exists(iniFile_, ec)) {
        const std::string ini = game::readFile(iniFile_);
        ImGui::LoadIniSettingsFromMemory(ini.data(), ini.size());
    }
}

/// The progress file beside the settings. A damaged one is kept aside by the reader and
/// the player is told once; results an older settings file kept move into it (saved
/// before the settings, which no longer write them, are saved without them).
void PlayerFiles::loadProgress() {
    progressFile_ = !def_.progressFile.empty()
                        ? def_.progressFile
                        : (std::filesystem::path(def_.settingsFolder) / "progress.json").string();
    std::error_code ec;
    const bool existed = std::filesystem::exists(progressFile_, ec);
    std::string warning;
    if (def_.progressReadOnly) { // a check run: read, never move nor write
        try {
            if (existed)
                progress_ = game::parseProgress(progressFile_, game::readFile(progressFile_));
        } catch (const std::exception& e) {
            warning = e.what();
        }
        if (!warning.empty()) std::cerr << "artillery: " << warning << "\n";
        progressFile_.clear();
        return;
    }
    progress_ = game::loadProgress(progressFile_, warning);
    if (!warning.empty()) {
        std::cerr << "artillery: " << warning << "\n";
        warning_ = warning;
    }
    if (game::adoptOlderResults(progress_, settings_.results)) {
        if (const std::string err = game::saveProgress(progressFile_, progress_); !err.empty())
            std::cerr << "artillery: progress not saved: " << err << "\n";
    }
}

void PlayerFiles::save(const ViewControls& view) {
    if (!progressFile_.empty())
        if (const std::string err = game::saveProgress(progressFile_, progress_); !err.empty())
            std::cerr << "artillery: progress not saved: " << err << "\n";
    if (settingsFile_.empty()) return;
    settings_.draw = drawChoices(view);
    if (const std::string err = savePlayerSettings(settingsFile_, settings_); !err.empty())
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

std::string PlayerFiles::replaysFolder() const {
    if (def_.settingsFolder.empty()) return "";
    return (std::filesystem::path(def_.settingsFolder) / "replays").string();
}

std::string PlayerFiles::recordFileFor(const std::string& name) const {
    const std::string folder = replaysFolder();
    if (folder.empty()) return "";
    std::filesystem::create_directories(folder);
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
