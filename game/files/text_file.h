// Text files as every loader and saver of the game handles them: read whole within a
// size limit and refused before a byte is read when they are no regular file; written
// atomically; and their errors, which name the file, the place in it and what was
// expected, in text that prints cleanly whatever bytes the file held. JSON's own reading
// is game/files/json_reader.h, which builds on this.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace game {

/// One clear message: "FILE: PATH: what was expected (got what)".
struct LoadError : std::runtime_error {
    LoadError(const std::string& file, const std::string& path, const std::string& message);
    std::string file, path, detail;
};

/// The largest file any loader reads (levels, replays, command scripts, settings), bytes.
inline constexpr std::size_t kMaxFileBytes = 16u << 20;

/// Reads a whole regular file of at most kMaxFileBytes; a missing or unreadable file, a
/// device, a FIFO or a directory, or a larger file is a LoadError before anything is read.
std::string readFile(const std::string& file);
/// Writes text to path atomically: a temporary file in the same folder, flushed and
/// fsync'd, then renamed over the target, so a crash leaves the old file or the new
/// one, never half of either. Throws std::runtime_error on failure.
void writeFileAtomically(const std::string& path, const std::string& text);

/// The text with every byte that is not part of valid UTF-8 (and every control
/// character but tab) written as \xNN, so a message quoting a file prints cleanly.
std::string printable(const std::string& text);
/// Characters (UTF-8 code points) in text; an invalid byte counts as one.
std::size_t characterCount(const std::string& text);

/// FNV-1a 64 of the bytes, as 16 hex digits (levels' content hash in replays).
std::string contentHash(const std::string& bytes);

} // namespace game
