// An advisory lock for a read-merge-write of a file two processes share (two windows of
// the game and their progress and settings). The lock is taken on a sibling file,
// FILE.lock, not on the data file: the data file is replaced by a rename when it is
// written (text_file.h), and a lock on the old file would not hold the new one. The lock
// file is never removed (removing it would let a third process lock a new one while the
// second still holds the old).
#pragma once

#include <string>

namespace game {

class FileLock {
  public:
    /// Locks `lockFile` (flock, exclusive; created when missing), waiting at most
    /// `seconds` for a process that holds it. locked() says whether it did; why() why not.
    FileLock(const std::string& lockFile, double seconds);
    ~FileLock();
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;

    bool locked() const { return fd_ >= 0; }
    const std::string& why() const { return why_; }

  private:
    int fd_ = -1;
    std::string why_;
};

/// The lock file of `file`: FILE.lock beside it.
std::string lockFileOf(const std::string& file);

} // namespace game
