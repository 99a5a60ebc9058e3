// bench_rigid: what the rigid layer costs and how wrong it is.
//   1. step cost of a tower scene asleep vs the same bodies kept awake, and the ratio
//      (sleeping bodies must cost under 5 % of awake ones), with Box2D still
//      stepped while asleep and with quiescent steps skipped (the default);
//   2. the rigid drop: Box2D's bounce apexes against e^(2k) H for every restitution
//      preset (the measured presets), at dt = 1/120 s with 1 and 4 sub-steps.
// Usage: bench_rigid [--csv] [--ticks N]. Times are wall clock, so they vary from run
// to run; the ratio is the figure to read.
#include "bench/options.h"
#include "physics/rigid/rigid_drop.h"
#include "physics/rigid/rigid_scenes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace phys;

constexpr double kTick = 1.0 / 120.0;

struct Cost {
    double box2dUs = 0.0; ///< median time inside b2World::Step (RigidProfile::stepUs)
    double stepUs = 0.0;  ///< median time of the whole RigidWorld::step, bookkeeping included
    int awake = 0;
    int solved = 0;
};

double median(std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

enum class Mode { Awake, AsleepStepped, AsleepSkipped };

// Builds the tower, lets it settle (asleep unless kept awake), then times `ticks` steps.
// The median resists the odd slow tick (scheduler, cache).
Cost towerCost(int columns, int height, Mode mode, int ticks) {
    RigidWorldDef def;
    def.allowSleeping = mode != Mode::Awake;
    def.skipQuiescentSteps = mode == Mode::AsleepSkipped;
    RigidWorld world(def);
    RigidTowerDef td;
    td.columns = columns;
    td.height = height;
    buildTower(world, td);
    for (int t = 0; t < 4 * 120; ++t)
        world.step(kTick);
    std::vector<double> box2d, whole;
    box2d.reserve(static_cast<std::size_t>(ticks));
    whole.reserve(static_cast<std::size_t>(ticks));
    using Clock = std::chrono::steady_clock;
    for (int t = 0; t < ticks; ++t) {
        const auto t0 = Clock::now();
        world.step(kTick);
        whole.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
        box2d.push_back(world.profile().stepUs);
    }
    Cost c;
    c.box2dUs = median(box2d);
    c.stepUs = median(whole);
    c.awake = world.profile().awakeBodies;
    c.solved = world.solvedContacts();
    return c;
}

struct Preset {
    const char* name;
    double e;
};
constexpr Preset kPresets[] = {
    {"golf", 0.858},         {"tennis", 0.712},           {"billiard", 0.804},
    {"hand ball", 0.752},    {"wooden", 0.603},           {"steel bearing", 0.597},
    {"glass marble", 0.658}, {"rubber-band ball", 0.828}, {"hollow hard plastic", 0.688},
};

/// The cost of sleeping bodies: towers awake, asleep and stepped, asleep and skipped.
void printSleepCost(bool csv, int ticks) {
    if (csv)
        std::printf("scene,bodies,awake_us,asleep_box2d_us,asleep_skipped_us,ratio_box2d,"
                    "ratio_skipped\n");
    else
        std::printf("Sleep cost: whole RigidWorld::step, median of %d ticks of 1/120 s after "
                    "4 s settling\n"
                    "  awake:   allowSleeping off, the same bodies at rest but awake\n"
                    "  stepped: asleep, b2World::Step still called (skipQuiescentSteps off)\n"
                    "  skipped: asleep, Box2D not stepped (the default)\n"
                    "%-16s %6s %10s %10s %10s %9s %9s\n",
                    ticks, "scene", "bodies", "awake us", "stepped us", "skipped us", "stepped",
                    "skipped");
    const int scenes[][2] = {{1, 10}, {10, 10}, {40, 10}};
    for (const auto& s : scenes) {
        const Cost awake = towerCost(s[0], s[1], Mode::Awake, ticks);
        const Cost stepped = towerCost(s[0], s[1], Mode::AsleepStepped, ticks);
        const Cost skipped = towerCost(s[0], s[1], Mode::AsleepSkipped, ticks);
        const double r1 = stepped.stepUs / awake.stepUs;
        const double r2 = skipped.stepUs / awake.stepUs;
        const std::string name = std::to_string(s[0]) + " x " + std::to_string(s[1]) + " boxes";
        if (csv)
            std::printf("%s,%d,%.3f,%.3f,%.3f,%.4f,%.4f\n", name.c_str(), s[0] * s[1], awake.stepUs,
                        stepped.stepUs, skipped.stepUs, r1, r2);
        else
            std::printf("%-16s %6d %10.2f %10.2f %10.3f %8.2f%% %8.2f%%   (inside "
                        "b2World::Step: awake %.2f, stepped %.2f us; awake bodies %d/%d)\n",
                        name.c_str(), s[0] * s[1], awake.stepUs, stepped.stepUs, skipped.stepUs,
                        100.0 * r1, 100.0 * r2, awake.box2dUs, stepped.box2dUs, stepped.awake,
                        awake.awake);
    }
}

/// Rigid drops: each preset's first three apexes against e^(2k) H, at 1 and 4 sub-steps.
void printDropApexes(bool csv) {
    const double height = 1.0;
    for (const int substeps : {1, 4}) {
        if (csv)
            std::printf("\npreset,e,substeps,bounce,apex_m,expected_m,error_pct\n");
        else
            std::printf("\nRigid drop from H = %g m, dt = 1/120 s, %d sub-step%s: apex (error)\n"
                        "%-20s %6s %22s %22s %22s\n",
                        height, substeps, substeps == 1 ? "" : "s", "preset", "e", "bounce 1",
                        "bounce 2", "bounce 3");
        double worst[3] = {0.0, 0.0, 0.0};
        for (const Preset& p : kPresets) {
            const std::vector<double> apex = rigidDropApexes(height, p.e, 3, kTick, substeps);
            if (!csv) std::printf("%-20s %6.3f", p.name, p.e);
            for (std::size_t k = 0; k < 3; ++k) {
                const double expected = std::pow(p.e, 2.0 * static_cast<double>(k + 1)) * height;
                if (k >= apex.size()) {
                    if (!csv) std::printf(" %22s", "(no bounce)");
                    continue;
                }
                const double err = 100.0 * (apex[k] - expected) / expected;
                worst[k] = std::max(worst[k], std::abs(err));
                if (csv)
                    std::printf("%s,%.3f,%d,%zu,%.6f,%.6f,%.3f\n", p.name, p.e, substeps, k + 1,
                                apex[k], expected, err);
                else
                    std::printf("   %8.5f m (%+6.2f%%)", apex[k], err);
            }
            if (!csv) std::printf("\n");
        }
        if (!csv)
            std::printf("%-27s %21.2f%% %21.2f%% %21.2f%%\n", "worst |error|", worst[0], worst[1],
                        worst[2]);
    }
}

} // namespace

int main(int argc, char** argv) {
    bool csv = false;
    int ticks = 2000;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--csv") == 0) {
            csv = true;
        } else if (std::strcmp(argv[i], "--ticks") == 0 && i + 1 < argc &&
                   bench_args::countOption("bench_rigid", "--ticks", argv[i + 1], ticks, 1, 1e7)) {
            ++i;
        } else {
            std::fprintf(stderr, "usage: bench_rigid [--csv] [--ticks N >= 1]\n");
            return 2;
        }
    }

    printSleepCost(csv, ticks);
    printDropApexes(csv);
    return 0;
}
