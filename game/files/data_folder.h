// Where the game's own data is: the shipped levels (and the campaign, levels/campaign.json).
// One place decides it, from where the executable is, so the game finds its levels from
// any working folder:
//   installed   <executable's folder>/../share/artillery (cmake --install, the .deb): a
//               path relative to the executable, so any prefix works;
//   build tree  the source tree the executable was built from (the build knows it);
//   elsewhere   the working folder.
#pragma once

#include <string>

namespace game {

/// The folder that holds levels/: the first of the three above that has a levels/ folder
/// ("." when none has).
std::string dataFolder();

/// dataFolder()'s levels/; written "levels" when that is the working folder's own levels/,
/// so a game started in the source tree records its level as the shipped replays do.
std::string levelsFolder();

/// The shipped level file `name` (like "10_duel.json") in levelsFolder().
std::string shippedLevel(const std::string& name);

} // namespace game
