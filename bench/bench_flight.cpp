// bench_flight: the in-flight comparison of `artillery bench scaling`
// (game/bench/scaling.cpp, compareFlight: the particle layer's update against a reference
// kernel of the same bytes and arithmetic) on its own, so that callgrind can count each
// side's instructions, which load does not change:
//
//   valgrind --tool=callgrind --callgrind-out-file=cg.flight build/bench/bench_flight
//   callgrind_annotate --inclusive=yes cg.flight | grep -E 'World::step|flightReference'
//
// World::step is the update (all of it, the model choice and counts included) and
// flightReferenceStep (flightReferenceVerletStep with --verlet) the reference, both over
// the same number of steps. Without valgrind it prints the wall-clock figures, which
// mean something on a quiet machine only.
//
// Usage: bench_flight [--particles N] [--steps S] [--verlet]
#include "bench/options.h"
#include "game/bench/scaling.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

int main(int argc, char** argv) {
    long particles = 10000;
    int steps = 50;
    bool verlet = false;
    for (int i = 1; i < argc; ++i) {
        const bool more = i + 1 < argc;
        bool ok = true;
        if (std::strcmp(argv[i], "--particles") == 0 && more) {
            ok = bench_args::countOption("bench_flight", "--particles", argv[++i], particles, 1);
        } else if (std::strcmp(argv[i], "--steps") == 0 && more) {
            ok = bench_args::countOption("bench_flight", "--steps", argv[++i], steps, 1);
        } else if (std::strcmp(argv[i], "--verlet") == 0) {
            verlet = true;
        } else {
            ok = false;
        }
        if (!ok) {
            std::fprintf(stderr,
                         "usage: bench_flight [--particles N >= 1] [--steps S >= 1] [--verlet]\n");
            return 2;
        }
    }
    const game::bench::FlightComparison r =
        game::bench::compareFlight(particles, verlet, steps, 1);
    std::printf("%ld in flight, %s: update %.4f ms/step, reference %.4f ms: %.2fx  [load %.2f]\n",
                particles, verlet ? "velocity-verlet" : "symplectic-euler", r.updateMs,
                r.referenceMs, r.updateMs / r.referenceMs, r.load);
    return 0;
}
