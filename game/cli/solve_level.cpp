// artillery solve-level: the best game the solver finds on a level, as commands.
#include "game/cli/verbs.h"

#include "game/files/json_reader.h"
#include "game/generate/level_generator.h"
#include "game/solver.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <ostream>

namespace game::cli {

namespace {

std::string describeShot(const std::vector<Command>& c, std::size_t i) {
    // A shot is select, aim, power, fire at one tick.
    char line[200];
    std::snprintf(line, sizeof line, "  tick %6llu  %-10s  aim %8.3f deg  power %7.3f m/s  fire\n",
                  static_cast<unsigned long long>(c[i].tick), c[i].text.c_str(), c[i + 1].number,
                  c[i + 2].number);
    return line;
}

/// A duel has no stars; it is playable when each cannon can hit the other with one shot
/// (the solver's shot at the start, as `artillery generate` checks its duel maps).
int solveDuel(const std::string& file, const Level& level, bool json, long long require,
              bool record, std::ostream& out) {
    const auto [first, second] = generate::duelHitsEachWay(level);
    const bool playable = first && second;
    const char* noReplay = "no replay written: a duel is not solved, only checked";
    if (json) {
        nlohmann::json j{{"mode", "duel"}, {"hits", {first, second}}, {"playable", playable}};
        if (record) j["note"] = noReplay;
        out << j.dump() << "\n";
    } else {
        if (record) out << noReplay << "\n";
        auto yes = [](bool b) { return b ? "yes" : "no"; };
        out << file << ": a duel has no stars; one shot from each side hits the other: cannon 1 "
            << yes(first) << ", cannon 2 " << yes(second) << "\n";
        if (!playable && require > 0) out << file << ": a side that cannot hit makes no duel\n";
    }
    return playable || require == 0 ? kOk : kCheckFailed;
}

/// The rules' own numbers hold for the game found: no score above the largest the rules
/// allow, the stars' scores ascending up to it. "" when they do, else what does not.
std::string rulesBroken(const SolveResult& r) {
    const auto& s = r.starScores;
    if (r.score > r.maxScore)
        return "score " + std::to_string(r.score) + " above the largest the rules allow, " +
               std::to_string(r.maxScore);
    if (!(s[0] <= s[1] && s[1] <= s[2] && s[2] <= r.maxScore))
        return "the stars' scores " + std::to_string(s[0]) + ", " + std::to_string(s[1]) + ", " +
               std::to_string(s[2]) + " are not ascending up to " + std::to_string(r.maxScore);
    return "";
}

} // namespace

int runSolveLevel(const Args& args, std::ostream& out) {
    args.text("<positional>");
    const bool json = args.flag("json");
    const auto record = args.text("record");
    const long long require = args.integer("require-stars", 0, 0, 3);
    args.rejectUnknown();
    if (args.positionals().size() != 1)
        args.fail("name one level file, e.g. artillery solve-level levels/01_earth_basics.json");
    const std::string file = args.positionals()[0];
    if (record) requireWritableFile(args, "record", *record);
    Level level;
    try {
        level = loadLevel(file);
    } catch (const LoadError& e) {
        throw UsageError(e.what());
    }
    if (level.mode == Mode::Duel)
        return solveDuel(file, level, json, require, record.has_value(), out);
    const SolveResult r = solveLevel(level);
    if (record && r.practice) {
        try {
            saveReplay(*record, replayOf(level, r));
        } catch (const std::runtime_error& e) {
            throw WorkError(std::string("artillery solve-level: the replay was not written: ") +
                            e.what());
        }
    }
    if (json) {
        nlohmann::json j{{"stars", r.stars},
                         {"score", r.score},
                         {"max_score", r.maxScore},
                         {"shots", r.shots},
                         {"commands", nlohmann::json::parse(commandsToJson(r.commands))}};
        if (r.practice) j["star_scores"] = r.starScores;
        if (!r.practice)
            j["note"] = std::string("a ") + modeName(level.mode) + " has no stars to earn";
        out << j.dump() << "\n";
    } else if (!r.practice) {
        out << file << ": a " << modeName(level.mode)
            << " has no stars to earn; nothing to solve" << (record ? " (no replay written)" : "")
            << "\n";
    } else {
        char line[240];
        std::snprintf(line, sizeof line,
                      "%s: %d star%s, score %d of %d (stars at %d, %d, %d), %d shot%s (%ld trial "
                      "games)\n",
                      file.c_str(), r.stars, r.stars == 1 ? "" : "s", r.score, r.maxScore,
                      r.starScores[0], r.starScores[1], r.starScores[2], r.shots,
                      r.shots == 1 ? "" : "s", r.evaluations);
        out << line;
        for (std::size_t i = 0; i + 3 < r.commands.size(); i += 4)
            out << describeShot(r.commands, i);
        if (record) out << "replay written to " << *record << "\n";
    }
    if (const std::string broken = r.practice ? rulesBroken(r) : ""; !broken.empty()) {
        out << file << ": the scoring rules do not hold: " << broken << "\n";
        return kCheckFailed;
    }
    if (r.practice && r.stars < require) {
        if (!json)
            out << file << ": the solver reached " << r.stars << " star(s), fewer than the "
                << require << " required\n";
        return kCheckFailed;
    }
    return kOk;
}

} // namespace game::cli
