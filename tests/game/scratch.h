// A folder of a test's own, empty, under the system's temporary folder: named after the
// test and this process (CTest runs test programs side by side). The test removes it.
#pragma once

#include <filesystem>
#include <string>
#include <unistd.h>

inline std::filesystem::path scratchFolder(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("artillery-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}
