// What the game remembers between runs: the player's choices (difficulty, hotseat,
// preview and hint toggles, what to draw) and the ImGui layout; the results of the levels
// are the progress file beside it (game/progress.h). Kept in
// $XDG_CONFIG_HOME/artillery (else ~/.config/artillery), written atomically (temp file
// + rename) so a crash never leaves half a file, and merged key by key with what another
// window of the game saved meanwhile.
#pragma once

#include "game/ai.h"
#include "game/audio/synthesizer.h"
#include "game/progress.h"

#include <map>
#include <string>

namespace ui {

using LevelResult = game::LevelResult;

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
    bool physicsPanel = false;     ///< the physics panel (F2), a lab panel: closed until asked for
    DrawChoices draw;
    /// Master, effects and UI volume (0..1) and mute: the settings panel's Sound section.
    game::audio::SoundMix sound;
    /// The level results an older settings file kept (its "levels" object), by level file
    /// name: read once to move them into the progress file, never written back.
    std::map<std::string, LevelResult> results;
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
/// Saves a run's settings beside other windows': under an advisory lock on FILE.lock it
/// reads the file again and writes, key by key, this run's value where this run changed
/// it (against `base`, the settings as it last read or wrote them) and the file's value
/// where it did not: the last change of each key wins, and a choice another window made
/// meanwhile is kept. On success `base` and `mine` become the merged whole. A file that
/// no longer parses is left as it is (nothing is saved over it). Returns "" or why not.
std::string savePlayerSettingsMerged(const std::string& file, PlayerSettings& base,
                                     PlayerSettings& mine);

/// The player's volumes, as the game's pause menu set them (settings.json in the config
/// folder), else the defaults: for the windows that are not the game's (the network duel,
/// the physics lab). A check run (`--frames`) reads nothing of the player's.
game::audio::SoundMix playerSoundMix(bool checkRun);

} // namespace ui
