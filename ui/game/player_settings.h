// What the game remembers between runs: the best result of every level, the player's
// choices (difficulty, hotseat, preview and hint toggles, what to draw) and the ImGui
// layout. Kept in
// $XDG_CONFIG_HOME/artillery (else ~/.config/artillery), written atomically (temp file
// + rename) so a crash never leaves half a file.
#pragma once

#include "game/ai.h"

#include <map>
#include <string>

namespace ui {

struct LevelResult {
    int bestScore = 0;
    int stars = 0;      ///< 0..3
    int plays = 0;      ///< matches finished
    bool won = false;   ///< duel: beaten at least once
    /// The best stars so far came only with a learning aid (full preview or hint) in
    /// view, so they are at most two; the level select says so.
    bool assisted = false;
};

/// The Draw toggles as the player left them (the panel's view section: MatchView's trails,
/// the labels, and the debug overlays of ui/render/world_view.h).
struct DrawChoices {
    bool trails = true;
    bool labels = true;
    bool velocities = false;
    bool forces = false;
    bool ghosts = false;
    bool contacts = false;
    bool cells = false;
    bool sleeping = false;
    bool models = false;
    bool operator==(const DrawChoices&) const = default;
};

struct PlayerSettings {
    game::Difficulty difficulty = game::Difficulty::Normal;
    bool hotseat = false;          ///< a duel's "cpu" cannon is played by a second person
    bool trajectoryPreview = true;
    bool fullPreview = false;      ///< the whole path, not the launch arc (assisted: no third star)
    bool solutionHint = false;     ///< assisted: no third star
    bool cameraFollow = true;      ///< the camera follows the shell and frames the impact
    bool screenShake = true;       ///< blasts shake the view (off for comfort)
    bool physicsPanel = true;
    DrawChoices draw;
    /// By level file name (not path), so results survive moving the folder.
    std::map<std::string, LevelResult> results;

    /// Records a finished match; returns true when it beat the stored best (as many stars
    /// without an aid as before with one counts).
    bool record(const std::string& levelFile, int score, int stars, bool won, bool assisted = false);
    const LevelResult* result(const std::string& levelFile) const;
};

/// The folder settings live in ("" when neither XDG_CONFIG_HOME nor HOME is set).
std::string configFolder();

/// Parses a settings file strictly; throws game::LoadError naming the file, the JSON
/// path and what was expected (unknown fields, wrong types, out-of-range values).
PlayerSettings parsePlayerSettings(const std::string& file, const std::string& text);
/// Reads settings; a missing file gives the defaults, a damaged one the defaults and the
/// reason in `warning` (empty when the file was fine or absent). The caller must then
/// not save over the damaged file.
PlayerSettings loadPlayerSettings(const std::string& file, std::string& warning);
/// Writes atomically, creating the folder. Returns "" or why it failed.
std::string savePlayerSettings(const std::string& file, const PlayerSettings& settings);

} // namespace ui
