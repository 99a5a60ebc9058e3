// bench_duel_ai: calibrates the computer's difficulties. Easy, normal, hard and the
// solver as a player duel each other headless on the shipped duel maps and generated
// ones, alternating who starts, each duel seeded (winds and aim errors); prints a table
// of wins, losses and draws per pair, and the time it took.
//
//   bench_duel_ai [--duels N] [--maps K] [--pairs easy-normal,normal-solver,...]
//
// N duels per pair (default 100), spread evenly over every duel in levels/ (in file
// order) and K more generated at normal difficulty, seeds 1..K (default 4).
#include "bench/options.h"
#include "game/bench/duel_ai.h"
#include "game/generate/level_generator.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using game::bench::DuelPlayer;

namespace {

std::optional<DuelPlayer> playerFromName(const std::string& name) {
    if (name == "solver") return DuelPlayer{};
    if (const auto d = game::difficultyFromName(name)) return DuelPlayer{*d};
    return std::nullopt;
}

/// Every duel among the level files of `folder`, in file-name order; nothing when the
/// folder cannot be read.
std::optional<std::vector<game::Level>> shippedDuels(const std::string& folder) {
    std::error_code ec;
    std::filesystem::directory_iterator it(folder, ec);
    if (ec) return std::nullopt;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : it)
        if (entry.path().extension() == ".json" && entry.path().filename() != "campaign.json")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    std::vector<game::Level> duels;
    for (const auto& f : files)
        if (game::Level l = game::loadLevel(f.string()); l.mode == game::Mode::Duel)
            duels.push_back(std::move(l));
    return duels;
}

/// The pairs of "A-B,..." , or nullopt after a line saying what is wrong.
std::optional<std::vector<std::pair<DuelPlayer, DuelPlayer>>> parsePairs(const std::string& pairList) {
    std::vector<std::pair<DuelPlayer, DuelPlayer>> pairs;
    std::stringstream list(pairList);
    for (std::string item; std::getline(list, item, ',');) {
        const auto dash = item.find('-');
        const auto a = playerFromName(item.substr(0, dash));
        const auto b = dash == std::string::npos ? std::nullopt : playerFromName(item.substr(dash + 1));
        if (!a || !b) {
            std::fprintf(stderr,
                         "bench_duel_ai: --pairs expects A-B with A, B in easy, normal, "
                         "hard, solver; got '%s'\n",
                         item.c_str());
            return std::nullopt;
        }
        pairs.emplace_back(*a, *b);
    }
    return pairs;
}

/// The shipped duels and `generated` generated ones, or nullopt after a line.
std::optional<std::vector<game::Level>> duelMaps(int generated) {
    auto shipped = shippedDuels("levels");
    if (!shipped) {
        std::fprintf(stderr, "bench_duel_ai: cannot read the folder levels/ (run it from the "
                             "source tree)\n");
        return std::nullopt;
    }
    std::vector<game::Level> maps = std::move(*shipped);
    for (int s = 1; s <= generated; ++s) {
        game::generate::GenerateDef def;
        def.seed = static_cast<std::uint64_t>(s);
        def.mode = game::Mode::Duel;
        maps.push_back(game::generate::generateLevel(def).level);
    }
    if (maps.empty()) {
        std::fprintf(stderr, "bench_duel_ai: no duel in levels/ and --maps 0: nothing to play on\n");
        return std::nullopt;
    }
    return maps;
}

} // namespace

int main(int argc, char** argv) {
    int duels = 100, generated = 4;
    std::string pairList =
        "easy-normal,easy-hard,normal-hard,easy-solver,normal-solver,hard-solver";
    for (int i = 1; i < argc; ++i) {
        bool ok = true;
        if (!std::strcmp(argv[i], "--duels") && i + 1 < argc)
            ok = bench_args::countOption("bench_duel_ai", "--duels", argv[++i], duels, 2, 1e6);
        else if (!std::strcmp(argv[i], "--maps") && i + 1 < argc)
            ok = bench_args::countOption("bench_duel_ai", "--maps", argv[++i], generated, 0, 1e4);
        else if (!std::strcmp(argv[i], "--pairs") && i + 1 < argc)
            pairList = argv[++i];
        else
            ok = false;
        if (!ok) {
            std::fprintf(stderr,
                         "usage: bench_duel_ai [--duels N >= 2] [--maps K >= 0] [--pairs A-B,...]\n");
            return 2;
        }
    }
    const auto pairs = parsePairs(pairList);
    if (!pairs) return 2;
    const auto found = duelMaps(generated);
    if (!found) return 2;
    const std::vector<game::Level>& maps = *found;
    std::printf("maps: %s", maps[0].name.c_str());
    for (std::size_t k = 1; k < maps.size(); ++k)
        std::printf(", %s", maps[k].name.c_str());
    std::printf(
        "\n\n| A | B | duels | A wins | B wins | draws | A's win rate | mean shots | seconds |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    std::fflush(stdout);
    const auto start = std::chrono::steady_clock::now();
    for (const auto& [a, b] : *pairs) {
        const auto t0 = std::chrono::steady_clock::now();
        int wins[2] = {0, 0}, draws = 0;
        long shots = 0;
        for (int k = 0; k < duels; ++k) {
            const game::Level& map = maps[static_cast<std::size_t>(k) % maps.size()];
            // Who starts alternates; every duel has its own winds and aim errors.
            const bool aStarts = (k / static_cast<int>(maps.size())) % 2 == 0;
            const auto r =
                game::bench::playDuel(map, a, b, aStarts, 1000 + static_cast<std::uint64_t>(k));
            if (r.winner < 0)
                ++draws;
            else
                ++wins[r.winner];
            shots += r.shots;
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("| %s | %s | %d | %d | %d | %d | %.0f %% | %.1f | %.0f |\n", a.name().c_str(),
                    b.name().c_str(), duels, wins[0], wins[1], draws, 100.0 * wins[0] / duels,
                    static_cast<double>(shots) / duels, seconds);
        std::fflush(stdout);
    }
    std::printf("\ntotal %.0f s\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return 0;
}
