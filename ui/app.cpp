#include "ui/app.h"

#include "game/cli/verbs.h"
#include "game/files/text_file.h"
#include "ui/charts/bench_verb.h"
#include "ui/game/png_frames.h"
#include "ui/icon/game_icon.h"
#include "ui/net/net_verbs.h"
#include "ui/play/play_verb.h"

#include <string_view>

#include <algorithm>
#include <csignal>
#include <iostream>
#include <string>
#include <vector>

namespace ui {

namespace {

std::vector<game::cli::Verb> allVerbs() {
    // play first: it is what a player runs; then the verbs that need no window, with
    // `run` replaced by the same verb given the renderer (so --png works).
    std::vector<game::cli::Verb> all{playVerb()};
    for (const game::cli::Verb& v : game::cli::verbs())
        all.push_back(std::string_view(v.name) == "run" ? runVerbWithRenderer() : v);
    all.push_back(benchVerb()); // draws its charts with the renderer, so it lives in ui/
    all.push_back(net::hostVerb()); // sockets live beside the window, not in game/
    all.push_back(net::joinVerb());
    all.push_back(iconVerb()); // drawn by the renderer, like the charts
    return all;
}

void printOverview(std::ostream& out) {
    out << "artillery: a 2D physics playground and artillery game\n\n"
           "usage: artillery VERB [options]    (artillery VERB --help for each verb)\n\n"
           "verbs:\n";
    // The summaries line up two spaces after the longest verb name (12 columns at least).
    std::size_t width = 12;
    for (const auto& v : allVerbs()) width = std::max(width, std::string(v.name).size() + 2);
    for (const auto& v : allVerbs()) {
        std::string name = v.name;
        name.resize(width, ' ');
        out << "  " << name << v.summary << "\n";
    }
    out << "\nEvery verb takes --json for machine-readable output. Exit codes: 0 ok,\n"
           "1 check failed, 2 bad input (an output that cannot be written included, refused\n"
           "before any work), 3 the work failed (a file could not be written as it ran).\n"
           "artillery --version prints the version.\n";
}

/// One line on standard error, "artillery VERB: ...", whatever threw it.
void sayOneLine(const std::string& verb, const std::string& what) {
    std::string line = what.rfind("artillery ", 0) == 0 ? what : "artillery " + verb + ": " + what;
    for (char& c : line)
        if (c == '\n') c = ' ';
    std::cerr << line << "\n";
}

/// Runs one verb: whatever it throws ends as one line and an exit code, never an abort.
/// Bad input (an option, a file it reads, a path it would write) is 2; anything that
/// fails once the work has started (a write that fails, memory) is 3.
int runVerb(const game::cli::Verb& v, int argc, const char* const* argv) {
    try {
        game::cli::Args args(v.name, argc, argv, 2, v.flags, v.usage);
        if (args.flag("help")) {
            std::cout << v.usage;
            return game::cli::kOk;
        }
        const int code = v.run(args, std::cout);
        // What the verb printed is its output too: a standard output that cannot take it
        // (a full disk, /dev/full) is a failure of the work, not a success.
        if (!std::cout.flush()) {
            sayOneLine(v.name, "standard output could not be written");
            return game::cli::kWorkFailed;
        }
        return code;
    } catch (const game::cli::UsageError& e) {
        sayOneLine(v.name, e.what());
        return game::cli::kBadInput;
    } catch (const game::LoadError& e) {
        sayOneLine(v.name, e.what());
        return game::cli::kBadInput;
    } catch (const std::exception& e) {
        sayOneLine(v.name, e.what());
        return game::cli::kWorkFailed;
    } catch (...) {
        sayOneLine(v.name, "failed with an unknown error");
        return game::cli::kWorkFailed;
    }
}

} // namespace

int runApp(int argc, const char* const* argv) {
    if (argc < 2) return runDefault(std::cout, printOverview);
    const std::string verb = argv[1];
    if (verb == "--help" || verb == "-h" || verb == "help") {
        printOverview(std::cout);
        return game::cli::kOk;
    }
    if (verb == "--version") {
        std::cout << "artillery " << ARTILLERY_VERSION << "\n";
        return game::cli::kOk;
    }
    // A file size limit (ulimit -f) makes a write fail with EFBIG, reported as any
    // failed write is, instead of killing the process with SIGXFSZ.
    std::signal(SIGXFSZ, SIG_IGN);
    for (const auto& v : allVerbs())
        if (verb == v.name) return runVerb(v, argc, argv);
    std::cerr << "artillery: unknown verb '" << verb << "' (run artillery --help for the list)\n";
    return game::cli::kBadInput;
}

} // namespace ui
