// bench_soak: one simulated hour (by default) at the game tick, to show that nothing
// drifts, blows up or leaks over a long session. It runs, side by side:
//
//   busy          a dissipative game-like scene (a particle gas settling into a pile,
//                 springs, Box2D crates coupled to the particles, resting contact, sleep):
//                 its energy falls by design; it is here for the guard (0 removals),
//                 NaN (0) and memory (flat).
//   oscillators   particles on undamped springs, one bank per integrator (symplectic
//                 Euler, Verlet, velocity Verlet, leapfrog, RK4): energy drift per
//                 integrator; for symplectic Euler and velocity Verlet the exactly
//                 conserved modified energy is checked every tick.
//   gas           particles in a box, e = 1, no friction, no sleep, no gravity.
//   bodies        Box2D circles and boxes in a box, e = 1, no friction, no sleep.
//
// Every report interval it prints the energy drift of each scene, the non-finite values
// and guard removals so far (must stay 0), the resident memory (from /proc/self/statm;
// must stay flat once warm) and the wall time; at the end a summary. Exit 0 when there
// was no fault and the exact invariants held, 1 otherwise, 2 on bad arguments.
//
//   bench_soak [--seconds S] [--scenes busy,oscillators,gas,bodies] [--report S]
//              [--particles N] [--crates M] [--oscillators N] [--gas N] [--bodies M]
#include "bench/options.h"
#include "soak_scenes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <unistd.h>
#include <vector>

namespace {

constexpr std::string_view kScenes = "busy,oscillators,gas,bodies";
std::vector<std::string_view> names(std::string_view list);

struct Options {
    double seconds = 3600.0; ///< simulated time, s
    double report = 60.0;    ///< simulated seconds between progress lines
    std::string scenes{kScenes};
    int particles = 1000;  ///< busy scene
    int crates = 100;      ///< busy scene
    int oscillators = 400; ///< per integrator
    int gas = 1000;
    int bodies = 1000;
    bool has(std::string_view scene) const { return std::ranges::count(names(scenes), scene) > 0; }
};

/// The names of a comma-separated list ("busy,gas" -> busy, gas).
std::vector<std::string_view> names(std::string_view list) {
    std::vector<std::string_view> out;
    for (;;) {
        const auto comma = list.find(',');
        out.push_back(list.substr(0, comma));
        if (comma == std::string_view::npos) return out;
        list.remove_prefix(comma + 1);
    }
}

constexpr const char* kUsage =
    "usage: bench_soak [--seconds S > 0 (3600)] [--report S > 0 (60)]\n"
    "                  [--scenes LIST of busy,oscillators,gas,bodies (all)]\n"
    "                  [--particles N >= 1 (1000)] [--crates M >= 0 (100)]   busy scene\n"
    "                  [--oscillators N >= 1 (400, per integrator)] [--gas N >= 1 (1000)]\n"
    "                  [--bodies M >= 1 (1000)]\n";

bool parse(int argc, char** argv, Options& o) {
    using bench_args::countOption, bench_args::realOption;
    constexpr const char* kName = "bench_soak";
    for (int i = 1; i < argc; i += 2) {
        if (i + 1 >= argc) return false;
        const char* flag = argv[i];
        const char* value = argv[i + 1];
        bool ok = true;
        if (!std::strcmp(flag, "--seconds"))
            ok = realOption(kName, flag, value, o.seconds, 1e-3, 1e7);
        else if (!std::strcmp(flag, "--report"))
            ok = realOption(kName, flag, value, o.report, 1e-3, 1e7);
        else if (!std::strcmp(flag, "--scenes")) {
            o.scenes = value;
            for (const std::string_view name : names(value))
                ok = ok && std::ranges::count(names(kScenes), name) > 0;
            if (!ok)
                std::fprintf(stderr, "%s: --scenes expects names from %.*s, got '%s'\n", kName,
                             static_cast<int>(kScenes.size()), kScenes.data(), value);
        } else if (!std::strcmp(flag, "--particles"))
            ok = countOption(kName, flag, value, o.particles, 1, 1e6);
        else if (!std::strcmp(flag, "--crates"))
            ok = countOption(kName, flag, value, o.crates, 0, 1e6);
        else if (!std::strcmp(flag, "--oscillators"))
            ok = countOption(kName, flag, value, o.oscillators, 1, 1e6);
        else if (!std::strcmp(flag, "--gas"))
            ok = countOption(kName, flag, value, o.gas, 1, 1e6);
        else if (!std::strcmp(flag, "--bodies"))
            ok = countOption(kName, flag, value, o.bodies, 1, 1e6);
        else {
            std::fprintf(stderr, "%s: unknown option %s\n", kName, flag);
            ok = false;
        }
        if (!ok) return false;
    }
    return true;
}

double residentMiB() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) /
           (1024.0 * 1024.0);
}

