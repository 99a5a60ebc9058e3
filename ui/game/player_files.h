// The player's files, as a window of the game keeps them: the choices (settings.json), the
// window layout (imgui.ini), the campaign progress (progress.json, game/progress.h) and
// the folders the game writes into (replays/, maps/), all in one settings folder. Saved
// merged with what another window of the game saved meanwhile (the progress per level,
// the settings per key, the layout whole: the last window closed keeps its own). A folder
// that cannot be written (game/files/save_folder.h) never closes the game: it plays on,
// says once why nothing is saved, and records its replays in a temporary folder. With no
// folder (tests, headless, check runs) nothing is read or written: replays are not kept
// and random maps go to a temporary folder.
#pragma once

#include "game/files/save_folder.h"
#include "game/progress.h"
#include "ui/game/player_settings.h"
#include "ui/play/physics_panel.h"

#include <string>

namespace ui {

struct PlayerFilesDef {
    std::string settingsFolder;    ///< "" = nowhere
    std::string progressFile;      ///< "" = progress.json in settingsFolder, if any
    bool progressReadOnly = false; ///< read it, never write it (check runs)
};

class PlayerFiles {
  public:
    /// Probes the folder (making it, and its replays/ folder, when missing) and reads what
    /// it holds. Needs an ImGui context: the window layout goes into it. A damaged settings
    /// or progress file is kept as it is (the settings are then not saved over it), and a
    /// folder that cannot be written is said once; warning() says why.
    explicit PlayerFiles(const PlayerFilesDef& def);

    PlayerSettings& settings() { return settings_; }
    const PlayerSettings& settings() const { return settings_; }
    game::Progress& progress() { return progress_; }
    const game::Progress& progress() const { return progress_; }
    /// What went wrong opening the files ("" when nothing did), for the status line.
    const std::string& warning() const { return warning_; }

    /// Writes the progress, the settings (with the draw choices of `view`) and the window
    /// layout, each merged with what another window saved meanwhile; a file that cannot be
    /// written is named on the terminal (once the game is open, the status line says the
    /// first failure).
    void save(const ViewControls& view);
    /// A finished game's result for `levelFile`, saved at once. True for a new best.
    bool recordResult(const std::string& levelFile, int score, int stars, bool won,
                      bool assisted, const ViewControls& view);

    /// Where the game records replays: the folder's replays/, a temporary folder when it
    /// cannot be written, "" in check runs and headless (nowhere).
    std::string replaysFolder() const { return folder_.replaysFolder(); }
    /// `name` in the replays folder, the folder made if need be ("" when none is kept).
    std::string recordFileFor(const std::string& name) const;
    /// Where Save As, the playtest and random maps write levels: the player's maps folder.
    std::string mapsFolder() const;
    /// A save that failed once the game was open (a replay at a turn's end): the message
    /// the first time, "" after (the game plays on; it says it once).
    std::string failedOnce(const std::string& what, const std::string& why) {
        return folder_.failedOnce(what, why);
    }

  private:
    void loadSettings();
    void loadProgress();
    void saveProgress();
    void say(const std::string& message);

    PlayerFilesDef def_;
    game::SaveFolder folder_;
    PlayerSettings settings_;
    PlayerSettings settingsBase_; ///< the settings as last read or saved: what changed merges
    game::Progress progress_;
    game::Progress progressBase_; ///< the progress as last read or saved
    std::string settingsFile_, iniFile_, progressFile_; ///< "" = not saved
    std::string warning_;
};

/// The view the window opens with: the player's stored draw choices, plus what the
/// command line turns on (its draw flags only switch things on).
ViewControls openingView(ViewControls flags, const DrawChoices& stored);
/// The draw toggles of `view`, as the settings file keeps them.
DrawChoices drawChoices(const ViewControls& view);

} // namespace ui
