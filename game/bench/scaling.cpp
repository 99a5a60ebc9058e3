#include "game/bench/scaling.h"

#include "game/bench/flight_reference.h"
#include "physics/rigid/rigid_world.h"
#include "physics/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numeric>
#include <random>

namespace game::bench {

using namespace phys;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

double mean(const std::vector<double>& v) {
    return v.empty() ? 0.0
                     : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

std::unique_ptr<World> flightWorld(long n, Integrator integrator = Integrator::SymplecticEuler) {
    WorldDef d;
    d.integrator = integrator;
    d.forces.drag = DragModel::Quadratic;
    d.forces.wind = {3.0, 0.0};
    d.collision.model = ContactModel::None;
    auto w = std::make_unique<World>(d);
    w->particles.reserve(static_cast<std::size_t>(n));
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (long i = 0; i < n; ++i) {
        ParticleDef pd;
        pd.position = {1000.0 * u(rng), 1000.0 + 500.0 * u(rng)};
        pd.velocity = {50.0 * u(rng), 50.0 * u(rng)};
        pd.mass = 1.0;
        pd.radius = 0.05;
        w->particles.add(pd);
    }
    return w;
}

std::unique_ptr<World> clothWorld(int side, int substeps) {
    WorldDef d;
    d.integrator = Integrator::SymplecticEuler;
    d.tickSeconds = 1.0 / 60.0;
    d.substeps = substeps;
    d.collision.model = ContactModel::None;
    auto w = std::make_unique<World>(d);
    const double h = 0.05;
    w->particles.reserve(static_cast<std::size_t>(side) * side);
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            ParticleDef pd;
            pd.position = {i * h, -j * h};
            pd.mass = (j == 0) ? 0.0 : 0.01; // top row pinned
            pd.radius = 0.01;
            w->particles.add(pd);
        }
    auto link = [&](int a, int b, double len) {
        Spring s;
        s.a = static_cast<ParticleId>(a);
        s.b = static_cast<ParticleId>(b);
        s.restLength = len;
        s.stiffness = 200.0;
        s.damping = 0.02;
        w->springs.push_back(s);
    };
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const int k = j * side + i;
            if (i + 1 < side) link(k, k + 1, h);
            if (j + 1 < side) link(k, k + side, h);
            if (i + 1 < side && j + 1 < side) link(k, k + side + 1, h * std::sqrt(2.0));
            if (i > 0 && j + 1 < side) link(k, k + side - 1, h * std::sqrt(2.0));
        }
    return w;
}

// The pile: balls of radius 0.05 m on a grid 0.12 m apart (a little jitter so they do
// not stack in perfect columns), about twice as many columns as rows, in an open box.
constexpr double kBallRadius = 0.05, kBallSpacing = 0.12;
constexpr double kWoodenRestitution = 0.603; // the measured wooden ball's preset (materials.h)

struct PileLayout {
    long columns = 1, rows = 1;
    double width = 1.0;       ///< inside of the box, m
    double oddRowShift = 0.0; ///< spacings the odd rows start to the right
};

// The staggered heap is the heap of tests/physics/pile_test.cpp (staggeredHeap) and of
// `bench_pile --heap`: its odd rows half a spacing right, in a box wider by as much.
PileLayout pileLayout(long n, PileShape shape) {
    PileLayout l;
    l.columns = std::max(4L, static_cast<long>(std::ceil(std::sqrt(2.0 * n))));
    l.rows = (n + l.columns - 1) / l.columns;
    l.oddRowShift = shape == PileShape::Staggered ? 0.5 : 0.0;
    l.width = static_cast<double>(l.columns) * kBallSpacing + (1.0 + l.oddRowShift) * kBallSpacing;
    return l;
}

template <class Place> void placeBalls(long n, const PileLayout& l, Place place) {
    std::mt19937_64 rng(777);
    std::uniform_real_distribution<double> jitter(-0.01, 0.01);
    for (long i = 0; i < n; ++i) {
        const long c = i % l.columns, r = i / l.columns;
        const double shift = r % 2 == 1 ? l.oddRowShift * kBallSpacing : 0.0;
        place(Vec2{kBallSpacing * (static_cast<double>(c) + 1.0) + shift + jitter(rng),
                   kBallSpacing * (static_cast<double>(r) + 1.0) + jitter(rng)});
    }
}

} // namespace

