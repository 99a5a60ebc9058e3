// bench_replay: records a two-minute match (the computer playing every cannon), then
// re-simulates it headless without rendering, several times, and prints the median time
// and how many times faster than real time that is. One core: nothing here is threaded.
//
//   bench_replay [LEVEL.json] [--seconds S] [--repeats N]
#include "bench/options.h"
#include "game/files/text_file.h"
#include "game/headless.h"
#include "game/replay.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    std::string file = "levels/10_duel.json";
    double seconds = 120.0;
    int repeats = 5;
    for (int i = 1; i < argc; ++i) {
        bool ok = true;
        if (!std::strcmp(argv[i], "--seconds") && i + 1 < argc)
            ok = bench_args::realOption("bench_replay", "--seconds", argv[++i], seconds, 1e-3, 1e6);
        else if (!std::strcmp(argv[i], "--repeats") && i + 1 < argc)
            ok = bench_args::countOption("bench_replay", "--repeats", argv[++i], repeats, 1);
        else
            file = argv[i];
        if (ok) continue;
        std::fprintf(stderr, "usage: bench_replay [LEVEL.json] [--seconds S > 0] [--repeats N >= 1]\n");
        return 2;
    }
    game::Level level;
    try {
        level = game::loadLevel(file);
    } catch (const game::LoadError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    }
    const auto ticks = static_cast<std::uint64_t>(seconds * 120.0);

    // Record: the computer plays every turn (its aiming is part of recording, not of
    // re-simulation: the replay holds its commands).
    game::HeadlessOptions rec;
    rec.session.autoplay = true;
    rec.ticks = ticks;
    const auto recorded = game::runHeadless(level, rec);
    std::printf("recorded %s: %llu ticks (%.0f s), %d shots, %zu commands, %.0f ms with the computer aiming\n",
                level.name.c_str(), static_cast<unsigned long long>(recorded.ticks), seconds,
                recorded.shots, recorded.recording.commands.size(), recorded.simMs);

    std::vector<double> ms;
    bool ok = true;
    for (int r = 0; r < repeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        const game::VerifyResult v = game::verifyReplay(level, recorded.recording);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        ok = ok && v.ok;
    }
    std::sort(ms.begin(), ms.end());
    const double median = ms[ms.size() / 2];
    std::printf("re-simulated %d times: median %.1f ms (best %.1f ms) = %.0fx real time; target 200 ms (600x): %s; hashes %s\n",
                repeats, median, ms.front(), seconds * 1000.0 / median, median <= 200.0 ? "met" : "NOT met",
                ok ? "all equal" : "DIFFERENT");
    return ok ? 0 : 1;
}
