#include "game/cli/bench_options.h"

#include "game/cli/verbs.h"
#include "game/files/text_file.h"

#include <cstdio>
#include <iostream>

namespace game::cli::benchcli {

Size sizeOption(const Args& args) {
    const bool full = args.flag("full"), quick = args.flag("quick");
    if (full && quick) args.fail("--full and --quick cannot be combined");
    return full ? Size::Full : quick ? Size::Quick : Size::Default;
}

std::function<void(int, int)> progressLine(const std::string& what) {
    return [what](int done, int total) {
        std::fprintf(stderr, "\r%s: %d/%d", what.c_str(), done, total);
        if (done == total) std::fprintf(stderr, "\n");
        std::fflush(stderr);
    };
}

std::string outputPath(const Args& args, const std::string& name) {
    const std::string path = args.text(name).value_or("");
    if (!args.has(name)) args.fail("--" + name + " FILE is required");
    if (path.empty()) args.fail("--" + name + " expects a file name");
    requireWritableFile(args, name, path);
    return path;
}

void writeText(const std::string& path, const std::string& text) {
    // Written to a temporary file and renamed, so a reader never sees half a CSV.
    try {
        writeFileAtomically(path, text);
    } catch (const std::exception& e) {
        throw WorkError(std::string("artillery bench: the CSV was not written: ") + e.what());
    }
}

int chartOutcome(const std::string& png, const std::string& plotError) {
    if (plotError.empty()) return kOk;
    std::cerr << "artillery bench: cannot draw " << png << ": " << plotError << "\n";
    return kWorkFailed;
}

std::string andChart(const std::string& png, const std::string& plotError) {
    return plotError.empty() ? " and " + png : "";
}

} // namespace game::cli::benchcli