std::unique_ptr<World> particlePile(long n, PileShape shape) {
    const PileLayout l = pileLayout(n, shape);
    auto w = std::make_unique<World>(WorldDef{}); // default collision settings
    const double top = kBallSpacing * static_cast<double>(l.rows + 4);
    w->shapes.addSegment({0.0, 0.0}, {l.width, 0.0}, material::kWooden);
    w->shapes.addSegment({0.0, 0.0}, {0.0, top}, material::kWooden);
    w->shapes.addSegment({l.width, 0.0}, {l.width, top}, material::kWooden);
    w->particles.reserve(static_cast<std::size_t>(n));
    placeBalls(n, l, [&](Vec2 p) {
        ParticleDef pd;
        pd.position = p;
        pd.radius = kBallRadius;
        pd.mass = 0.1;
        pd.material = material::kWooden;
        w->particles.add(pd);
    });
    return w;
}

std::unique_ptr<RigidWorld> rigidPile(long n, RigidPileSetup setup, PileShape shape) {
    const PileLayout l = pileLayout(n, shape);
    const double s = setup.scale;
    RigidWorldDef def;
    def.gravity = def.gravity * s;
    def.restitutionThreshold *= s; // a speed: the same bounces are lost at every scale
    def.continuousPhysics = setup.continuous;
    auto w = std::make_unique<RigidWorld>(def);
    const double width = l.width * s, top = kBallSpacing * static_cast<double>(l.rows + 4) * s;
    const RigidMaterial wood{1000.0, 0.6, kWoodenRestitution};
    // Solid inside the loop would trap the balls, so three open chains: floor (drawn
    // left to right, solid below) and the walls (solid outside).
    const Vec2 floor[] = {{0.0, 0.0}, {width, 0.0}};
    const Vec2 left[] = {{0.0, top}, {0.0, 0.0}};
    const Vec2 right[] = {{width, 0.0}, {width, top}};
    w->createTerrain(floor, wood);
    w->createTerrain(left, wood);
    w->createTerrain(right, wood);
    placeBalls(n, l, [&](Vec2 p) {
        BodyDef bd;
        bd.position = p * s;
        w->createCircle(bd, kBallRadius * s, wood);
    });
    return w;
}

double pileWorkload(long n, int steps) {
    auto w = particlePile(n);
    for (int i = 0; i < kPileSettleTicks; ++i) w->step();
    const auto t0 = Clock::now();
    for (int i = 0; i < steps; ++i) w->step();
    return seconds(t0);
}

namespace {

double rigidPileSeconds(long n, int steps, RigidPileSetup setup) {
    auto w = rigidPile(n, setup);
    const double tick = WorldDef{}.tickSeconds;
    for (int i = 0; i < kPileSettleTicks; ++i) w->step(tick);
    const auto t0 = Clock::now();
    for (int i = 0; i < steps; ++i) w->step(tick);
    return seconds(t0);
}

} // namespace

double rigidPileWorkload(long n, int steps) {
    return rigidPileSeconds(n, steps, {});
}

double tunedRigidPileWorkload(long n, int steps) {
    return rigidPileSeconds(n, steps, kTunedBox2D);
}

namespace {

// One run: the three piles are built and settled, then step through the same span of the
// drop in windows, in turn. The windows are not repeats: the pile lands, settles and
// falls asleep across them, so each side's figure is its cost of the whole span, not the
// median of its windows (which would time whichever stage fell in the middle).
PileComparison comparePilesOnce(long balls, int windowTicks, int windows, PileShape shape) {
    PileComparison r;
    r.balls = balls;
    r.shape = shape;
    auto particles = particlePile(balls, shape);
    auto rigid = rigidPile(balls, {}, shape);
    auto tuned = rigidPile(balls, kTunedBox2D, shape);
    const double tick = WorldDef{}.tickSeconds;
    for (int i = 0; i < kPileSettleTicks; ++i) {
        particles->step();
        rigid->step(tick);
        tuned->step(tick);
    }
    // ms per step of one window of a Box2D pile.
    auto rigidWindowMs = [&](RigidWorld& w) {
        const auto t0 = Clock::now();
        for (int i = 0; i < windowTicks; ++i)
            w.step(tick);
        return 1e3 * seconds(t0) / windowTicks;
    };
    r.windowTicks = windowTicks;
    for (int k = 0; k < std::max(1, windows); ++k) {
        long awake = 0;
        const auto t0 = Clock::now();
        for (int i = 0; i < windowTicks; ++i) {
            particles->step();
            awake += balls - particles->collisionStats().sleeping;
        }
        r.particleWindowMs.push_back(1e3 * seconds(t0) / windowTicks);
        r.asleepAfterWindow.push_back(particles->collisionStats().sleeping);
        r.awakeBallTicks.push_back(awake);
        r.rigidWindowMs.push_back(rigidWindowMs(*rigid));
        r.tunedRigidWindowMs.push_back(rigidWindowMs(*tuned));
    }
    r.particleMs = mean(r.particleWindowMs);
    r.rigidMs = mean(r.rigidWindowMs);
    r.tunedRigidMs = mean(r.tunedRigidWindowMs);
    r.load = loadNow();
    r.runs = 1;
    r.particleRunMs = {r.particleMs};
    r.rigidRunMs = {r.rigidMs};
    r.tunedRigidRunMs = {r.tunedRigidMs};
    return r;
}

} // namespace

