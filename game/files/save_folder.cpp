#include "game/files/save_folder.h"

#include "game/files/output_path.h"

#include <cstdlib>
#include <filesystem>
#include <unistd.h>
#include <vector>

namespace game {

namespace {

/// A new folder of its own under the system's temporary folder, or "" when none can be
/// made.
std::string temporaryReplaysFolder() {
    std::error_code ec;
    const std::filesystem::path tmp = std::filesystem::temp_directory_path(ec);
    if (ec) return "";
    std::string pattern = (tmp / "artillery-replays-XXXXXX").string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (!::mkdtemp(name.data())) return "";
    return name.data();
}

} // namespace

SaveFolder::SaveFolder(const std::string& folder) : folder_(folder) {
    if (folder_.empty()) return;
    const std::string why = unwritableFolder(folder_, true);
    writable_ = why.empty();
    const std::string replays = (std::filesystem::path(folder_) / "replays").string();
    const std::string replaysWhy = writable_ ? unwritableFolder(replays, true) : why;
    if (replaysWhy.empty()) {
        replays_ = replays;
        return;
    }
    replays_ = temporaryReplaysFolder();
    const std::string where =
        replays_.empty() ? "replays are kept in memory only, until the game closes"
                         : "replays go to " + replays_ + " for this run";
    notice_ = writable_ ? "replays cannot be saved in " + replays + " (" + replaysWhy + "): " + where
                        : "nothing will be saved in " + folder_ + " (" + why +
                              "): not the settings, the progress nor the replays; " + where;
}

std::string SaveFolder::fileToWrite(const std::string& name) const {
    if (!writable_) return "";
    return (std::filesystem::path(folder_) / name).string();
}

std::string SaveFolder::failedOnce(const std::string& what, const std::string& why) {
    if (failureSaid_) return "";
    failureSaid_ = true;
    return what + " not saved: " + why + " (the game plays on; later saves are tried again)";
}

} // namespace game
