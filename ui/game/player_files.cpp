#include "ui/game/player_files.h"

#include "game/files/text_file.h"

#include <filesystem>

namespace ui {

namespace {

std::string inFolder(const std::string& folder, const char* name) {
    return (std::filesystem::path(folder) / name).string();
}

} // namespace

PlayerFiles::PlayerFiles(const PlayerFilesDef& def) : def_(def), folder_(def.settingsFolder) {
    if (!folder_.notice().empty()) notices_.push_back(folder_.notice());
    settingsFile_ = folder_.fileToWrite("settings.json");
    layoutFile_ = folder_.fileToWrite("imgui.ini");
    if (!def_.progressFile.empty())
        progressFile_ = def_.progressFile;
    else
        progressFile_ = folder_.fileToWrite("progress.json");
    if (def_.progressReadOnly) progressFile_.clear();
}

PlayerSettings PlayerFiles::loadSettings() {
    if (def_.settingsFolder.empty()) return {};
    std::string warning;
    settingsBase_ = loadPlayerSettings(inFolder(def_.settingsFolder, "settings.json"), warning);
    if (!warning.empty()) {
        // The damaged file is kept as it is, so this run saves no settings over it.
        notices_.push_back(warning);
        settingsFile_.clear();
    }
    return settingsBase_;
}

std::string PlayerFiles::loadLayout() const {
    if (def_.settingsFolder.empty()) return "";
    const std::string file = inFolder(def_.settingsFolder, "imgui.ini");
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return "";
    try {
        return game::readFile(file);
    } catch (const std::exception&) {
        return ""; // a layout that cannot be read is the default layout
    }
}

game::Progress PlayerFiles::loadProgress(const PlayerSettings& settings) {
    const std::string file = !def_.progressFile.empty() ? def_.progressFile
                             : def_.settingsFolder.empty()
                                 ? ""
                                 : inFolder(def_.settingsFolder, "progress.json");
    if (file.empty()) return {};
    std::string warning;
    if (def_.progressReadOnly) { // a check run: read, never move nor write
        std::error_code ec;
        try {
            if (std::filesystem::exists(file, ec))
                progressBase_ = game::parseProgress(file, game::readFile(file));
        } catch (const std::exception& e) {
            notices_.push_back(e.what());
        }
        return progressBase_;
    }
    progressBase_ = game::loadProgress(file, warning);
    if (!warning.empty()) notices_.push_back(warning);
    game::Progress progress = progressBase_;
    // Results an older settings file kept move into the progress file (saved before the
    // settings, which no longer write them, are saved without them).
    if (game::adoptOlderResults(progress, settings.results))
        for (const std::string& err : saveProgress(progress))
            notices_.push_back(err);
    return progress;
}

std::vector<std::string> PlayerFiles::saveProgress(game::Progress& progress) {
    if (progressFile_.empty()) return {};
    std::string warning;
    std::vector<std::string> said;
    if (const std::string err = game::saveProgressMerged(progressFile_, progressBase_, progress, warning);
        !err.empty())
        said.push_back("progress not saved: " + err);
    if (!warning.empty()) said.push_back(warning);
    return said;
}

std::vector<std::string> PlayerFiles::save(game::Progress& progress, PlayerSettings& settings,
                                           const std::string& layout) {
    std::vector<std::string> said = saveProgress(progress);
    if (settingsFile_.empty()) return said;
    if (const std::string err = savePlayerSettingsMerged(settingsFile_, settingsBase_, settings);
        !err.empty())
        said.push_back("settings not saved: " + err);
    try {
        game::writeFileAtomically(layoutFile_, layout);
    } catch (const std::exception& e) {
        said.push_back(std::string("window layout not saved: ") + e.what());
    }
    return said;
}

std::vector<std::string> PlayerFiles::takeNotices() {
    std::vector<std::string> out;
    out.swap(notices_);
    return out;
}

} // namespace ui
