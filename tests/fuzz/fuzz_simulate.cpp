// Structure-aware fuzzing of load-and-simulate. The fuzzer's bytes do not go to a parser
// as text; they choose the fields of a valid-shaped level (FUZZ_SIMULATE 1) or of a
// command script played against a shipped level (FUZZ_SIMULATE 2), with values drawn
// towards the extremes the loaders allow. When the loader accepts the input, the level
// is simulated for a few hundred ticks with the computer playing every cannon.
// Invariant: accepted implies no crash, no abort, no exception other than LoadError, no
// NaN or infinity in any particle's state, and every tick done within kTickBudget of
// wall time (the harness reads the clock; the simulation never does). Slow is not hung:
// a level may cost more wall time a tick than it simulates (docs/robustness.md: 2,000
// small blocks under strong gravity; the window runs it in slow motion), so an input
// that has spent kInputBudget is stopped there, its ticks so far checked, and passes.
#include "game/command.h"
#include "game/files/json_reader.h"
#include "game/headless.h"
#include "game/level.h"

#include <fuzzer/FuzzedDataProvider.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

constexpr std::uint64_t kTicks = 300;
// s of wall time for one tick in the sanitized fuzz build (about ten times slower than
// Release): the computer plans its shot within one tick, at most kMaxTrialTicks of trial
// flight (game/ai.h: 0.2-0.3 s in Release). Before that bound, a 20 km world with no
// gravity took 1.5 s in Release and 10.9 s here.
constexpr double kTickBudget = 10.0;
// s of wall time for the whole input, under libFuzzer's -timeout of 10 s (Makefile).
constexpr double kInputBudget = 4.0;

/// Thrown by the check when the input has used kInputBudget (see above).
struct InputBudgetSpent {};

/// A number near one of the interesting places: 0, the limits, tiny, huge, ordinary.
double extreme(FuzzedDataProvider& in, double lo, double hi) {
    switch (in.ConsumeIntegralInRange(0, 6)) {
    case 0: return lo;
    case 1: return hi;
    case 2: return std::clamp(0.0, lo, hi);
    case 3: return std::clamp(in.ConsumeBool() ? 1e-9 : -1e-9, lo, hi);
    case 4: return lo + (hi - lo) * 1e-6;
    default: return in.ConsumeFloatingPointInRange(lo, hi);
    }
}

nlohmann::json point(FuzzedDataProvider& in, double lo, double hi) {
    return {extreme(in, lo, hi), extreme(in, lo, hi)};
}

#if FUZZ_SIMULATE == 1 // the level fuzzer: a level of extremes
std::string levelText(FuzzedDataProvider& in) {
    using nlohmann::json;
    const double w = in.ConsumeBool() ? 200.0 : extreme(in, 1.0, 2e4);
    json l{{"format", 1}, {"name", "fuzz"}, {"world", {{"min", {0, 0}}, {"max", {w, w / 2}}}}};
    l["mode"] = in.PickValueInArray({"practice", "duel", "sandbox"});
    json terrain = json::array();
    const int tn = in.ConsumeIntegralInRange(2, 40);
    for (int i = 0; i < tn; ++i) terrain.push_back({w * i / (tn - 1), extreme(in, 0.0, w / 4)});
    l["terrain"] = {{"points", terrain}, {"destructible", in.ConsumeBool()}};
    l["physics"] = {{"gravity", extreme(in, 0.0, 1000.0)}, {"air_density", extreme(in, 0.0, 100.0)},
                    {"drag", in.ConsumeBool()}, {"wind", extreme(in, -100.0, 100.0)}};
    if (in.ConsumeBool()) l["physics"]["water_level"] = extreme(in, 0.0, w / 2);
    const char* projectiles[] = {"cannonball", "golf-ball", "tennis-ball", "steel-ball",
                                 "glass-marble", "wooden-ball"};
    for (int i = 0, n = in.ConsumeIntegralInRange(1, 8); i < n; ++i)
        l["cannons"].push_back({{"position", point(in, 0.0, w)},
                                {"player", in.PickValueInArray({"1", "2", "cpu"})},
                                {"max_speed_mps", extreme(in, 1.0, 2000.0)},
                                {"speed_mps", extreme(in, 0.0, 1.0)},
                                {"projectiles", {in.PickValueInArray(projectiles)}}});
    for (int i = 0, n = in.ConsumeIntegralInRange(0, 4); i < n; ++i)
        l["targets"].push_back({{"position", point(in, 0.0, w)}, {"radius", extreme(in, 0.05, 100.0)}});
    const int blocks = in.ConsumeBool() ? in.ConsumeIntegralInRange(0, 2000) : in.ConsumeIntegralInRange(0, 30);
    const nlohmann::json origin = point(in, 0.0, w);
    const double side = extreme(in, 0.05, 5.0);
    for (int i = 0; i < blocks; ++i) {
        // A grid from one corner (many blocks apart), or all at one point.
        const bool stacked = in.ConsumeBool();
        l["blocks"].push_back({{"position", stacked ? origin
                                                    : json{origin[0].get<double>() + (i % 45) * side * 1.1,
                                                           origin[1].get<double>() + (i / 45) * side * 1.1}},
                               {"size", {side, side}},
                               {"density", extreme(in, 1.0, 30000.0)},
                               {"material", in.PickValueInArray({"wood", "stone", "steel"})},
                               {"target", in.ConsumeBool()}});
    }
    for (int i = 0, n = in.ConsumeIntegralInRange(0, 6); i < n; ++i)
        l["ropes"].push_back({{"from", point(in, 0.0, w)}, {"to", point(in, 0.0, w)},
                              {"segments", in.ConsumeIntegralInRange(1, 200)},
                              {"sag", extreme(in, 0.0, 2.0)},
                              {"mass_per_segment", extreme(in, 1e-3, 1e4)}});
    for (int i = 0, n = in.ConsumeIntegralInRange(0, 6); i < n; ++i)
        l["blobs"].push_back({{"center", point(in, 0.0, w)}, {"radius", extreme(in, 0.05, 100.0)},
                              {"points", in.ConsumeIntegralInRange(3, 64)},
                              {"stiffness", extreme(in, 1.0, 1e7)}, {"mass", extreme(in, 1e-3, 1e5)},
                              {"target", in.ConsumeBool()}});
    for (int i = 0, n = in.ConsumeIntegralInRange(0, 6); i < n; ++i) {
        const int shape = in.ConsumeIntegralInRange(0, 2);
        if (shape == 0)
            l["obstacles"].push_back({{"shape", "circle"}, {"center", point(in, 0.0, w)},
                                      {"radius", extreme(in, 1e-3, 1e4)}});
        else
            l["obstacles"].push_back({{"shape", shape == 1 ? "polyline" : "polygon"},
                                      {"points", {point(in, 0.0, w), point(in, 0.0, w), point(in, 0.0, w)}}});
    }
    l["seed"] = in.ConsumeIntegral<std::uint32_t>();
    return l.dump();
}

