// artillery check: validate level files.
#include "game/cli/verbs.h"

#include "game/campaign.h"
#include "game/files/json_reader.h"
#include "game/level.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <ostream>

namespace game::cli {

namespace {

/// The campaign against the levels folder beside it: one entry per problem found.
int checkCampaign(const std::string& file, bool json, nlohmann::json& report, std::ostream& out) {
    try {
        const Campaign c = loadCampaign(file);
        const std::string folder = std::filesystem::path(file).parent_path().string();
        const std::vector<std::string> problems =
            campaignProblems(c, folder.empty() ? "." : folder);
        std::size_t levels = 0;
        for (const Chapter& ch : c.chapters)
            levels += ch.levels.size();
        report.push_back({{"file", file},
                          {"ok", problems.empty()},
                          {"campaign", true},
                          {"chapters", c.chapters.size()},
                          {"levels", levels},
                          {"problems", problems}});
        if (!json) {
            if (problems.empty())
                out << "ok    " << file << "  campaign: " << c.chapters.size() << " chapter(s), "
                    << levels << " level(s), " << c.outside.size() << " outside\n";
            for (const std::string& p : problems)
                out << "FAIL  " << p << "\n";
        }
        return problems.empty() ? 0 : 1;
    } catch (const LoadError& e) {
        report.push_back({{"file", file}, {"ok", false}, {"path", e.path}, {"error", e.detail}});
        if (!json) out << "FAIL  " << e.what() << "\n";
        return 1;
    }
}

} // namespace

int runCheck(const Args& args, std::ostream& out) {
    args.text("<positional>"); // files are positional
    const bool json = args.flag("json");
    args.rejectUnknown();
    const auto& files = args.positionals();
    if (files.empty())
        args.fail("name at least one level file, e.g. artillery check levels/*.json");

    int failed = 0;
    nlohmann::json report = nlohmann::json::array();
    for (const std::string& file : files) {
        if (std::filesystem::path(file).filename() == "campaign.json") {
            failed += checkCampaign(file, json, report, out);
            continue;
        }
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
            report.push_back(
                {{"file", file}, {"ok", false}, {"path", e.path}, {"error", e.detail}});
            if (!json) out << "FAIL  " << e.what() << "\n";
        }
    }
    if (json) out << nlohmann::json{{"levels", report}, {"failed", failed}}.dump() << "\n";
    return failed ? kCheckFailed : kOk;
}

} // namespace game::cli
