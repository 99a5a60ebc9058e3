// The verbs of the `artillery` executable that need no window. ui/ adds the ones
// that do (play) and dispatches all of them.
#pragma once

#include "game/cli/args.h"
#include "physics/integrators.h"

#include <iosfwd>
#include <span>

namespace game::cli {

struct Verb {
    const char* name;
    const char* summary; ///< one line for the verb list
    const char* usage;   ///< full --help text
    std::set<std::string> flags; ///< options that take no value (besides --json, --help)
    int (*run)(const Args& args, std::ostream& out);
};

/// The verbs this layer provides, in the order the help lists them.
std::span<const Verb> verbs();

// Options several verbs share.
/// --gravity G (m/s^2) or --planet NAME; default Earth.
double gravityOption(const Args& args);
/// --integrator NAME; `fallback` when absent.
phys::Integrator integratorOption(const Args& args, phys::Integrator fallback);

int runSolve(const Args& args, std::ostream& out);
int runTrajectory(const Args& args, std::ostream& out);
int runSpring(const Args& args, std::ostream& out);
int runCheck(const Args& args, std::ostream& out);

} // namespace game::cli
