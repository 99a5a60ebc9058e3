// The level select's Random map: generates the requested map (game/generate), writes it
// into the player's folder and says what happened, so the game screen can play it.
#pragma once

#include "game/ai.h"
#include "ui/game/game_menus.h"

#include <optional>
#include <string>

namespace ui {

/// The folder generated maps are written to: `settingsFolder`/maps, or the system's
/// temporary folder when the game keeps no settings (check runs, headless).
std::string randomMapsFolder(const std::string& settingsFolder);

/// Generates the map at `difficulty` (the computer's), writes it into `folder` as
/// random_MODE_SEED_DIFFICULTY.json and returns that file; on failure nullopt. Either way
/// `status` says what happened (the candidate taken, or why nothing was written).
std::optional<std::string> writeRandomMap(const RandomMapRequest& request,
                                          game::Difficulty difficulty, const std::string& folder,
                                          std::string& status);

} // namespace ui
