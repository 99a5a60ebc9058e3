// The `artillery` executable: verb dispatch. Verbs that need no window come from
// game::cli; the window's verbs are added here.
#pragma once

namespace ui {

/// Runs the command line; returns the process exit code (0 ok, 1 check failed, 2 bad
/// input, 3 the work failed).
int runApp(int argc, const char* const* argv);

} // namespace ui