/// Resident memory at the start, after the first report (warm), at the end, and its max.
struct MemoryTrace {
    double start = 0.0, warm = -1.0, last = 0.0, max = 0.0;
    void sample() {
        last = residentMiB();
        if (warm < 0.0) warm = last;
        max = std::max(max, last);
    }
};

/// Column label of an integrator's drift (the header has 11 characters per column).
const char* columnLabel(phys::Integrator m) {
    switch (m) {
    case phys::Integrator::SymplecticEuler:
        return "sympl-euler";
    case phys::Integrator::VelocityVerlet:
        return "vel-verlet";
    default:
        return phys::info(m).name;
    }
}

/// The scenes the options ask for, stepped together and reported in columns.
struct Scenes {
    std::unique_ptr<soak::BusyScene> busy;
    std::vector<std::unique_ptr<soak::OscillatorBank>> banks;
    std::unique_ptr<soak::ElasticGas> gas;
    std::unique_ptr<soak::ElasticBodies> bodies;

    explicit Scenes(const Options& opt) {
        const phys::Integrator methods[] = {phys::Integrator::SymplecticEuler, phys::Integrator::Verlet,
                                            phys::Integrator::VelocityVerlet, phys::Integrator::Leapfrog,
                                            phys::Integrator::RK4};
        std::uint64_t seed = 2026;
        if (opt.has("busy")) busy = std::make_unique<soak::BusyScene>(opt.particles, opt.crates, seed++);
        if (opt.has("oscillators"))
            for (const phys::Integrator m : methods)
                banks.push_back(std::make_unique<soak::OscillatorBank>(m, opt.oscillators, seed++));
        if (opt.has("gas")) gas = std::make_unique<soak::ElasticGas>(opt.gas, seed++);
        if (opt.has("bodies")) bodies = std::make_unique<soak::ElasticBodies>(opt.bodies, seed++);
    }

    void step(soak::Faults& faults) {
        if (busy) busy->step(faults);
        for (auto& b : banks)
            b->step(faults);
        if (gas) gas->step(faults);
        if (bodies) bodies->step(faults);
    }

    /// What each scene holds, then the progress header: relative energy drift (E - E0)/E0
    /// of each scene.
    void printHeader(const Options& opt) const {
        using soak::kTick;
        if (busy)
            std::printf("  busy: %d particles, %zu springs, %d Box2D crates in a %.0f m x 40 m box "
                        "(dissipative)\n",
                        opt.particles, busy->world.springs.size(), opt.crates,
                        soak::BusyScene::width(opt.particles));
        if (!banks.empty())
            std::printf("  oscillators: %d per integrator x %zu, k %.0f..%.0f N/m, 1 kg "
                        "(w dt %.3f..%.3f), undamped\n",
                        opt.oscillators, banks.size(), soak::OscillatorBank::kMin,
                        soak::OscillatorBank::kMax, std::sqrt(soak::OscillatorBank::kMin) * kTick,
                        std::sqrt(soak::OscillatorBank::kMax) * kTick);
        if (gas) std::printf("  gas: %d particles, e = 1, frictionless, no gravity, no sleep\n", opt.gas);
        if (bodies)
            std::printf("  bodies: %d Box2D circles and boxes, e = 1, frictionless, no gravity, no sleep\n",
                        opt.bodies);
        std::printf("\n%8s", "minute");
        if (busy) std::printf(" %10s", "busy E/E0");
        for (const auto& b : banks)
            std::printf(" %11s", columnLabel(b->method));
        if (gas) std::printf(" %11s", "gas");
        if (bodies) std::printf(" %11s", "Box2D");
        if (busy) std::printf(" %7s", "awake");
        std::printf(" %6s %7s %8s %8s\n", "NaN", "removed", "RSS MiB", "wall s");
    }

