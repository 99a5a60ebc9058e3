// `artillery play`: the game in a window, or headless through OSMesa/EGL with the same
// drawing code, and what `artillery` with no arguments does.
#pragma once

#include "game/cli/verbs.h"

#include <iosfwd>

namespace ui {

/// The play verb for the verb list.
const game::cli::Verb& playVerb();

int runPlay(const game::cli::Args& args, std::ostream& out);

/// `artillery` with no arguments: play in a window when there is a display; else render
/// the headless demo to a PNG, say where it is, and list the verbs.
int runDefault(std::ostream& out, void (*printOverview)(std::ostream&));

} // namespace ui
