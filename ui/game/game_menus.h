// The game's ImGui screens and overlays: level select (the campaign's chapters, drawn by
// ui/game/campaign_view.*), the recorded replays, the pause menu (rewinding included), help,
// and the row of a turn's controls for the mouse. Each is a function that draws one frame of
// it and reports what the player chose, as Dear ImGui's widgets do; the game screen acts on it.
#pragma once

#include "game/match.h"
#include "game/progress.h"
#include "ui/game/player_settings.h"
#include "ui/play/physics_panel.h"

#include <imgui.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ui {

/// One shipped level as the select screen lists it.
struct LevelEntry {
    std::string file;
    std::string name;
    std::string lesson;
    game::Mode mode = game::Mode::Practice; ///< what the file says (when it loads)
    std::string error; ///< why it does not load ("" when it does)
    std::vector<std::string> weapons; ///< the weapons its cannons offer, in their order
};

/// Every *.json in `folder`, sorted by file name, each loaded to read its name and lesson.
std::vector<LevelEntry> listLevels(const std::string& folder);

/// A replay the game recorded, as the Replays screen lists it.
struct ReplayEntry {
    std::string file;
    std::string level;    ///< the level's name
    double seconds = 0.0; ///< length of the recording
    int shots = 0;
    std::string modified; ///< when it was last written, "YYYY-MM-DD HH:MM"
    std::string error;    ///< why it cannot be watched ("" when it can)
};

/// Every *.json in `folder` (the replays the game records), newest first, each loaded
/// with its level to check it can be watched.
std::vector<ReplayEntry> listReplays(const std::string& folder);

enum class Overlay { None, LevelSelect, Replays, Pause, Lesson };

/// The level select's Random map row: the seed (typed to play a shared map, or drawn
/// anew) and practice or duel; the difficulty is the computer's.
struct RandomMapForm {
    char seed[24] = "1";
    bool duel = false;
    std::string status; ///< what the last Generate did
};

/// A map to generate and play at once.
struct RandomMapRequest {
    std::uint64_t seed = 1;
    bool duel = false;
};

/// The level select's Level editor row: a new level, or one of the listed levels to
/// edit, or back to the level being edited.
struct LevelEditorForm {
    int selected = 0;      ///< index into the level list shown
    std::string editing;   ///< the name of the level the editor holds ("" = none open)
};

/// What the player picked in a menu this frame.
struct MenuChoice {
    std::optional<std::string> openLevel; ///< a level file to play
    std::optional<std::string> openReplay; ///< a replay file to watch
    bool replays = false;                  ///< show the recorded replays
    bool networkDuel = false;              ///< leave for the network duel screen (ui/net)
    bool resume = false;
    bool restart = false;
    bool levelSelect = false;
    bool help = false;
    bool quit = false;
    bool settingsChanged = false; ///< difficulty, hotseat or toggles (persist them)
    std::optional<std::size_t> showLesson; ///< a chapter's lesson screen (campaign index)
    std::string lessonThenLevel;           ///< the level its Play button opens ("" = none)
    std::optional<std::string> lessonSeen; ///< a chapter id whose lesson was read
    std::optional<RandomMapRequest> randomMap; ///< generate this map and play it
    std::optional<std::string> editLevel; ///< open the editor on this file ("" = a new level)
    bool continueEditing = false;         ///< back to the level the editor holds
    std::optional<std::uint64_t> rewindTo; ///< go back to this tick and play on (a branch)
    bool watchLastShot = false;            ///< the last shot again (ReplayControl::watchLastShot)
};

/// The computer's difficulty, as a combo box; true when changed.
bool difficultyCombo(PlayerSettings& settings);
/// The Random map form: a seed (typed to play a shared map, or drawn anew), practice or
/// duel, and Generate, which asks for the map to be made and played (choice.randomMap).
void randomMapRow(RandomMapForm& form, MenuChoice& choice);
/// The Level editor form: a new level, one of `levels` to edit, or back to the one the
/// editor holds (choice.editLevel, choice.continueEditing).
void levelEditorRow(LevelEditorForm& form, const std::vector<LevelEntry>& levels, MenuChoice& choice);

/// The replays in `folder` ("" when this run keeps none: check runs, headless).
MenuChoice replaysScreen(const std::vector<ReplayEntry>& replays, const std::string& folder);
/// The pause menu's rewind slider: the moment it points at while it is dragged.
struct RewindControl {
    double seconds = 0.0;
    bool dragging = false;
};

/// The pause menu: resume, restart, levels, help, the rewind slider and the last shot
/// again (over `match`, when one is played), the player's choices and the Sound section.
/// `silentWhy` is why the game plays silent ("" when it plays sound).
MenuChoice pauseMenu(PlayerSettings& settings, const std::string& silentWhy,
                     const game::Match* match, RewindControl& rewind);
/// The Sound section: master, effects and UI volume and mute. True once an edit is done
/// (a slider let go, the box ticked): time to save the settings.
bool soundSection(game::audio::SoundMix& mix, const std::string& silentWhy);
/// The keyboard, mouse and controller shortcuts. `open` is cleared by its close button.
void helpOverlay(bool& open);

/// What the turn's controls asked for this frame.
struct MatchPanelRequests {
    bool fire = false;
    bool endTurn = false;
    std::optional<std::size_t> projectile;
    bool settingsChanged = false;
    bool menu = false; ///< the pause menu
};

/// The controls of a turn for the mouse, in one row with its top-left corner at `corner`
/// (window points): the projectile, Fire, End turn (duels) and the pause menu. `humanTurn`
/// greys out what only a person on turn may do.
MatchPanelRequests matchControls(const game::Match& match, bool humanTurn, ImVec2 corner);

} // namespace ui