PileComparison comparePiles(long balls, int windowTicks, int windows, int runs, PileShape shape) {
    PileComparison best = comparePilesOnce(balls, windowTicks, windows, shape);
    for (int k = 1; k < runs; ++k) {
        const PileComparison run = comparePilesOnce(balls, windowTicks, windows, shape);
        best.particleRunMs.push_back(run.particleMs);
        best.rigidRunMs.push_back(run.rigidMs);
        best.tunedRigidRunMs.push_back(run.tunedRigidMs);
        if (run.particleMs < best.particleMs)
            best.particleMs = run.particleMs, best.particleWindowMs = run.particleWindowMs;
        if (run.rigidMs < best.rigidMs)
            best.rigidMs = run.rigidMs, best.rigidWindowMs = run.rigidWindowMs;
        if (run.tunedRigidMs < best.tunedRigidMs)
            best.tunedRigidMs = run.tunedRigidMs, best.tunedRigidWindowMs = run.tunedRigidWindowMs;
        best.load = std::fmax(best.load, run.load); // the one that is a number, if one is
    }
    best.runs = static_cast<int>(best.particleRunMs.size());
    return best;
}

const PileComparison* firstLeadThatDoesNotGrow(const std::vector<PileComparison>& piles,
                                               PileLead lead) {
    for (std::size_t k = 1; k < piles.size(); ++k)
        if (!((piles[k].*lead)() > (piles[k - 1].*lead)())) return &piles[k];
    return nullptr;
}

double flightWorkload(long n, int steps) {
    auto w = flightWorld(n);
    w->step();
    w->step();
    const auto t0 = Clock::now();
    for (int i = 0; i < steps; ++i) w->step();
    return seconds(t0);
}

double clothWorkload(long n, int steps) {
    const int side = std::max(2, static_cast<int>(std::lround(std::sqrt(static_cast<double>(n)))));
    auto w = clothWorld(side, 8);
    w->step();
    const auto t0 = Clock::now();
    for (int i = 0; i < steps; ++i) w->step();
    return seconds(t0);
}

std::vector<ScalingPoint> measureScaling(const std::string& name, const Workload& work,
                                         const ScalingDef& def,
                                         const std::function<void(int, int)>& progress) {
    std::vector<ScalingPoint> out;
    int done = 0;
    for (long n : def.sizes) {
        std::vector<double> t;
        for (int r = 0; r < std::max(1, def.repeats); ++r) t.push_back(work(n, def.steps));
        const double us = 1e6 * median(t) / def.steps;
        out.push_back({name, n, us, 1e3 * us / static_cast<double>(n), loadNow()});
        if (progress) progress(++done, static_cast<int>(def.sizes.size()));
    }
    return out;
}

