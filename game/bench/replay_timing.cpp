#include "game/bench/replay_timing.h"

#include "game/bench/scaling.h"
#include "game/replay.h"
#include "game/replay_player.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

namespace game::bench {

std::vector<ReplayTiming> timeReplays(const std::string& folder, int repeats, std::size_t limit) {
    namespace fs = std::filesystem;
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(folder, ec)) {
        const std::string name = e.path().filename().string();
        if (name.size() > 12 && name.ends_with(".replay.json")) files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    if (files.size() > limit) files.resize(limit);
    std::vector<ReplayTiming> out;
    for (const auto& path : files) {
        const Replay replay = loadReplay(path.string());
        const Level level = levelForReplay(path.string(), replay);
        ReplayPlayer player(level, replay);
        player.seek(player.lastTick());
        const std::uint64_t target = player.lastTick() > 0 ? player.lastTick() - 1 : 0;
        std::vector<double> t;
        for (int k = 0; k < std::max(1, repeats); ++k) {
            player.seek(player.lastTick());
            const auto t0 = std::chrono::steady_clock::now();
            player.seek(target);
            t.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                    .count());
        }
        std::sort(t.begin(), t.end());
        // With restart points: build them all (timed), then seek to the tick before each
        // point, the longest re-simulation from the point before it; each point used is
        // rebuilt untimed before the next seek.
        ReplayPlayer withPoints(level, replay);
        const auto b0 = std::chrono::steady_clock::now();
        withPoints.prepareRestartPoints(UINT64_MAX);
        const double buildMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - b0).count();
        const std::uint64_t spacing = withPoints.restartPoints().spacing();
        double restartSeekMs = 0;
        for (std::uint64_t at = spacing; at <= withPoints.lastTick(); at += spacing) {
            withPoints.seek(withPoints.lastTick());
            withPoints.prepareRestartPoints(UINT64_MAX);
            const auto s0 = std::chrono::steady_clock::now();
            withPoints.seek(std::min(at + spacing, withPoints.lastTick()) - 1);
            restartSeekMs = std::max(
                restartSeekMs,
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - s0)
                    .count());
        }
        ReplayTiming r;
        r.restartSeekMs = restartSeekMs;
        r.buildMs = buildMs;
        r.restartPoints = withPoints.restartPoints().points();
        r.file = path.filename().string();
        r.ticks = player.lastTick();
        r.worstSeekMs = t[t.size() / 2];
        r.load = loadNow();
        out.push_back(r);
    }
    return out;
}

} // namespace game::bench
