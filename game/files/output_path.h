// Where a verb is about to write, checked before the work starts: a run that simulates
// for minutes and then cannot save its replay has lost the player's time. A folder is
// judged by what it does, not by its permission bits (root ignores them, and a
// read-only mount or /proc refuses whatever they say): a probe file is created in it
// and removed.
#pragma once

#include <string>

namespace game {

/// "" when `file` can be written: its folder exists, is a folder and takes a new file,
/// and the file, if it is there already, is a regular file that may be written. Else one
/// line naming the path and the reason ("the folder '/nonexistent/dir' does not exist",
/// "'/etc/passwd' is not a folder", "the folder '/proc' does not take new files:
/// Permission denied", "'out' is a folder, not a file").
std::string unwritableFile(const std::string& file);

/// The same for a folder that files will be written into. With `create`, the folder
/// (and its parents) is made first, as the writer would make it.
std::string unwritableFolder(const std::string& folder, bool create);

} // namespace game