double scalingExponent(const std::vector<ScalingPoint>& points) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (const auto& p : points) {
        if (p.items <= 0 || p.usPerStep <= 0) continue;
        const double x = std::log(static_cast<double>(p.items)), y = std::log(p.usPerStep);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        ++n;
    }
    return n < 2 ? NAN : (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

double parseLoadAverage(const std::string& text) {
    char* end = nullptr;
    const double one = std::strtod(text.c_str(), &end);
    return end != text.c_str() && std::isfinite(one) && one >= 0.0 ? one : NAN;
}

double loadNow() {
    std::FILE* f = std::fopen("/proc/loadavg", "r");
    if (!f) return NAN;
    char text[128] = {};
    const std::size_t got = std::fread(text, 1, sizeof text - 1, f);
    std::fclose(f);
    return parseLoadAverage(std::string(text, got));
}

double spreadOfRuns(const std::vector<double>& runMs) {
    if (runMs.size() < 2) return 0.0;
    const auto [fastest, slowest] = std::minmax_element(runMs.begin(), runMs.end());
    return *fastest > 0.0 ? *slowest / *fastest - 1.0 : 0.0;
}

double PileComparison::widestSpread() const {
    return std::max(spreadOfRuns(particleRunMs), spreadOfRuns(tunedRigidRunMs));
}

std::string busyHostRefusal(double spread, bool intoDocs, bool underLoad) {
    if (!intoDocs || underLoad || !(spread > kBusyHostSpread)) return {};
    char why[200];
    std::snprintf(why, sizeof why,
                  "a pile's runs spread by %.1f %% (more than %.0f %%): the host was busy, "
                  "whatever its load average said",
                  100.0 * spread, 100.0 * kBusyHostSpread);
    return std::string("refusing to write figures into docs/: ") + why +
           "; run again on a quiet host, or pass --under-load to mark them as taken under load";
}

std::string docsFiguresRefusal(double load, bool intoDocs, bool underLoad) {
    if (!intoDocs || underLoad || load <= 1.0) return {};
    char why[120];
    if (std::isfinite(load))
        std::snprintf(why, sizeof why, "the 1-minute load average is %.2f (above 1)", load);
    else
        std::snprintf(why, sizeof why, "the load average cannot be read (/proc/loadavg)");
    return std::string("refusing to write figures into docs/: ") + why +
           "; wait for a quiet machine, or pass --under-load to mark them as taken under load";
}

double FlightComparison::bytesPerParticle() const {
    return static_cast<double>(kFlightBytesPerParticle);
}

namespace {
double gigabytesPerSecond(long n, double ms) {
    return ms > 0 ? static_cast<double>(n) * kFlightBytesPerParticle / (ms * 1e6) : 0.0;
}
} // namespace

double FlightComparison::updateGBs() const { return gigabytesPerSecond(n, updateMs); }
double FlightComparison::referenceGBs() const { return gigabytesPerSecond(n, referenceMs); }
double FlightComparison::copyGBs() const { return gigabytesPerSecond(n, copyMs); }

FlightComparison compareFlight(long n, bool velocityVerlet, int steps, int repeats) {
    FlightComparison r;
    r.n = n;
    r.integrator = velocityVerlet ? "velocity-verlet" : "symplectic-euler";
    r.referenceLanes = velocityVerlet ? flightReferenceVerletLanes() : flightReferenceLanes();
    auto w = flightWorld(n, velocityVerlet ? Integrator::VelocityVerlet : Integrator::SymplecticEuler);
    // The reference steps its own copy of the same particles (same sizes, same state).
    auto ref = flightWorld(n, Integrator::SymplecticEuler);
    const ForceDef& forces = w->def().forces;
    FlightReferenceStep c;
    c.h = w->def().tickSeconds / w->def().substeps;
    c.gravity = forces.gravity;
    c.wind = forces.wind;
    c.halfRhoPi = LocalForceLaw(forces).halfRhoPi;
    // The copy moves as many bytes as a step reads and writes: half of them each way.
    const std::size_t copy = static_cast<std::size_t>(n) * kFlightBytesPerParticle / 2;
    std::vector<unsigned char> from(copy, 1), to(copy, 0);
    w->step();
    // The reference does the integrator's own arithmetic: one drag evaluation per step
    // for symplectic Euler, two for velocity Verlet.
    auto reference = [&] {
        if (velocityVerlet)
            flightReferenceVerletStep(ref->particles, c);
        else
            flightReferenceStep(ref->particles, c);
    };
    reference();
    copyBytes(to.data(), from.data(), copy);
    std::vector<double> ut, rt, ct;
    for (int k = 0; k < std::max(1, repeats); ++k) {
        auto t0 = Clock::now();
        for (int i = 0; i < steps; ++i) w->step();
        ut.push_back(seconds(t0) / steps);
        t0 = Clock::now();
        for (int i = 0; i < steps; ++i) reference();
        rt.push_back(seconds(t0) / steps);
        t0 = Clock::now();
        for (int i = 0; i < steps; ++i) copyBytes(to.data(), from.data(), copy);
        ct.push_back(seconds(t0) / steps);
    }
    r.updateMs = 1e3 * median(ut);
    r.referenceMs = 1e3 * median(rt);
    r.copyMs = 1e3 * median(ct);
    r.load = loadNow();
    return r;
}

double clothFrameMs(int side, int frames) {
    auto w = clothWorld(side, 8);
    w->step();
    std::vector<double> t;
    for (int f = 0; f < frames; ++f) {
        const auto t0 = Clock::now();
        w->step();
        t.push_back(seconds(t0));
    }
    return 1e3 * median(t);
}

std::string toCsv(const std::vector<ScalingPoint>& points, bool underLoad) {
    std::string out = "workload,items,us_per_step,ns_per_item,load_1min,under_load\n";
    char line[200];
    for (const auto& p : points) {
        std::snprintf(line, sizeof line, "%s,%ld,%.4g,%.4g,%.2f,%d\n", p.workload.c_str(),
                      p.items, p.usPerStep, p.nsPerItem, p.load, underLoad ? 1 : 0);
        out += line;
    }
    return out;
}

} // namespace game::bench
