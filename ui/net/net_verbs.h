// `artillery host` and `artillery join`: a duel over the network, headless (a script or
// the computer plays the local cannon) or in a window (--window).
#pragma once

#include "game/cli/verbs.h"

namespace ui::net {

const game::cli::Verb& hostVerb();
const game::cli::Verb& joinVerb();

} // namespace ui::net
