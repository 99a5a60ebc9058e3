// bench_pile: the pile of `artillery bench scaling` (game/bench/scaling.cpp: wooden balls
// dropped into an open box) as particles and as Box2D circles, stepped on their own so
// that callgrind can count each side's instructions, which load does not change:
//
//   valgrind --tool=callgrind --toggle-collect='*stepParticlePile*' build/bench/bench_pile
//   valgrind --tool=callgrind --toggle-collect='*stepRigidPile*' build/bench/bench_pile
//   callgrind_annotate callgrind.out.<pid> | head -40
//
// Each side is built and settled for kPileSettleTicks (0.5 s, not counted), then steps
// `--skip` ticks (not counted either; none by default), then `--ticks` more; Ir per tick
// is the collected total over the ticks. Without valgrind it prints wall ms per tick
// (meaningful on a quiet machine only; read the ratio) and, for checking that a change
// gives the same bits, the particle world's hash and what the step did (contacts, pairs,
// passes, broad phases, sleepers); `--trace` prints that, the particles the sub-steps
// worked on (the rest were settled sleepers), and the wall ms, every tick.
// `--tuned` builds the Box2D side as Box2D is at its best for this scene (kTunedBox2D:
// every length x10, no time of impact) instead of as the game builds it.
//
// `--heap N --seconds S` instead drops the heap of `artillery bench scaling` and of
// tests/physics/pile_test.cpp (N balls, every other row half a spacing over) and
// prints, every simulated second, how many balls sleep, the kinetic energy, the fastest
// ball and the deepest overlap (in radii): whether a big heap comes to rest, and how far
// inside itself it rests.
// `--drop N --seconds S` does the same for the bench's own pile of N balls.
//
// Usage: bench_pile [--balls N] [--skip S] [--ticks T] [--side particles|rigid|both]
//                   [--tuned] [--trace] [--csv]
//        bench_pile --heap N [--seconds S]
//        bench_pile --drop N [--seconds S]
#include "bench/options.h"
#include "game/bench/scaling.h"
#include "physics/diagnostics.h"
#include "physics/rigid/rigid_world.h"
#include "physics/world.h"

#include <algorithm>
#include <optional>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

using namespace phys;
using Clock = std::chrono::steady_clock;

// The stepping loops callgrind collects in (--toggle-collect); never inlined, so that
// their names exist.
[[gnu::noinline]] void stepParticlePile(World& w, int ticks) {
    for (int t = 0; t < ticks; ++t)
        w.step();
}

[[gnu::noinline]] void stepRigidPile(RigidWorld& w, int ticks, double tick) {
    for (int t = 0; t < ticks; ++t)
        w.step(tick);
}

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

int sleepers(const ParticleSet& p) {
    int n = 0;
    for (std::size_t i = 0; i < p.slots(); ++i)
        n += (p.flags[i] & kAlive) && (p.flags[i] & kSleeping) ? 1 : 0;
    return n;
}

struct Options {
    long balls = 2000;
    int ticks = 60;
    int skip = 0; ///< ticks stepped after the settling and before the counted ones
    bool particles = true, rigid = true, csv = false, trace = false, tuned = false;
    long heap = 0, drop = 0; ///< balls of the staggered heap, of the bench's pile
    double seconds = 20.0;
};

// The deepest overlap of two balls, or of a ball and a static segment, in radii of the
// ball (the smaller one's): how far the contact solver leaves the pile inside itself.
// Pairs by a sweep along x.
double worstOverlapInRadii(const World& w) {
    const ParticleSet& p = w.particles;
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < p.slots(); ++i)
        if (p.flags[i] & kAlive) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](auto i, auto j) { return p.px[i] < p.px[j]; });
    double widest = 0.0;
    for (const std::size_t i : order)
        widest = std::max(widest, p.radius[i]);
    double worst = 0.0;
    for (std::size_t k = 0; k < order.size(); ++k) {
        const std::size_t i = order[k];
        const Vec2 pi = p.position(static_cast<ParticleId>(i));
        for (const Segment& s : w.shapes.segments)
            worst = std::max(worst, (p.radius[i] - closestPoint(s, pi).distance) / p.radius[i]);
        for (std::size_t m = k + 1; m < order.size(); ++m) {
            const std::size_t j = order[m];
            if (p.px[j] - pi.x >= p.radius[i] + widest) break;
            const double reach = p.radius[i] + p.radius[j];
            const double gap = length(p.position(static_cast<ParticleId>(j)) - pi) - reach;
            worst = std::max(worst, -gap / std::min(p.radius[i], p.radius[j]));
        }
    }
    return worst;
}

