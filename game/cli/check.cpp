// artillery check: validate level files.
#include "game/cli/verbs.h"

#include "game/files/json_reader.h"
#include "game/level.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace game::cli {

int runCheck(const Args& args, std::ostream& out) {
    args.text("<positional>"); // files are positional
    const bool json = args.flag("json");
    args.rejectUnknown();
    const auto& files = args.positionals();
    if (files.empty()) args.fail("name at least one level file, e.g. artillery check levels/*.json");

    int failed = 0;
    nlohmann::json report = nlohmann::json::array();
    for (const std::string& file : files) {
        try {
            const Level l = loadLevel(file);
            report.push_back({{"file", file},
                              {"ok", true},
                              {"name", l.name},
                              {"mode", modeName(l.mode)},
                              {"content_hash", l.contentHash}});
            if (!json)
                out << "ok    " << file << "  \"" << l.name << "\" (" << modeName(l.mode) << ", "
                    << l.cannons.size() << " cannon(s), " << l.targets.size() << " target(s), "
                    << l.blocks.size() << " block(s))\n";
        } catch (const LoadError& e) {
            ++failed;
            report.push_back({{"file", file}, {"ok", false}, {"path", e.path}, {"error", e.detail}});
            if (!json) out << "FAIL  " << e.what() << "\n";
        }
    }
    if (json) out << nlohmann::json{{"levels", report}, {"failed", failed}}.dump() << "\n";
    return failed ? kCheckFailed : kOk;
}

} // namespace game::cli
