// The verbs of the `artillery` executable that need no window. ui/ adds the ones
// that do (play) and dispatches all of them.
#pragma once

#include "game/cli/args.h"
#include "game/cli/video_request.h"
#include "physics/integrators.h"

#include <functional>
#include <iosfwd>
#include <memory>
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
/// Refuses (bad input, before any work) an output file of `--option` that cannot be
/// written: a missing folder, a path that is no folder, a folder that takes no new file
/// (game/files/output_path.h).
void requireWritableFile(const Args& args, const std::string& option, const std::string& file);
/// The same for an output folder; with `create` it is made first, as the writer would.
void requireWritableFolder(const Args& args, const std::string& option, const std::string& folder,
                           bool create);

int runSolve(const Args& args, std::ostream& out);
int runTrajectory(const Args& args, std::ostream& out);
int runSpring(const Args& args, std::ostream& out);
int runDrop(const Args& args, std::ostream& out);
int runCheck(const Args& args, std::ostream& out);
int runReplayVerify(const Args& args, std::ostream& out);
int runRun(const Args& args, std::ostream& out);
int runSolveLevel(const Args& args, std::ostream& out);
int runGenerate(const Args& args, std::ostream& out);

} // namespace game::cli

namespace game {
class FrameSink;
}

namespace game::cli {

/// Makes a frame sink that writes PNGs into a folder (ui/ provides it): (folder, width,
/// height, draw the HUD, error out) -> sink or nullptr with the reason.
using FrameSinkFactory = std::function<std::unique_ptr<FrameSink>(
    const std::string& folder, int width, int height, bool hud, std::string& why)>;

/// `artillery run` with an optional renderer for --png and video encoder for --video.
int runHeadlessVerb(const Args& args, std::ostream& out, const FrameSinkFactory* sinks,
                    const VideoSinkFactory* videos = nullptr);

} // namespace game::cli