// Every simulated second until `seconds`: how many balls sleep, the kinetic energy, the
// fastest ball, the deepest overlap, the wall ms per tick and the hash: whether a big pile
// comes to rest, and how well it is solved.
void printSettling(World& w, double seconds) {
    const int perSecond = static_cast<int>(std::lround(1.0 / w.def().tickSeconds));
    std::printf("%8s %9s %12s %12s %11s %10s %16s\n", "time_s", "asleep", "kinetic_J",
                "fastest_m_s", "overlap_r", "ms_per_tick", "hash");
    for (int s = 1; s <= static_cast<int>(std::lround(seconds)); ++s) {
        const auto t0 = Clock::now();
        stepParticlePile(w, perSecond);
        const double ms = msSince(t0) / perSecond;
        double fastest = 0.0;
        const ParticleSet& p = w.particles;
        for (std::size_t i = 0; i < p.slots(); ++i)
            fastest = std::max(fastest, std::hypot(p.vx[i], p.vy[i]));
        std::printf("%8d %9d %12.4g %12.4g %11.4f %10.3f %016llx\n", s, sleepers(p),
                    energy(p, w.springs, w.def().forces).kinetic, fastest,
                    worstOverlapInRadii(w), ms,
                    static_cast<unsigned long long>(w.hash()));
    }
}

// The heap of `artillery bench scaling` and tests/physics/pile_test.cpp (staggeredHeap):
// the pile's balls with every other row half a spacing over, so they settle into a heap.
void runHeap(long n, double seconds) {
    auto w = game::bench::particlePile(n, game::bench::PileShape::Staggered);
    std::printf("heap of %ld balls, staggered rows\n", n);
    printSettling(*w, seconds);
}

// The scaling bench's own pile (rows straight above each other, so it lands in columns
// that topple for seconds), from the drop.
void runDrop(long n, double seconds) {
    auto w = game::bench::particlePile(n);
    std::printf("the bench's pile of %ld balls, from the drop\n", n);
    printSettling(*w, seconds);
}

/// The options, or nullopt after saying what is wrong and the usage.
std::optional<Options> parseOptions(int argc, char** argv) {
    Options o;
    using bench_args::countOption, bench_args::realOption;
    constexpr const char* kName = "bench_pile";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool more = i + 1 < argc;
        bool ok = true;
        if (a == "--balls" && more) {
            ok = countOption(kName, "--balls", argv[++i], o.balls, 1);
        } else if (a == "--skip" && more) {
            ok = countOption(kName, "--skip", argv[++i], o.skip, 0, 1e7);
        } else if (a == "--ticks" && more) {
            ok = countOption(kName, "--ticks", argv[++i], o.ticks, 1, 1e7);
        } else if (a == "--side" && more) {
            const std::string side = argv[++i];
            o.particles = side == "particles" || side == "both";
            o.rigid = side == "rigid" || side == "both";
            ok = o.particles || o.rigid;
            if (!ok)
                std::fprintf(stderr, "%s: --side expects particles, rigid or both, got '%s'\n",
                             kName, side.c_str());
        } else if (a == "--tuned") {
            o.tuned = true;
        } else if (a == "--trace") {
            o.trace = true;
        } else if (a == "--csv") {
            o.csv = true;
        } else if (a == "--heap" && more) {
            ok = countOption(kName, "--heap", argv[++i], o.heap, 1);
        } else if (a == "--drop" && more) {
            ok = countOption(kName, "--drop", argv[++i], o.drop, 1);
        } else if (a == "--seconds" && more) {
            ok = realOption(kName, "--seconds", argv[++i], o.seconds, 1e-3, 1e6);
        } else {
            // Here either an option that takes a value came last, or `a` is unknown.
            const bool takesValue = a == "--balls" || a == "--skip" || a == "--ticks" ||
                                    a == "--side" || a == "--heap" || a == "--drop" ||
                                    a == "--seconds";
            if (takesValue)
                std::fprintf(stderr, "%s: %s needs a value\n", kName, a.c_str());
            else
                std::fprintf(stderr, "%s: unknown option '%s'\n", kName, a.c_str());
            ok = false;
        }
        if (!ok) {
            std::fprintf(stderr,
                         "usage: bench_pile [--balls N >= 1] [--skip S >= 0] [--ticks T >= 1] "
                         "[--side particles|rigid|both] [--tuned] [--trace] [--csv]\n"
                         "       bench_pile --heap N >= 1 [--seconds S > 0]\n"
                         "       bench_pile --drop N >= 1 [--seconds S > 0]\n");
            return std::nullopt;
        }
    }
    return o;
}

