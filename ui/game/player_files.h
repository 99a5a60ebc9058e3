// The player's files as a window of the game keeps them: the settings, the progress and
// the window layout in the settings folder (game/files/save_folder.h says whether it can
// be written, and where the replays go when it cannot), read when the game opens and
// saved merged with what another window of the game saved meanwhile (the progress per
// level, the settings per key, the layout whole: the last window closed keeps its own).
// Nothing here draws: the game screen shows the messages it returns.
#pragma once

#include "game/files/save_folder.h"
#include "game/progress.h"
#include "ui/game/player_settings.h"

#include <string>
#include <vector>

namespace ui {

struct PlayerFilesDef {
    std::string settingsFolder;    ///< "" = nowhere: nothing read or kept (tests, headless)
    std::string progressFile;      ///< "" = progress.json in settingsFolder, if any
    bool progressReadOnly = false; ///< read it, never write it (check runs)
};

class PlayerFiles {
  public:
    PlayerFiles() = default;
    /// Probes the folder (making it, and its replays/ folder, when missing).
    explicit PlayerFiles(const PlayerFilesDef& def);

    /// Reads the settings: the defaults when there are none, or when the file is damaged
    /// (then nothing is saved over it this run, and a message says so).
    PlayerSettings loadSettings();
    /// Reads the progress; results an older settings file kept move into it.
    game::Progress loadProgress(const PlayerSettings& settings);
    /// The window layout last saved (ImGui's ini text), "" when none.
    std::string loadLayout() const;

    /// Saves the progress, the settings and the layout. `progress` and `settings` take
    /// in what another window saved meanwhile. Returns what could not be saved, one
    /// message each (empty when everything was, or nothing is kept).
    std::vector<std::string> save(game::Progress& progress, PlayerSettings& settings,
                                  const std::string& layout);
    /// Only the progress (a result, a lesson read), merged likewise.
    std::vector<std::string> saveProgress(game::Progress& progress);

    /// Where replays go ("" = nowhere, or only in memory).
    const std::string& replaysFolder() const { return folder_.replaysFolder(); }
    /// What the player must be told once, when the game opens: the folder that cannot be
    /// written, a damaged file kept aside or left alone. Taken: the second call is empty.
    std::vector<std::string> takeNotices();
    /// A save the folder failed after all (a replay at a turn's end): the message the
    /// first time, "" after.
    std::string failedOnce(const std::string& what, const std::string& why) {
        return folder_.failedOnce(what, why);
    }

  private:
    PlayerFilesDef def_;
    game::SaveFolder folder_;
    std::string settingsFile_, layoutFile_, progressFile_; ///< "" = not saved
    PlayerSettings settingsBase_;  ///< the settings as last read or saved
    game::Progress progressBase_;  ///< the progress as last read or saved
    std::vector<std::string> notices_;
};

} // namespace ui
