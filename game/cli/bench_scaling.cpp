// artillery bench scaling: step cost against N, the particle piles against Box2D, flights
// against a reference kernel, the cloth frame and replay seeks; the figures printed, as
// JSON, as CSV and as a chart.
#include "game/bench/machine.h"
#include "game/bench/replay_timing.h"
#include "game/cli/bench.h"
#include "game/cli/bench_options.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <ostream>

namespace game::cli::benchcli {

using namespace game::bench;
using nlohmann::json;

namespace {

/// Does `path` go into a folder named docs (the figures the documentation shows)?
bool intoDocs(const std::string& path) {
    for (const auto& part : std::filesystem::path(path).parent_path())
        if (part == "docs") return true;
    return false;
}

/// "[load 0.42]": the 1-minute load average beside a figure.
std::string loadNote(double load) {
    char t[40];
    if (std::isfinite(load)) std::snprintf(t, sizeof t, "  [load %.2f]", load);
    else std::snprintf(t, sizeof t, "  [load unknown]");
    return t;
}

/// The values printed with `format` and joined by ", ".
template <class T>
std::string joined(const std::vector<T>& values, const char* format) {
    std::string s;
    char t[32];
    for (const T v : values) {
        std::snprintf(t, sizeof t, format, v);
        s += (s.empty() ? "" : ", ") + std::string(t);
    }
    return s;
}

/// "windows of 30 ticks from tick 61: particles 0.74, 0.31, 0.12 ms; Box2D ...; particles
/// asleep after each: 408, 1936, 1896 of 2000; awake ball-ticks in each: 57866, 17498,
/// 2229": which stage of the drop each window timed.
std::string pileWindows(const game::bench::PileComparison& p) {
    return "windows of " + std::to_string(p.windowTicks) + " ticks from tick " +
           std::to_string(p.firstTick()) + ": particles " + joined(p.particleWindowMs, "%.3g") +
           " ms; Box2D " + joined(p.rigidWindowMs, "%.3g") +
           " ms; particles asleep after each: " + joined(p.asleepAfterWindow, "%d") + " of " +
           std::to_string(p.balls) +
           "; awake ball-ticks in each: " + joined(p.awakeBallTicks, "%ld");
}

const char* verdict(bool met) { return met ? "met" : "NOT met"; }

/// "best of 3 runs", or "one run".
std::string runsNote(int runs) {
    return runs > 1 ? "best of " + std::to_string(runs) + " runs" : "one run";
}

/// " (runs 4.62-6.71)": the slowest run beside the fastest, "" for one run.
std::string runSpread(const std::vector<double>& runMs) {
    if (runMs.size() < 2) return "";
    const auto [fastest, slowest] = std::minmax_element(runMs.begin(), runMs.end());
    char s[64];
    std::snprintf(s, sizeof s, " (runs %.3g-%.3g)", *fastest, *slowest);
    return s;
}

/// "lead over Box2D growing with N (14.0x, 11.7x, 19.6x at 1000, 2000, 4000 balls): NOT
/// met from 1000 to 2000 balls", the lead being `lead` of each pile, over `over`.
std::string leadGrowth(const std::vector<game::bench::PileComparison>& piles,
                       game::bench::PileLead lead, const char* over) {
    const game::bench::PileComparison* stalls = firstLeadThatDoesNotGrow(piles, lead);
    std::vector<double> leads;
    std::vector<long> sizes;
    for (const auto& p : piles)
        leads.push_back((p.*lead)()), sizes.push_back(p.balls);
    std::string s = std::string("lead over ") + over + " growing with N (" +
                    joined(leads, "%.1fx") + " at " + joined(sizes, "%ld") +
                    " balls): " + verdict(stalls == nullptr);
    if (stalls != nullptr)
        s += " from " + std::to_string((stalls - 1)->balls) + " to " +
             std::to_string(stalls->balls) + " balls";
    return s;
}

/// How much each part of the run measures, by --quick, the default or --full.
struct ScalingPlan {
    ScalingDef light, heavy;
    std::vector<long> pileSizes{1000, 2000, 4000}, flightSizes{10000, 1000000};
    int pileSteps = 30, pileRuns = 3, flightRepeats = 5, replayRepeats = 3;
    std::size_t replayLimit = SIZE_MAX;
    int clothFrames = 30;
};

ScalingPlan scalingPlan(Size size) {
    ScalingPlan p;
    switch (size) {
    case Size::Quick:
        p.light.sizes = {500, 1000, 2000};
        p.light.steps = 3, p.light.repeats = 1;
        p.heavy = p.light;
        p.pileSizes = {200}, p.flightSizes = {2000, 20000};
        p.pileSteps = 5, p.pileRuns = 1, p.flightRepeats = 1, p.replayRepeats = 1, p.replayLimit = 1;
        p.clothFrames = 3;
        break;
    case Size::Default:
        p.light.sizes = {1000, 3000, 10000, 30000, 100000};
        p.light.steps = 10, p.light.repeats = 3;
        // Piles settle for kPileSettleTicks before each timing, which costs more than
        // the timing itself: one run of 20 steps per size keeps the verb short.
        p.heavy.sizes = {250, 500, 1000, 2000, 4000};
        p.heavy.steps = 20, p.heavy.repeats = 1;
        break;
    case Size::Full:
        p.light.sizes = {1000, 3000, 10000, 30000, 100000, 300000};
        p.light.steps = 20, p.light.repeats = 5;
        p.heavy.sizes = {250, 500, 1000, 2000, 4000, 8000, 16000};
        p.heavy.steps = 20, p.heavy.repeats = 3;
        p.pileSizes = {1000, 2000, 4000, 8000};
        p.pileRuns = 5, p.flightRepeats = 9, p.replayRepeats = 5;
        break;
    }
    return p;
}

/// The workloads' step costs, the piles and heaps side by side, the flights against the
/// reference kernel and the cloth frame, into `report`.
void measureAll(ScalingReport& report, const ScalingPlan& plan) {
    auto add = [&](const std::string& name, const Workload& w, const ScalingDef& d) {
        auto pts = measureScaling(name, w, d, progressLine("scaling " + name));
        report.points.insert(report.points.end(), pts.begin(), pts.end());
    };
    add("flight", flightWorkload, plan.light);
    add("cloth", clothWorkload, plan.light);
    add("pile", pileWorkload, plan.heavy);
    add("box2d", rigidPileWorkload, plan.heavy);
    add("box2d-tuned", tunedRigidPileWorkload, plan.heavy);
    for (long balls : plan.pileSizes) {
        std::fprintf(stderr, "pile of %ld balls, particles and Box2D side by side...\n", balls);
        report.piles.push_back(comparePiles(balls, plan.pileSteps, 3, plan.pileRuns));
        if (balls == 2000 || plan.pileSizes.size() == 1) report.pile = report.piles.back();
    }
    for (long balls : plan.pileSizes) {
        std::fprintf(stderr, "heap of %ld balls in staggered rows, side by side...\n", balls);
        report.heaps.push_back(comparePiles(balls, plan.pileSteps, 3, plan.pileRuns,
                                            game::bench::PileShape::Staggered));
    }
    for (long n : plan.flightSizes)
        for (bool verlet : {false, true}) {
            std::fprintf(stderr, "%ld particles in flight (%s) against the reference kernel...\n",
                         n, verlet ? "velocity Verlet" : "symplectic Euler");
            // About 1e7 particle steps per repeat: enough to time, short at any n.
            const int steps = static_cast<int>(std::clamp(10000000L / n, 3L, 500L));
            report.flights.push_back(compareFlight(n, verlet, steps, plan.flightRepeats));
        }
    report.clothMs = clothFrameMs(64, plan.clothFrames);
    report.clothLoad = loadNow();
}

/// The slowest seeks in the replays of --replays DIR (default tests/replays, if there).
std::vector<ReplayTiming> timeReplaySeeks(const Args& args, const std::string& replays,
                                          const ScalingPlan& plan) {
    std::vector<ReplayTiming> seeks;
    if (std::filesystem::is_directory(replays)) {
        std::fprintf(stderr, "seeking in the replays of %s...\n", replays.c_str());
        try {
            seeks = timeReplays(replays, plan.replayRepeats, plan.replayLimit);
        } catch (const std::exception& e) {
            args.fail(std::string("--replays: ") + e.what());
        }
    } else if (args.has("replays")) {
        args.fail("--replays: folder '" + replays + "' does not exist");
    }
    return seeks;
}

/// Each workload's scaling exponent and its cost at the largest N.
json workloadsReport(const ScalingReport& report, bool asJson, std::ostream& out) {
    json rows = json::array();
    char line[400];
    if (!asJson) {
        out << "1-minute load average before the run" << loadNote(report.loadAtStart)
            << (report.underLoad ? "  (taken under load: --under-load)" : "") << "\n";
        out << "machine: " << report.machine << "\n";
        out << "workload    scaling exponent (1 = linear)   us/step at largest N\n";
    }
    for (const char* name : {"flight", "cloth", "pile", "box2d", "box2d-tuned"}) {
        std::vector<ScalingPoint> pts;
        for (const auto& p : report.points)
            if (p.workload == name) pts.push_back(p);
        const double e = scalingExponent(pts);
        if (!asJson) {
            std::snprintf(line, sizeof line, "%-11s %10.2f over N = %ld..%ld %18.4g", name, e,
                          pts.front().items, pts.back().items, pts.back().usPerStep);
            out << line << loadNote(pts.back().load) << "\n";
        }
        rows.push_back({{"workload", name},
                        {"exponent", jnum(e)},
                        {"largest_n", pts.back().items},
                        {"us_per_step_at_largest", jnum(pts.back().usPerStep)},
                        {"load", jnum(pts.back().load)}});
    }
    return rows;
}

/// " (target >= 10x: met)" for the pile of 2,000 balls in columns, which carries the
/// target (both its leads are judged by it); a lead taken on a busy host is no figure,
/// met or not, and says so. "" for the other piles and the heaps.
std::string pileTarget(const PileComparison& p, double lead) {
    if (p.shape == PileShape::Staggered || p.balls != 2000) return "";
    const std::string verdict = lead >= 10 ? "met" : "NOT met";
    const double spread = p.widestSpread();
    if (!(spread > kBusyHostSpread)) return " (target >= 10x: " + verdict + ")";
    char busy[120];
    std::snprintf(busy, sizeof busy, ", but the runs spread by %.1f %%: a busy host, not a figure",
                  100.0 * spread);
    return " (target >= 10x: " + verdict + busy + ")";
}

void printPile(const PileComparison& p, std::ostream& out) {
    char line[400];
    std::snprintf(line, sizeof line,
                  "%s of %ld balls, ticks %d-%d, %s: particles %.3g ms/step%s, "
                  "Box2D %.3g ms/step%s: particles %.2fx faster%s",
                  p.shape == PileShape::Staggered ? "heap (staggered rows)" : "pile", p.balls,
                  p.firstTick(), p.lastTick(), runsNote(p.runs).c_str(), p.particleMs,
                  runSpread(p.particleRunMs).c_str(), p.rigidMs, runSpread(p.rigidRunMs).c_str(),
                  p.speedup(), pileTarget(p, p.speedup()).c_str());
    out << line << loadNote(p.load) << "\n";
    out << "  " << pileWindows(p) << "\n";
    std::snprintf(line, sizeof line,
                  "  against Box2D at the size it is tuned for (every length x%g, no "
                  "time of impact): %.3g ms/step%s (windows %s): particles %.2fx "
                  "faster%s",
                  kTunedBox2D.scale, p.tunedRigidMs, runSpread(p.tunedRigidRunMs).c_str(),
                  joined(p.tunedRigidWindowMs, "%.3g").c_str(), p.speedupOverTuned(),
                  pileTarget(p, p.speedupOverTuned()).c_str());
    out << line << "\n";
}

json pileJson(const PileComparison& p) {
    return json{{"balls", p.balls},
                {"particle_ms", p.particleMs},
                {"box2d_ms", p.rigidMs},
                {"speedup", p.speedup()},
                {"box2d_tuned_ms", p.tunedRigidMs},
                {"box2d_tuned_window_ms", p.tunedRigidWindowMs},
                {"speedup_over_tuned", p.speedupOverTuned()},
                {"runs", p.runs},
                {"widest_run_spread", p.widestSpread()},
                {"particle_run_ms", p.particleRunMs},
                {"box2d_run_ms", p.rigidRunMs},
                {"box2d_tuned_run_ms", p.tunedRigidRunMs},
                {"window_ticks", p.windowTicks},
                {"particle_window_ms", p.particleWindowMs},
                {"box2d_window_ms", p.rigidWindowMs},
                {"asleep_after_window", p.asleepAfterWindow},
                {"awake_ball_ticks", p.awakeBallTicks},
                {"load", jnum(p.load)}};
}

/// The piles in columns and the heaps in staggered rows, and whether each lead grows.
void pilesReport(json& j, const ScalingReport& report, bool asJson, std::ostream& out) {
    j["piles"] = json::array();
    for (const auto& p : report.piles) {
        if (!asJson) printPile(p, out);
        j["piles"].push_back(pileJson(p));
    }
    if (report.piles.size() > 1) {
        j["pile_lead_grows_with_n"] = firstLeadThatDoesNotGrow(report.piles) == nullptr;
        j["pile_lead_over_tuned_grows_with_n"] =
            firstLeadThatDoesNotGrow(report.piles, &PileComparison::speedupOverTuned) == nullptr;
        if (!asJson)
            out << leadGrowth(report.piles, &PileComparison::speedup, "Box2D") << "\n"
                << leadGrowth(report.piles, &PileComparison::speedupOverTuned,
                              "Box2D at its tuned size")
                << "\n";
    }
    j["heaps"] = json::array();
    for (const auto& p : report.heaps) {
        if (!asJson) printPile(p, out);
        j["heaps"].push_back(pileJson(p));
    }
    if (report.heaps.size() > 1 && !asJson)
        out << leadGrowth(report.heaps, &PileComparison::speedupOverTuned,
                          "Box2D at its tuned size, in the heap")
            << "\n";
}

json flightsReport(const ScalingReport& report, bool asJson, std::ostream& out) {
    json rows = json::array();
    char line[400];
    for (const auto& f : report.flights) {
        if (!asJson) {
            std::snprintf(line, sizeof line,
                          "%ld in flight, %s: update %.4g ms/step, reference of its arithmetic (%d lanes) %.4g ms: "
                          "%.2fx (target <= 1.5: %s)\n"
                          "  %.0f B/particle moved: update %.3g GB/s, reference %.3g GB/s, "
                          "memcpy of as many bytes %.3g GB/s (%.4g ms)",
                          f.n, f.integrator.c_str(), f.updateMs, f.referenceLanes, f.referenceMs,
                          f.ratio(), verdict(f.ratio() <= 1.5), f.bytesPerParticle(),
                          f.updateGBs(), f.referenceGBs(), f.copyGBs(), f.copyMs);
            out << line << loadNote(f.load) << "\n";
        }
        rows.push_back({{"particles", f.n}, {"integrator", f.integrator},
                        {"update_ms", f.updateMs}, {"reference_ms", f.referenceMs},
                        {"copy_ms", f.copyMs}, {"ratio", f.ratio()},
                        {"reference_lanes", f.referenceLanes},
                        {"bytes_per_particle", f.bytesPerParticle()},
                        {"update_gb_s", f.updateGBs()},
                        {"reference_gb_s", f.referenceGBs()},
                        {"copy_gb_s", f.copyGBs()}, {"load", jnum(f.load)}});
    }
    return rows;
}

json replaysReport(const std::vector<ReplayTiming>& seeks, bool asJson, std::ostream& out) {
    json rows = json::array();
    char line[400];
    for (const auto& r : seeks) {
        if (!asJson) {
            std::snprintf(line, sizeof line,
                          "replay %-28s %5llu ticks: slowest seek from the start %.4g ms "
                          "(%.3g ms/tick); from %zu restart points %.4g ms (built in %.4g ms); "
                          "target seek <= 100 ms: %s",
                          r.file.c_str(), static_cast<unsigned long long>(r.ticks), r.worstSeekMs,
                          r.msPerTick(), r.restartPoints, r.restartSeekMs, r.buildMs,
                          verdict(r.restartSeekMs <= 100.0));
            out << line << loadNote(r.load) << "\n";
        }
        rows.push_back({{"file", r.file}, {"ticks", r.ticks},
                        {"worst_seek_ms", r.worstSeekMs}, {"ms_per_tick", r.msPerTick()},
                        {"restart_points", r.restartPoints},
                        {"restart_seek_ms", r.restartSeekMs},
                        {"restart_build_ms", r.buildMs},
                        {"load", jnum(r.load)}});
        if (r.file.starts_with("06_rope_bridge") && !asJson) {
            std::snprintf(line, sizeof line,
                          "rope bridge with its crate: %.3g ms per tick (target <= 0.1 ms: %s)",
                          r.msPerTick(), verdict(r.msPerTick() <= 0.1));
            out << line << loadNote(r.load) << "\n";
        }
    }
    return rows;
}

} // namespace

int runScalingCommand(const Args& args, std::ostream& out, const BenchPlots* plots) {
    const Size size = sizeOption(args);
    const bool asJson = args.flag("json");
    const bool underLoad = args.flag("under-load");
    const std::string csv = outputPath(args, "csv"), png = outputPath(args, "png");
    const std::string replays = args.text("replays", "tests/replays");
    args.rejectUnknown();

    ScalingReport report;
    report.loadAtStart = loadNow();
    report.machine = game::bench::thisMachine().describe();
    report.underLoad = underLoad;
    // Figures for the documentation come from a quiet machine: the load of other work
    // slows Box2D, the particles and the memory by different factors, so ratios taken
    // under load say little. The bench itself is not running yet, so this is the others.
    const bool docs = intoDocs(csv) || intoDocs(png);
    const std::string refusal = docsFiguresRefusal(report.loadAtStart, docs, underLoad);
    if (!refusal.empty()) args.fail(refusal);

    const ScalingPlan plan = scalingPlan(size);
    measureAll(report, plan);
    const std::vector<ReplayTiming> seeks = timeReplaySeeks(args, replays, plan);

    // The load before the run said nothing of the host's slow spells; the runs' spread does.
    double spread = 0.0;
    for (const PileComparison& p : report.piles)
        spread = std::max(spread, p.widestSpread());
    const std::string busy = busyHostRefusal(spread, docs, underLoad);
    if (!busy.empty()) args.fail(busy);
    writeText(csv, toCsv(report.points, report.underLoad));
    std::string plotError = plots && plots->scaling ? plots->scaling(report, png)
                                                    : "no renderer for --png";

    json j;
    j["csv"] = csv;
    j["png"] = png;
    j["load_at_start"] = jnum(report.loadAtStart);
    j["machine"] = report.machine;
    j["under_load"] = underLoad;
    j["workloads"] = workloadsReport(report, asJson, out);
    pilesReport(j, report, asJson, out);
    j["flights"] = flightsReport(report, asJson, out);
    j["replays"] = replaysReport(seeks, asJson, out);
    if (!asJson) {
        char line[200];
        std::snprintf(line, sizeof line,
                      "cloth 64x64, 8 sub-steps: %.3g ms per 1/60 s frame (target < 2 ms: %s)",
                      report.clothMs, verdict(report.clothMs < 2.0));
        out << line << loadNote(report.clothLoad) << "\n";
        out << "wrote " << csv << andChart(png, plotError) << "\n";
    } else {
        j["cloth_64_frame_ms"] = report.clothMs;
        j["cloth_load"] = jnum(report.clothLoad);
        out << j.dump() << "\n";
    }
    return chartOutcome(png, plotError);
}

} // namespace game::cli::benchcli
