// artillery generate: a level from a seed, checked playable before it is written.
#include "game/cli/verbs.h"

#include "game/files/json_reader.h"
#include "game/generate/level_generator.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace game::cli {

namespace {

/// -o FILE (or --output FILE): where the level goes.
std::string outputFile(const Args& args) {
    const auto output = args.text("output");
    const auto& pos = args.positionals();
    if (!pos.empty() && pos[0] == "-o") {
        if (pos.size() < 2) args.fail("-o needs a file name, e.g. -o maps/duel_42.json");
        if (pos.size() > 2) args.fail("unexpected argument '" + pos[2] + "'");
        if (output) args.fail("give -o or --output, not both");
        return pos[1];
    }
    if (!pos.empty())
        args.fail("unexpected argument '" + pos[0] + "' (the output file goes after -o)");
    if (!output) args.fail("name the output file with -o FILE");
    return *output;
}

} // namespace

int runGenerate(const Args& args, std::ostream& out) {
    args.text("<positional>");
    const bool json = args.flag("json");
    if (!args.has("seed")) args.fail("give a seed, e.g. --seed 42");
    generate::GenerateDef def;
    def.seed = static_cast<std::uint64_t>(args.integer("seed", 1, 0, 0x7fffffffffffffffll));
    if (!args.has("mode")) args.fail("give --mode practice or --mode duel");
    const std::string mode = *args.text("mode");
    if (mode != "practice" && mode != "duel")
        args.fail("--mode expects practice or duel, got '" + mode + "'");
    def.mode = mode == "duel" ? Mode::Duel : Mode::Practice;
    const std::string difficulty = args.text("difficulty", "normal");
    const auto d = difficultyFromName(difficulty);
    if (!d) args.fail("--difficulty expects easy, normal or hard, got '" + difficulty + "'");
    def.difficulty = *d;
    const std::string file = outputFile(args);
    args.rejectUnknown();
    // Before the solver's games: a file that cannot be written is refused at once.
    requireWritableFile(args, "output", file);

    const generate::Generated g = generate::generateLevel(def);
    if (g.playable) {
        try {
            writeFileAtomically(file, g.text);
        } catch (const std::runtime_error& e) {
            throw WorkError(std::string("artillery generate: the level was not written: ") +
                            e.what());
        }
    }
    const std::string verdict =
        def.mode == Mode::Duel
            ? std::string("each cannon hits the other with the solver's first shot")
            : "the solver reaches 3 stars in " + std::to_string(g.shots) + " shot(s)";
    if (json) {
        nlohmann::json j{{"file", g.playable ? nlohmann::json(file) : nlohmann::json(nullptr)},
                         {"seed", def.seed},
                         {"mode", modeName(def.mode)},
                         {"difficulty", difficultyName(def.difficulty)},
                         {"name", g.level.name},
                         {"candidates", g.candidates},
                         {"playable", g.playable},
                         {"content_hash", contentHash(g.text)}};
        if (def.mode == Mode::Duel)
            j["hits"] = {g.hitByFirst, g.hitBySecond};
        else
            j["stars"] = g.stars;
        out << j.dump() << "\n";
    } else if (g.playable) {
        out << file << ": \"" << g.level.name << "\", " << verdict << " (candidate " << g.candidates
            << " of the seed)\n";
    } else {
        out << "artillery generate: no candidate of seed " << def.seed << " was playable in "
            << g.candidates << " tries; nothing written (try another seed)\n";
    }
    return g.playable ? kOk : kCheckFailed;
}

} // namespace game::cli