#else // the commands fuzzer: a script for the sandbox level
std::string commandsText(FuzzedDataProvider& in) {
    using nlohmann::json;
    json list = json::array();
    std::uint64_t tick = 0;
    const char* settings[] = {"gravity", "air_density", "wind", "substeps", "restitution.golf-ball",
                              "integrator", "drag"};
    for (int i = 0, n = in.ConsumeIntegralInRange(0, 24); i < n; ++i) {
        tick += in.ConsumeIntegralInRange(0, 60);
        json c{{"tick", tick}};
        switch (in.ConsumeIntegralInRange(0, 9)) {
        case 0: c["cmd"] = "aim"; c["angle_deg"] = extreme(in, -180.0, 180.0); break;
        case 1: c["cmd"] = "power"; c["speed_mps"] = extreme(in, 0.0, 2000.0); break;
        case 2: c["cmd"] = "fire"; break;
        case 3:
            c["cmd"] = "select";
            c["projectile"] = in.PickValueInArray({"cannonball", "golf-ball", "wooden-ball", "bogus", ""});
            break;
        case 4:
            c["cmd"] = "set";
            c["name"] = in.PickValueInArray(settings);
            c["value"] = in.ConsumeBool() ? json(extreme(in, -1e3, 1e3)) : json(in.ConsumeIntegralInRange(0, 64));
            break;
        case 5:
            c["cmd"] = "spawn";
            c["what"] = in.PickValueInArray({"block", "rope", "cloth", "blob", "spring", "cannonball"});
            c["at"] = point(in, -10.0, 400.0);
            c["to"] = point(in, -10.0, 400.0);
            c["size"] = extreme(in, 0.0, 20.0);
            break;
        case 6: c["cmd"] = in.PickValueInArray({"end_turn", "sandbox", "release"}); break;
        default:
            c["cmd"] = in.PickValueInArray({"grab", "drag"});
            c["at"] = point(in, -10.0, 400.0);
            break;
        }
        list.push_back(c);
    }
    return list.dump();
}
#endif

struct FiniteCheck : game::FrameSink {
    const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point last = start;
    void frame(const game::Match& m) override {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - last).count();
        last = now;
        if (s > kTickBudget) {
            std::fprintf(stderr, "tick %llu took %.2f s (budget %.1f s)\n",
                         static_cast<unsigned long long>(m.tick()), s, kTickBudget);
            std::abort();
        }
        checkFinite(m);
        if (std::chrono::duration<double>(now - start).count() > kInputBudget)
            throw InputBudgetSpent{};
    }
    static void checkFinite(const game::Match& m) {
        const auto& p = m.world().particles;
        for (std::size_t i = 0; i < p.slots(); ++i)
            if (!std::isfinite(p.px[i]) || !std::isfinite(p.py[i]) || !std::isfinite(p.vx[i]) ||
                !std::isfinite(p.vy[i])) {
                std::fprintf(stderr, "particle %zu not finite at tick %llu\n", i,
                             static_cast<unsigned long long>(m.tick()));
                std::abort();
            }
    }
};

void simulate(const game::Level& level, std::vector<game::Command> commands) {
    FiniteCheck check;
    game::HeadlessOptions o;
    o.commands = std::move(commands);
    o.ticks = kTicks;
    o.session.autoplay = o.commands.empty();
    o.sink = &check;
    o.every = 1;
    game::runHeadless(level, o);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    try {
#if FUZZ_SIMULATE == 1
        const std::string text = levelText(in);
        // FUZZ_PRINT=1 with a saved input: prints the level it stands for.
        if (std::getenv("FUZZ_PRINT")) std::fprintf(stderr, "%s\n", text.c_str());
        const game::Level level = game::parseLevel("fuzz.json", text);
        simulate(level, {});
#else
        static const game::Level level =
            game::loadLevel(std::string(ARTILLERY_SOURCE_DIR) + "/levels/11_sandbox.json");
        simulate(level, game::parseCommands("fuzz.json", commandsText(in)));
#endif
    } catch (const game::LoadError&) {
        // Refused with a message: fine.
    } catch (const InputBudgetSpent&) {
        // Slow, every tick so far in budget and finite: fine.
    }
    return 0;
}
