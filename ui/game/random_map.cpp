#include "ui/game/random_map.h"

#include "game/files/text_file.h"
#include "game/generate/level_generator.h"

#include <filesystem>

namespace ui {

std::string randomMapsFolder(const std::string& settingsFolder) {
    if (settingsFolder.empty())
        return (std::filesystem::temp_directory_path() / "artillery_maps").string();
    return (std::filesystem::path(settingsFolder) / "maps").string();
}

std::optional<std::string> writeRandomMap(const RandomMapRequest& request,
                                          game::Difficulty difficulty, const std::string& folder,
                                          std::string& status) {
    game::generate::GenerateDef def;
    def.seed = request.seed;
    def.mode = request.duel ? game::Mode::Duel : game::Mode::Practice;
    def.difficulty = difficulty;
    const std::string seed = std::to_string(request.seed);
    const game::generate::Generated g = game::generate::generateLevel(def);
    if (!g.playable) {
        status = "seed " + seed + ": no playable map in " + std::to_string(g.candidates) +
                 " candidates; try another seed";
        return std::nullopt;
    }
    const std::string file =
        (std::filesystem::path(folder) / ("random_" + std::string(game::modeName(def.mode)) + "_" +
                                          seed + "_" + game::difficultyName(difficulty) + ".json"))
            .string();
    try {
        std::filesystem::create_directories(folder);
        game::writeFileAtomically(file, g.text);
    } catch (const std::exception& e) {
        status = std::string("not saved: ") + e.what();
        return std::nullopt;
    }
    status = "seed " + seed + " (" + game::difficultyName(difficulty) + "): candidate " +
             std::to_string(g.candidates) + ", saved as " + file;
    return file;
}

} // namespace ui
