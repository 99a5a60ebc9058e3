#include "game/cli/bench.h"

#include "game/bench/choose.h"
#include "game/cli/bench_options.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>

namespace game::cli {

using namespace game::bench;
using namespace game::cli::benchcli;
using nlohmann::json;

const char* const kBenchUsage =
    R"(usage: artillery bench work-precision [--scene NAME] --csv FILE --png FILE [--full|--quick] [--json]
       artillery bench stability --csv FILE --png FILE [--full|--quick] [--json]
       artillery bench scaling --csv FILE --png FILE [--full|--quick] [--replays DIR]
                               [--under-load] [--json]
       artillery bench choose --scene NAME --tolerance M [--full|--quick] [--json]

Speed against accuracy. Each measuring sub-command prints progress on stderr, writes
its measurements as CSV and a chart as PNG (drawn headless by the game's renderer),
and prints its key figures. By default each finishes in under 30 s on 2 cores (scaling
in about a minute);
--full runs longer sweeps (finer dt, larger N, more repeats), --quick tiny ones (tests).
Times are medians of repeats (a pile's: its cost over a span of its drop, the best
of 3 runs, 5 with --full, with the slowest beside it); the machine's load shows in
them.

work-precision  for each integrator and dt = largest, /2, /4, ...: the error against the
                scene's exact or reference solution and the CPU time per simulated
                second, log-log, one line per integrator; also the convergence slope
                (the order) and the cheapest method within 1e-2, 1e-4 and 1e-6 m.
  --scene NAME  projectile-drag, spring, orbit, pendulum, cloth (default: all, one
                panel each)
stability       per integrator: the largest stable w dt on an undamped spring (energy
                growth criterion, bisection) against theory, the energy growth across
                w dt, and the stiffest spring a 20-link rope survives at 1/120 s.
scaling         step cost against N: particles in flight, a particle pile with contacts,
                cloth springs, Box2D circles; the same piles of 1,000-4,000 balls as
                particles and as Box2D circles over ticks 61-150 of the drop (and its
                three windows, with the balls asleep after each and its awake
                ball-ticks), against Box2D as the game builds it and at the size Box2D
                is tuned for, and whether each lead grows with N; the same balls in
                staggered rows (a heap: each ball touches four to six others, where
                the pile's columns touch two); 10k and 1M particles
                in flight (symplectic Euler and velocity Verlet) against a vectorized
                reference kernel of the same arithmetic over the same arrays, with
                bytes per particle, GB/s and a memcpy of as many bytes;
                a 64x64 cloth frame (8 sub-steps); the slowest seek in every replay of
                --replays DIR (default tests/replays, if it exists), the rope bridge's
                cost per tick among them. Every figure has the 1-minute load average
                beside it, and the run names its machine (processor, logical CPUs,
                AVX2) on its second line, in --json and in the chart's title (with
                the load before the run): the same code's leads move with the
                processor. Writing --csv or --png into
                a docs/ folder is refused while the load average is above 1, and
                after the run when a pile's runs spread by more than 12 % (a busy
                host whatever the load: the 10x verdict then says it is no figure).
  --replays DIR folder of *.replay.json files to time seeks in
  --under-load  write into docs/ whatever the load or spread; the CSV and chart say so
choose          "accurate enough, fastest": measures the scene's sweep and prints the
                integrator and dt of least cost whose error is at most the tolerance.
  --tolerance M error tolerance, m (> 0)

  --csv FILE    measurements as CSV (header row first)
  --png FILE    the chart as PNG
  --json        the key figures as one JSON object on stdout

Exit code: 0 ok, 1 choose found no integrator and dt within the tolerance, 2 bad input
(a --csv or --png that cannot be written is refused before anything is measured), 3
the CSV or the chart could not be written.
)";

std::set<std::string> benchFlags() { return {"full", "quick", "under-load"}; }

