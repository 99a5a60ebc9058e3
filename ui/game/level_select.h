// The level select screen, as a game shows it: the campaign's chapters as pages of level
// tiles, each with a picture of the level drawn by the game's own renderer, its name, the
// stars earned and, while it is locked, why, in full. The next level on the way is
// highlighted and Enter plays it; the arrows turn the pages. Below: the other screens
// (replays, a random map, the level editor, the network duel) and the player's choices.
#pragma once

#include "game/progress.h"
#include "ui/game/campaign_view.h"
#include "ui/game/game_menus.h"
#include "ui/game/level_thumbnails.h"
#include "ui/game/player_settings.h"

#include <cstddef>
#include <vector>

namespace ui {

/// Which page is shown: a chapter, or the levels outside the chapters after the last.
struct LevelSelectState {
    std::size_t page = 0;
    bool opened = false; ///< the page was set where the player left off
};

/// What the screen offers besides the campaign: the Random map and Level editor forms
/// over `levels`, and the player's choices.
struct LevelSelectForms {
    RandomMapForm* randomMap = nullptr;
    LevelEditorForm* editor = nullptr;
    const std::vector<LevelEntry>* levels = nullptr;
};

/// Draws one frame of the level select; what the player chose. `pictures` draws the
/// tiles' pictures (then binds `fbo` for drawing again).
MenuChoice levelSelectScreen(const CampaignMenu& campaign, const game::Progress& progress,
                             PlayerSettings& settings, LevelSelectState& state,
                             LevelThumbnails& pictures, unsigned fbo, const LevelSelectForms& forms);

} // namespace ui
