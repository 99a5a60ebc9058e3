// A level back to its file: the JSON format of levels/README.md, so a level built or
// edited in memory (a generated map, the editor's) is saved as a file `check` and the
// loader accept. Loading the written text gives the same level field by field.
#pragma once

#include "game/level.h"

#include <string>

namespace game {

/// The level as JSON text in the level format, two-space indented, ending in a newline.
/// Fields at their loader default are still written where a reader of the file wants to
/// see them (positions, sizes, speeds); optional parts (paths, ropes' block ties, water)
/// only when present. Numbers are written in the shortest form that reads back exactly.
std::string levelToJson(const Level& level);

/// Writes levelToJson(level) to `file` atomically (temporary file + rename), so a crash
/// leaves the old file or the new one. Throws std::runtime_error naming the file.
void saveLevel(const std::string& file, const Level& level);

} // namespace game