namespace {

std::optional<AccuracyScene> sceneOption(const Args& args, bool required) {
    const auto name = args.text("scene");
    if (!name) {
        if (required) args.fail("--scene NAME is required (projectile-drag, spring, orbit, pendulum, cloth)");
        return std::nullopt;
    }
    const auto s = accuracySceneFromName(*name);
    if (!s)
        args.fail("--scene expects one of projectile-drag, spring, orbit, pendulum, cloth (got '" +
                  *name + "')");
    return s;
}

/// The dt sweep of a scene at a size: starts where every method is at least stable
/// enough to plot, ends where the best ones meet rounding.
WorkPrecisionDef sweepFor(AccuracyScene scene, Size size) {
    WorkPrecisionDef d = choiceSweep(scene);
    if (scene == AccuracyScene::Cloth || scene == AccuracyScene::PendulumRods) d.largestDt = 0.02;
    switch (size) {
    case Size::Quick: d.halvings = 3, d.repeats = 1; break;
    case Size::Default: d.halvings = scene == AccuracyScene::Cloth ? 6 : 7, d.repeats = 3; break;
    case Size::Full: d.halvings = 10, d.repeats = 5; break;
    }
    return d;
}

// ---- work-precision -------------------------------------------------------------------

/// Every scene's sweep (or the one asked for), in the scenes' order.
std::vector<WorkPrecisionPoint> measureWorkPrecision(std::optional<AccuracyScene> only, Size size) {
    std::vector<WorkPrecisionPoint> points;
    for (const auto& s : accuracyScenes()) {
        if (only && s.id != *only) continue;
        auto part = runWorkPrecision(sweepFor(s.id, size),
                                     progressLine(std::string("work-precision ") + s.name));
        points.insert(points.end(), part.begin(), part.end());
    }
    return points;
}

/// One integrator's row of a scene's table: its fitted order, its best error and the
/// cost there, and the cheapest run within 1e-4 m.
json integratorRow(const phys::IntegratorInfo& m, const std::vector<WorkPrecisionPoint>& mine,
                   bool asJson, std::ostream& out) {
    // The order shows where errors are small; runs that blew up or are still far
    // from converged (error above 5 cm) would only bend the fitted line.
    std::vector<WorkPrecisionPoint> converged;
    for (const auto& p : mine)
        if (p.error < 0.05) converged.push_back(p);
    const double slope = convergenceSlope(converged, m.id);
    const WorkPrecisionPoint* best = nullptr;
    for (const auto& p : mine)
        if (std::isfinite(p.error) && (!best || p.error < best->error)) best = &p;
    const WorkPrecisionPoint* within = cheapestWithin(mine, 1e-4);
    if (!asJson) {
        char line[200];
        std::snprintf(line, sizeof line, "  %-17s %5d  %6.2f  %12.3g  %10.3g s/s  %s\n",
                      m.name, m.order, slope, best ? best->error : NAN,
                      best ? best->cpuSecondsPerSimSecond : NAN,
                      within ? (std::to_string(within->cpuSecondsPerSimSecond * 1e3).substr(0, 6) +
                                " ms/s at dt " + std::to_string(within->dt).substr(0, 8))
                                   .c_str()
                             : "-");
        out << line;
    }
    return {{"integrator", m.name},
            {"order", m.order},
            {"slope", jnum(slope)},
            {"best_error_m", best ? jnum(best->error) : json(nullptr)},
            {"cpu_s_per_sim_s_at_best", best ? jnum(best->cpuSecondsPerSimSecond) : json(nullptr)}};
}

/// The cheapest integrator and dt of a scene within 1e-2, 1e-4 and 1e-6 m.
json cheapestRows(AccuracyScene scene, const std::vector<WorkPrecisionPoint>& ofScene, bool asJson,
                  std::ostream& out) {
    json rows = json::array();
    for (double tol : {1e-2, 1e-4, 1e-6}) {
        const auto c = chooseCheapest(scene, tol, ofScene);
        if (!asJson) {
            char line[200];
            if (c)
                std::snprintf(line, sizeof line,
                              "  cheapest within %.0e m: %-16s dt %-10.4g error %.3g m, "
                              "%.3g ms CPU per simulated s\n",
                              tol, phys::info(c->integrator).name, c->dt, c->error,
                              1e3 * c->cpuSecondsPerSimSecond);
            else
                std::snprintf(line, sizeof line, "  cheapest within %.0e m: none in this sweep\n", tol);
            out << line;
        }
        rows.push_back(c ? json{{"tolerance_m", tol},
                                {"integrator", phys::info(c->integrator).name},
                                {"dt_s", c->dt},
                                {"error_m", jnum(c->error)},
                                {"cpu_s_per_sim_s", jnum(c->cpuSecondsPerSimSecond)}}
                         : json{{"tolerance_m", tol}, {"integrator", nullptr}});
    }
    return rows;
}

/// One scene's figures: the table of integrators, then the cheapest within tolerances.
json sceneReport(const AccuracySceneInfo& s, const std::vector<WorkPrecisionPoint>& points,
                 bool asJson, std::ostream& out) {
    std::vector<WorkPrecisionPoint> ofScene;
    for (const auto& p : points)
        if (p.scene == s.id) ofScene.push_back(p);
    if (!asJson) {
        out << "\n" << s.name << " (" << s.reference << ", " << s.seconds << " s)\n";
        out << "  integrator        order  slope   best error m   cost at best  cheapest <= 1e-4 m\n";
    }
    json js;
    js["scene"] = s.name;
    js["integrators"] = json::array();
    for (const auto& m : phys::integrators()) {
        std::vector<WorkPrecisionPoint> mine;
        for (const auto& p : ofScene)
            if (p.integrator == m.id) mine.push_back(p);
        if (!mine.empty()) js["integrators"].push_back(integratorRow(m, mine, asJson, out));
    }
    js["cheapest"] = cheapestRows(s.id, ofScene, asJson, out);
    return js;
}

int runWorkPrecisionCommand(const Args& args, std::ostream& out, const BenchPlots* plots) {
    const auto only = sceneOption(args, false);
    const Size size = sizeOption(args);
    const bool asJson = args.flag("json");
    const std::string csv = outputPath(args, "csv"), png = outputPath(args, "png");
    args.rejectUnknown();

    const std::vector<WorkPrecisionPoint> points = measureWorkPrecision(only, size);
    writeText(csv, toCsv(points));
    std::string plotError = plots && plots->workPrecision ? plots->workPrecision(points, png)
                                                          : "no renderer for --png";
    json j;
    j["csv"] = csv;
    j["png"] = png;
    j["scenes"] = json::array();
    for (const auto& s : accuracyScenes())
        if (!only || s.id == *only) j["scenes"].push_back(sceneReport(s, points, asJson, out));
    if (asJson) out << j.dump() << "\n";
    else out << "\nwrote " << csv << andChart(png, plotError) << "\n";
    return chartOutcome(png, plotError);
}

// ---- stability ------------------------------------------------------------------------

/// Both tables of the stability CSV, one after the other, each with its header.
std::string stabilityCsv(const StabilityReport& report) {
    std::string text = toCsv(report.rows) + "\nintegrator,omega_dt,energy_growth\n";
    char line[128];
    for (const auto& c : report.curves)
        for (std::size_t k = 0; k < c.omegaDt.size(); ++k) {
            std::snprintf(line, sizeof line, "%s,%.6g,%.6g\n", phys::info(c.integrator).name,
                          c.omegaDt[k], c.growth[k]);
            text += line;
        }
    return text;
}

int runStabilityCommand(const Args& args, std::ostream& out, const BenchPlots* plots) {
    const Size size = sizeOption(args);
    const bool asJson = args.flag("json");
    const std::string csv = outputPath(args, "csv"), png = outputPath(args, "png");
    args.rejectUnknown();

    StabilityReport report;
    RopeDef rope;
    if (size == Size::Quick) rope.seconds = 0.5;
    if (size == Size::Full) rope.seconds = 5.0;
    report.rows = runStability(progressLine("stability limits"), rope);
    const int samples = size == Size::Quick ? 6 : size == Size::Full ? 61 : 25;
    report.curves = energyGrowthCurves(1e-2, 10.0, samples, progressLine("energy growth curves"));
    writeText(csv, stabilityCsv(report));
    std::string plotError = plots && plots->stability ? plots->stability(report, png)
                                                      : "no renderer for --png";

    json j;
    j["csv"] = csv;
    j["png"] = png;
    j["integrators"] = json::array();
    char line[128];
    if (!asJson)
        out << "integrator         max stable w dt   theory    off by   stiffest rope spring at 1/120 s\n";
    for (const auto& r : report.rows) {
        const bool bothFinite = std::isfinite(r.maxOmegaDt) && std::isfinite(r.theoryOmegaDt) &&
                                r.theoryOmegaDt > 0;
        const double off = bothFinite ? 100.0 * (r.maxOmegaDt / r.theoryOmegaDt - 1.0) : NAN;
        if (!asJson) {
            std::snprintf(line, sizeof line, "%-18s %15.4g %8.4g %8s %14.3g N/m\n",
                          phys::info(r.integrator).name, r.maxOmegaDt, r.theoryOmegaDt,
                          bothFinite ? (std::to_string(off).substr(0, 5) + " %").c_str()
                          : (r.maxOmegaDt == r.theoryOmegaDt) ? "agree"
                          : r.theoryOmegaDt == 0.0            ? "slow *"
                                                              : "DIFFER",
                          r.ropeStiffness);
            out << line;
        }
        j["integrators"].push_back({{"integrator", phys::info(r.integrator).name},
                                    {"max_omega_dt", jnum(r.maxOmegaDt)},
                                    {"theory_omega_dt", jnum(r.theoryOmegaDt)},
                                    {"rope_max_stiffness_n_per_m", jnum(r.ropeStiffness)}});
    }
    if (asJson) out << j.dump() << "\n";
    else out << "(0: unstable at any dt; inf: never unstable; * theory says unstable at any dt, "
                "but below this w dt the growth per step, e.g. (w dt)^4/4 for midpoint, stays "
                "under the 0.3 % test over the run)\nwrote " << csv
             << andChart(png, plotError) << "\n";
    return chartOutcome(png, plotError);
}

// ---- choose ---------------------------------------------------------------------------

int runChooseCommand(const Args& args, std::ostream& out) {
    const AccuracyScene scene = *sceneOption(args, true);
    const double tol = args.requiredNumber("tolerance", 1e-15, 1e6, "m");
    const Size size = sizeOption(args);
    const bool asJson = args.flag("json");
    args.rejectUnknown();
    const auto points = runWorkPrecision(sweepFor(scene, size),
                                         progressLine(std::string("measuring ") + info(scene).name));
    const auto c = chooseCheapest(scene, tol, points);
    double bestError = std::numeric_limits<double>::infinity();
    for (const auto& p : points) bestError = std::min(bestError, p.error);
    if (asJson) {
        json j{{"scene", info(scene).name}, {"tolerance_m", tol}};
        if (c) {
            j["integrator"] = phys::info(c->integrator).name;
            j["dt_s"] = c->dt;
            j["substeps_at_120_hz"] = c->substepsPerTick(1.0 / 120.0);
            j["error_m"] = jnum(c->error);
            j["cpu_s_per_sim_s"] = jnum(c->cpuSecondsPerSimSecond);
        } else {
            j["integrator"] = nullptr;
            j["best_error_m"] = jnum(bestError);
        }
        out << j.dump() << "\n";
    } else if (c) {
        char line[256];
        std::snprintf(line, sizeof line,
                      "%s within %.3g m: %s at dt = %.4g s (%d sub-steps per 1/120 s tick)\n"
                      "  measured error %.3g m, cost %.3g ms CPU per simulated second\n",
                      info(scene).name, tol, phys::info(c->integrator).name, c->dt,
                      c->substepsPerTick(1.0 / 120.0), c->error, 1e3 * c->cpuSecondsPerSimSecond);
        out << line;
    } else {
        out << info(scene).name << ": no integrator and dt of the sweep is within " << tol
            << " m (best error measured: " << bestError << " m); try --full or a looser tolerance\n";
    }
    // No setting meets the tolerance: the check the user asked for failed.
    return c ? kOk : kCheckFailed;
}

} // namespace

int runBench(const Args& args, std::ostream& out, const BenchPlots* plots) {
    args.text("<positional>");
    const auto& pos = args.positionals();
    if (pos.empty())
        args.fail("which bench? expected work-precision, stability, scaling or choose");
    if (pos.size() > 1) args.fail("unexpected argument '" + pos[1] + "'");
    const std::string& what = pos[0];
    if (what == "work-precision") return runWorkPrecisionCommand(args, out, plots);
    if (what == "stability") return runStabilityCommand(args, out, plots);
    if (what == "scaling") return benchcli::runScalingCommand(args, out, plots);
    if (what == "choose") return runChooseCommand(args, out);
    args.fail("unknown bench '" + what + "': expected work-precision, stability, scaling or choose");
}

} // namespace game::cli
