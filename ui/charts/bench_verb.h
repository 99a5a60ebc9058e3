// `artillery bench` with its charts: the measuring verb of game/cli/bench.h, given the
// headless chart renderer for --png.
#pragma once

#include "game/cli/verbs.h"

namespace ui {

/// The bench verb for the verb list (ui/app.cpp).
const game::cli::Verb& benchVerb();

} // namespace ui
