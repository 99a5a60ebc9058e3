#include "game/files/output_path.h"

#include "game/files/text_file.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace game {

namespace {

/// 'PATH', printable (appended piece by piece: g++ 12 warns of a bogus overflow in
/// "'" + std::string).
std::string quoted(const std::string& path) {
    std::string q = "'";
    q += printable(path);
    q += "'";
    return q;
}

/// The reason an existing path cannot be a folder to write into, or "".
std::string notAFolder(const std::string& folder) {
    struct ::stat st {};
    if (::stat(folder.c_str(), &st) != 0) {
        if (errno == ENOENT) return "the folder " + quoted(folder) + " does not exist";
        if (errno == ENOTDIR) {
            // A path through a file: name the file ("plain.txt/frames": 'plain.txt').
            std::filesystem::path part = folder;
            std::error_code ec;
            while (part.has_parent_path() && part != part.parent_path() &&
                   !(std::filesystem::exists(part, ec) && !std::filesystem::is_directory(part, ec)))
                part = part.parent_path();
            return quoted(part.string()) + " is not a folder";
        }
        return "the folder " + quoted(folder) + " cannot be examined: " + std::strerror(errno);
    }
    if (!S_ISDIR(st.st_mode)) return quoted(folder) + " is not a folder";
    return "";
}

/// Creates and removes a file in `folder`: "" when it could, else why not.
std::string probe(const std::string& folder) {
    static std::atomic<unsigned> counter{0};
    const std::string name = (std::filesystem::path(folder) /
                              (".artillery-probe-" + std::to_string(::getpid()) + "-" +
                               std::to_string(counter++)))
                                 .string();
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0)
        return "the folder " + quoted(folder) + " does not take new files: " +
               std::strerror(errno);
    ::close(fd);
    ::unlink(name.c_str());
    return "";
}

} // namespace

std::string unwritableFolder(const std::string& folder, bool create) {
    if (folder.empty()) return "an empty folder name";
    std::error_code made;
    if (create) std::filesystem::create_directories(folder, made);
    if (std::string why = notAFolder(folder); !why.empty()) {
        // A folder that could not be made says why (read-only, permission, /proc).
        std::error_code ec;
        if (made && !std::filesystem::exists(folder, ec) && why.ends_with("does not exist"))
            return "the folder " + quoted(folder) + " cannot be made: " + made.message();
        return why;
    }
    return probe(folder);
}

std::string unwritableFile(const std::string& file) {
    if (file.empty()) return "an empty file name";
    const std::filesystem::path path(file);
    if (!path.has_filename() || path.filename() == "." || path.filename() == "..")
        return quoted(file) + " names a folder, not a file";
    const std::string folder = path.parent_path().empty() ? "." : path.parent_path().string();
    if (std::string why = notAFolder(folder); !why.empty()) return why;
    struct ::stat st {};
    if (::stat(file.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) return quoted(file) + " is a folder, not a file";
        if (!S_ISREG(st.st_mode)) return quoted(file) + " is not a regular file";
        if (::access(file.c_str(), W_OK) != 0)
            return "the file " + quoted(file) + " cannot be written: " + std::strerror(errno);
    }
    return probe(folder);
}

} // namespace game