/// ms per tick of the particle pile over o.ticks after settling (and a line unless --csv).
double timeParticlePile(const Options& o) {
    auto w = game::bench::particlePile(o.balls);
    for (int t = 0; t < game::bench::kPileSettleTicks + o.skip; ++t)
        w->step();
    const auto t0 = Clock::now();
    if (o.trace) // what each tick did, to see where a window's work falls
        for (int t = 0; t < o.ticks; ++t) {
            const auto tickStart = Clock::now();
            stepParticlePile(*w, 1);
            const double ms = msSince(tickStart);
            const CollisionStats& s = w->collisionStats();
            std::printf("tick %d: %.4f ms, %zu contacts, %d pairs, %d passes (%d of "
                        "changes only), %d broad phases, %d asleep, %d worked on\n",
                        game::bench::kPileSettleTicks + o.skip + t + 1, ms,
                        w->contacts().size(), s.pairs, s.passes, s.changesOnly, s.broadPhases,
                        sleepers(w->particles), s.active);
        }
    else
        stepParticlePile(*w, o.ticks);
    const double particleMs = msSince(t0) / o.ticks;
    const CollisionStats& s = w->collisionStats();
    if (!o.csv)
        std::printf("particles %ld balls: %.4f ms/tick; last tick: %zu contacts, %d pairs, "
                    "%d passes, %d broad phases, %d asleep; hash %016llx\n",
                    o.balls, particleMs, w->contacts().size(), s.pairs, s.passes, s.broadPhases,
                    sleepers(w->particles), static_cast<unsigned long long>(w->hash()));
    return particleMs;
}

/// ms per tick of the Box2D pile, the same way.
double timeRigidPile(const Options& o) {
    auto w = o.tuned ? game::bench::rigidPile(o.balls, game::bench::kTunedBox2D)
                     : game::bench::rigidPile(o.balls);
    const double tick = WorldDef{}.tickSeconds;
    for (int t = 0; t < game::bench::kPileSettleTicks + o.skip; ++t)
        w->step(tick);
    const auto t0 = Clock::now();
    if (o.trace)
        for (int t = 0; t < o.ticks; ++t) {
            const auto tickStart = Clock::now();
            stepRigidPile(*w, 1, tick);
            std::printf("box2d tick %d: %.4f ms\n",
                        game::bench::kPileSettleTicks + o.skip + t + 1, msSince(tickStart));
        }
    else
        stepRigidPile(*w, o.ticks, tick);
    const double rigidMs = msSince(t0) / o.ticks;
    if (!o.csv)
        std::printf("box2d%s %ld balls: %.4f ms/tick; hash %016llx\n",
                    o.tuned ? " (tuned)" : "    ", o.balls, rigidMs,
                    static_cast<unsigned long long>(w->hash()));
    return rigidMs;
}

} // namespace

int main(int argc, char** argv) {
    const std::optional<Options> parsed = parseOptions(argc, argv);
    if (!parsed) return 2;
    const Options& o = *parsed;
    if (o.heap > 0) {
        runHeap(o.heap, o.seconds);
        return 0;
    }
    if (o.drop > 0) {
        runDrop(o.drop, o.seconds);
        return 0;
    }

    const double particleMs = o.particles ? timeParticlePile(o) : NAN;
    const double rigidMs = o.rigid ? timeRigidPile(o) : NAN;
    if (o.csv) {
        std::printf("balls,ticks,particle_ms,box2d_ms\n%ld,%d,%.5g,%.5g\n", o.balls, o.ticks,
                    particleMs, rigidMs);
    } else if (o.particles && o.rigid) {
        std::printf("box2d / particles: %.2fx (wall clock: read it on a quiet machine)\n",
                    rigidMs / particleMs);
    }
    return 0;
}