    /// The scenes' columns of one progress line.
    void printRow() const {
        if (busy) std::printf(" %10.6f", busy->energy() / busy->energy0);
        for (const auto& b : banks)
            std::printf(" %+11.3e", b->total.drift());
        if (gas) std::printf(" %+11.3e", gas->drift.drift());
        if (bodies) std::printf(" %+11.3e", bodies->drift.drift());
        if (busy) {
            const phys::StepProfile& p = busy->world.profile();
            std::printf(" %7d", p.integrated + p.closedForm);
        }
    }

    /// The energy table; true when every exactly conserved quantity held.
    bool printEnergy() const {
        bool invariantsHeld = true;
        std::printf("  %-22s %12s %12s %14s %14s %10s\n", "scene", "drift", "max dev", "worst single",
                    "H drift", "E/H band");
        for (const auto& b : banks) {
            std::printf("  %-22s %+12.3e %12.3e %14.3e", phys::info(b->method).name, b->total.drift(),
                        b->total.maxDeviation, b->worstSingle);
            if (b->hasInvariant()) {
                // H is conserved up to rounding; E/H stays inside its band (used <= 1).
                const bool held = b->invariantDrift < 1e-9 && b->bandExcess < 1e-12;
                invariantsHeld = invariantsHeld && held;
                std::printf(" %14.3e %9.4f%s\n", b->invariantDrift, b->bandUsed, held ? "" : " FAILED");
            } else {
                std::printf(" %14s %10s\n", "-", "-");
            }
        }
        if (gas)
            std::printf("  %-22s %+12.3e %12.3e\n", "particle gas (e = 1)", gas->drift.drift(),
                        gas->drift.maxDeviation);
        if (bodies)
            std::printf("  %-22s %+12.3e %12.3e\n", "Box2D bodies (e = 1)", bodies->drift.drift(),
                        bodies->drift.maxDeviation);
        if (busy)
            std::printf("  %-22s E/E0 = %.4f at the end (dissipative by design)\n", "busy",
                        busy->energy() / busy->energy0);
        return invariantsHeld;
    }
};

} // namespace

int main(int argc, char** argv) {
    Options opt;
    if (!parse(argc, argv, opt)) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    using soak::kTick;
    Scenes scenes(opt);
    MemoryTrace memory;
    memory.start = residentMiB();

    const long ticks = std::lround(opt.seconds / kTick);
    const long perReport = std::max(1L, std::lround(opt.report / kTick));
    std::printf("soak: %.0f s simulated at %.0f Hz (%ld ticks), a line every %.0f s\n", opt.seconds,
                1.0 / kTick, ticks, opt.report);
    scenes.printHeader(opt);

    soak::Faults faults;
    const auto t0 = std::chrono::steady_clock::now();
    const auto wallSeconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    for (long t = 1; t <= ticks; ++t) {
        scenes.step(faults);
        if (t % perReport != 0 && t != ticks) continue;
        memory.sample();
        std::printf("%8.2f", static_cast<double>(t) * kTick / 60.0);
        scenes.printRow();
        std::printf(" %6ld %7ld %8.1f %8.1f\n", faults.nonFinite, faults.removed, memory.last,
                    wallSeconds());
        if (faults.newCause) std::printf("         guard: %s\n", faults.cause.c_str());
        faults.newCause = false;
        std::fflush(stdout);
    }

    // Summary.
    const double wall = wallSeconds();
    std::printf("\nenergy over %.0f s (drift = (E_end - E0)/E0; max dev = max |E - E0|/E0 over "
                "every tick)\n",
                opt.seconds);
    const bool invariantsHeld = scenes.printEnergy();
    std::printf("non-finite values: %ld, guard removals: %ld (both must be 0)\n", faults.nonFinite,
                faults.removed);
    std::printf("resident memory: %.1f MiB after set-up, %.1f MiB after the first report, %.1f MiB "
                "at the end, %.1f MiB at most\n",
                memory.start, memory.warm, memory.last, memory.max);
    std::printf("wall time: %.1f s (%.3f s per simulated second)\n", wall, wall / opt.seconds);
    if (!invariantsHeld) std::printf("an exactly conserved quantity drifted or left its band\n");
    return faults.nonFinite == 0 && faults.removed == 0 && invariantsHeld ? 0 : 1;
}
