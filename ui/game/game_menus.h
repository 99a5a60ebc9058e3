// The game's ImGui screens and overlays: level select, pause menu, help, and the side
// panel with the match controls. Each is a function that draws one frame of it and
// reports what the player chose (STYLE.md, "Dear ImGui"); the game screen acts on it.
#pragma once

#include "game/match.h"
#include "ui/game/player_settings.h"
#include "ui/play/physics_panel.h"

#include <optional>
#include <string>
#include <vector>

namespace ui {

/// One shipped level as the select screen lists it.
struct LevelEntry {
    std::string file;
    std::string name;
    std::string lesson;
    std::string mode;
    std::string error; ///< why it does not load ("" when it does)
};

/// Every *.json in `folder`, sorted by file name, each loaded to read its name and lesson.
std::vector<LevelEntry> listLevels(const std::string& folder);

enum class Overlay { None, LevelSelect, Pause };

/// What the player picked in a menu this frame.
struct MenuChoice {
    std::optional<std::string> openLevel; ///< a level file to play
    bool resume = false;
    bool restart = false;
    bool levelSelect = false;
    bool help = false;
    bool quit = false;
    bool settingsChanged = false; ///< difficulty, hotseat or toggles (persist them)
};

MenuChoice levelSelectScreen(const std::vector<LevelEntry>& levels, PlayerSettings& settings);
MenuChoice pauseMenu(PlayerSettings& settings);
/// The keyboard, mouse and controller shortcuts. `open` is cleared by its close button.
void helpOverlay(bool& open);

/// What the match panel asked for this frame.
struct MatchPanelRequests {
    bool fire = false;
    bool endTurn = false;
    std::optional<std::size_t> projectile;
    bool settingsChanged = false;
};

/// The left-hand match panel: projectile combo, Fire and End turn buttons, the preview
/// and hint toggles, the difficulty in use. `humanTurn` greys out what only a person
/// on turn may do.
MatchPanelRequests matchPanel(const game::Match& match, bool humanTurn, PlayerSettings& settings,
                              game::Difficulty inUse, bool hotseatInUse);

} // namespace ui
