// The folder the game keeps the player's things in (settings, progress, replays, maps:
// $XDG_CONFIG_HOME/artillery), and whether it can. A folder that cannot be written (read
// only, a file where the folder should be, /proc) must not close the game: it plays on,
// says once where and why nothing will be saved, and records its replays in a temporary
// folder it names (or, when even that fails, keeps them in memory only).
#pragma once

#include <string>

namespace game {

class SaveFolder {
  public:
    /// Nowhere: nothing is kept and nothing is said (check runs, headless pictures).
    SaveFolder() = default;
    /// Makes `folder` (and its replays/ folder) if it is not there, and tries a file in
    /// each: what cannot be written is found now, before anything is played.
    explicit SaveFolder(const std::string& folder);

    /// The folder as given ("" = nowhere).
    const std::string& folder() const { return folder_; }
    /// The folder takes files (settings, progress and the window layout are saved).
    bool writable() const { return writable_; }
    /// FOLDER/name when the folder takes files, else "" (nothing to save to).
    std::string fileToWrite(const std::string& name) const;
    /// Where replays go: FOLDER/replays; a temporary folder made for this run when that
    /// cannot be written; "" when there is none (recordings then stay in memory).
    const std::string& replaysFolder() const { return replays_; }
    /// Where and why nothing will be saved, and where the replays go: one message, said
    /// once when the game opens. "" when everything can be saved.
    const std::string& notice() const { return notice_; }
    /// A save that failed all the same (a disk that filled up): the message to show the
    /// player the first time, "" after (the game plays on; it says it once).
    std::string failedOnce(const std::string& what, const std::string& why);

  private:
    std::string folder_;
    bool writable_ = false;
    std::string replays_;
    std::string notice_;
    bool failureSaid_ = false;
};

} // namespace game
