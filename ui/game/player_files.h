// The player's files, as the game screen keeps them: the choices (settings.json), the
// window layout (imgui.ini), the campaign progress (progress.json, game/progress.h) and
// the folders the game writes into (replays/, maps/), all in one settings folder. With no
// folder (tests, headless, check runs) nothing is read or written: replays are not kept
// and random maps go to a temporary folder.
#pragma once

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
    /// Reads what the folder holds. Needs an ImGui context: the window layout goes into
    /// it. A damaged settings or progress file is kept as it is (the settings are then not
    /// saved over it); warning() says why.
    explicit PlayerFiles(const PlayerFilesDef& def);

    PlayerSettings& settings() { return settings_; }
    const PlayerSettings& settings() const { return settings_; }
    game::Progress& progress() { return progress_; }
    const game::Progress& progress() const { return progress_; }
    /// What went wrong reading the files ("" when nothing did), for the status line.
    const std::string& warning() const { return warning_; }

    /// Writes the progress, the settings (with the draw choices of `view`) and the window
    /// layout; a file that cannot be written is named on the terminal.
    void save(const ViewControls& view);
    /// A finished game's result for `levelFile`, saved at once. True for a new best.
    bool recordResult(const std::string& levelFile, int score, int stars, bool won,
                      bool assisted, const ViewControls& view);

    /// Where the game records replays ("" in check runs and headless: nowhere).
    std::string replaysFolder() const;
    /// `name` in the replays folder, the folder made if need be ("" when none is kept).
    std::string recordFileFor(const std::string& name) const;
    /// Where Save As, the playtest and random maps write levels: the player's maps folder.
    std::string mapsFolder() const;

  private:
    void loadSettings();
    void loadProgress();

    PlayerFilesDef def_;
    PlayerSettings settings_;
    game::Progress progress_;
    std::string settingsFile_, iniFile_, progressFile_;
    std::string warning_;
};

/// The view the window opens with: the player's stored draw choices, plus what the
/// command line turns on (its draw flags only switch things on).
ViewControls openingView(ViewControls flags, const DrawChoices& stored);
/// The draw toggles of `view`, as the settings file keeps them.
DrawChoices drawChoices(const ViewControls& view);

} // namespace ui
