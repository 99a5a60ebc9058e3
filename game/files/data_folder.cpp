#include "game/files/data_folder.h"

#include <filesystem>
#include <system_error>

namespace game {

namespace fs = std::filesystem;

namespace {

bool hasLevels(const fs::path& folder) {
    std::error_code ec;
    return fs::is_directory(folder / "levels", ec);
}

/// The running executable (Linux: /proc/self/exe), "" when it cannot be read.
fs::path executable() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path{} : exe;
}

} // namespace

std::string dataFolder() {
    if (const fs::path exe = executable(); !exe.empty()) {
        const fs::path installed =
            (exe.parent_path() / ".." / "share" / "artillery").lexically_normal();
        if (hasLevels(installed)) return installed.string();
    }
#ifdef ARTILLERY_SOURCE_TREE
    if (hasLevels(ARTILLERY_SOURCE_TREE)) return ARTILLERY_SOURCE_TREE;
#endif
    return ".";
}

std::string levelsFolder() {
    const fs::path levels = fs::path(dataFolder()) / "levels";
    std::error_code ec;
    if (fs::equivalent(levels, "levels", ec)) return "levels";
    return levels.string();
}

std::string shippedLevel(const std::string& name) {
    return (fs::path(levelsFolder()) / name).string();
}

} // namespace game
