#include "game/files/file_lock.h"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <thread>
#include <unistd.h>

namespace game {

FileLock::FileLock(const std::string& lockFile, double seconds) {
    const int fd = ::open(lockFile.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
        why_ = "cannot open the lock file " + lockFile + ": " + std::strerror(errno);
        return;
    }
    // Polled rather than blocking: a process that hangs while it holds the lock must not
    // hang this one too. A read-merge-write holds it for milliseconds.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    for (;;) {
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
            fd_ = fd;
            return;
        }
        if (errno != EWOULDBLOCK && errno != EINTR) {
            why_ = "cannot lock " + lockFile + ": " + std::strerror(errno);
            break;
        }
        if (std::chrono::steady_clock::now() >= deadline) {
            why_ = "another process has held " + lockFile + " for over " +
                   std::to_string(static_cast<int>(seconds)) + " s";
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ::close(fd);
}

FileLock::~FileLock() {
    if (fd_ >= 0) ::close(fd_); // closing the descriptor releases the lock
}

std::string lockFileOf(const std::string& file) { return file + ".lock"; }

} // namespace game
