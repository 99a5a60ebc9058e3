// Live physics controls as commands: the panel edits a copy of the match's live settings
// (world settings and materials), and what changed becomes `set` commands (by the names
// in game/settings.h) that go through Session::submit, so a replay carries every change
// the player made.
#pragma once

#include "game/command.h"
#include "game/settings.h"

#include <vector>

namespace ui {

/// One `set` command per setting whose value differs between `before` and `after`, in
/// the settings table's order (a pair given back to the rule is `"combine"`). "planet"
/// is left out: it is another name for gravity.
std::vector<game::Command> settingCommands(const game::LiveSettings& before,
                                           const game::LiveSettings& after);
/// The same for edits of the world's settings alone.
std::vector<game::Command> settingCommands(const phys::WorldDef& before, const phys::WorldDef& after);

} // namespace ui
