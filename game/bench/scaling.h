// How step cost grows with the scene: particles in flight, springs in cloth (and, from
// the collision and rigid layers, piles with contacts and Box2D bodies), plus the
// particle update against a plain streaming kernel over the same bytes, the
// memory-bandwidth limit (a vectorized reference kernel and a memcpy in the same
// process), and the load average beside every figure.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace phys {
class World;
class RigidWorld;
} // namespace phys

namespace game::bench {

struct ScalingPoint {
    std::string workload;  ///< "flight", "cloth", ...
    long items = 0;        ///< particles (or bodies)
    double usPerStep = 0;  ///< median wall time of one world step, microseconds
    double nsPerItem = 0;  ///< usPerStep / items, nanoseconds
    double load = NAN;     ///< 1-minute load average when measured
};

struct ScalingDef {
    std::vector<long> sizes{1000, 3000, 10000, 30000, 100000};
    int steps = 20;   ///< timed steps per size (after 2 warm-up steps)
    int repeats = 3;  ///< median of repeats
};

/// A workload: builds a world of about n items and steps it.
using Workload = std::function<double(long n, int steps)>; // returns seconds for `steps` steps

/// Times `work` at every size of def.
std::vector<ScalingPoint> measureScaling(const std::string& name, const Workload& work,
                                         const ScalingDef& def,
                                         const std::function<void(int, int)>& progress = {});

/// Particles in flight under gravity and quadratic drag, symplectic Euler.
double flightWorkload(long n, int steps);
/// A square cloth of about n particles with structural and shear springs, 8 sub-steps.
double clothWorkload(long n, int steps);

/// A pile of about n balls (radius 0.05 m, wooden, COR 0.603) dropped into a box of
/// three static segments, in the particle layer with the default collision settings.
/// The first `settleTicks` ticks (the balls falling and landing) are not timed.
double pileWorkload(long n, int steps);
/// The same pile as Box2D circles in a RigidWorld (same box, radius, restitution), as
/// the game sets Box2D up, and at the size Box2D is tuned for (kTunedBox2D, below).
double rigidPileWorkload(long n, int steps);
double tunedRigidPileWorkload(long n, int steps);
/// How the balls start: rows straight above each other (the pile: the balls land in
/// columns, each touching the balls above and below it), or every other row shifted by
/// half a spacing (the heap: each ball settles into the notch of two below it and
/// touches its neighbours at the sides, as poured balls do).
enum class PileShape { Columns, Staggered };
/// The two piles themselves, unsettled, for programs that step them on their own
/// (bench/bench_pile.cpp counts their instructions under callgrind).
std::unique_ptr<phys::World> particlePile(long n, PileShape shape = PileShape::Columns);

/// How the Box2D pile is built. The game's way is metres with continuous collision on
/// (which RigidWorld itself switches off past kMostContinuousBodies bodies, so for the
/// bench's piles of 1,000 balls and more the two setups differ by their scale alone).
/// Box2D's own tolerances are fixed lengths tuned for bodies about 1 m across (in the
/// Debian build: a 0.1 m margin on every broad-phase box, 5 mm of linear slop, a 1 cm
/// skin on edges), so for balls 0.1 m across it keeps a contact for each of some twenty
/// neighbours whose boxes overlap, and its pile stands on a skin a tenth of a radius
/// thick. Scaling every length (and gravity with it) gives the same motion in Box2D's
/// own units at the size it is tuned for.
struct RigidPileSetup {
    double scale = 1.0;     ///< every length and gravity times this
    bool continuous = true; ///< Box2D's time of impact against the static box
};
/// Box2D at its best for this scene: balls 1 m across, and no time of impact, which
/// these speeds do not need (nothing leaves the box without it; tested).
inline constexpr RigidPileSetup kTunedBox2D{10.0, false};
std::unique_ptr<phys::RigidWorld> rigidPile(long n, RigidPileSetup setup = {},
                                            PileShape shape = PileShape::Columns);

/// Ticks run before the pile workloads are timed: 0.5 s at 1/120 s, so most balls are
/// in contact when the clock starts.
inline constexpr int kPileSettleTicks = 60;

/// The same pile of balls as particles and as Box2D circles: each side's cost of the same
/// span of the drop, ticks kPileSettleTicks + 1 on, in its best of `runs` runs.
struct PileComparison {
    long balls = 0;
    PileShape shape = PileShape::Columns;
    /// ms per step over the whole timed span (its windows' total over its ticks): the cost
    /// of simulating those ticks of the drop, in the side's fastest run.
    double particleMs = 0, rigidMs = 0;
    double load = NAN; ///< the highest 1-minute load average at the end of a run
    /// Each run's span cost per side, in run order. Each run builds the three piles anew
    /// and steps the same ticks, bit for bit; its time is the work plus whatever else the
    /// machine did meanwhile. Box2D as the game builds it keeps about twenty contacts a
    /// ball, several megabytes, and on the development machine (a virtual one) its runs
    /// spread by up to half, within one process too, while the guest's load stays low;
    /// so a side's figure is its fastest run, and the spread is printed beside it.
    int runs = 0;
    std::vector<double> particleRunMs, rigidRunMs, tunedRigidRunMs;
    /// The span's consecutive windows, windowTicks each, timed in turn (particles, Box2D,
    /// the tuned Box2D) so a burst of other work hits all three: ms per step of each
    /// side, the particles asleep at the window's end, and the awake particles summed
    /// over the window's ticks (the work a step costs scales with them). A pile that falls
    /// asleep costs far less in the later windows: they say which stage cost what. Each
    /// side's windows are those of its fastest run.
    int windowTicks = 0;
    std::vector<double> particleWindowMs, rigidWindowMs;
    std::vector<int> asleepAfterWindow;
    std::vector<long> awakeBallTicks;
    double speedup() const { return particleMs > 0 ? rigidMs / particleMs : 0; }
    /// The same span of Box2D set up as kTunedBox2D, timed third in each window: the
    /// lead over Box2D at its best, not as the game builds it.
    double tunedRigidMs = 0;
    std::vector<double> tunedRigidWindowMs;
    double speedupOverTuned() const { return particleMs > 0 ? tunedRigidMs / particleMs : 0; }
    /// The widest spread of the runs (spreadOfRuns) of the particles and the tuned Box2D,
    /// the two sides the 10x is judged by.
    double widestSpread() const;
    /// The timed span, ticks counted from 1 at the drop.
    int firstTick() const { return kPileSettleTicks + 1; }
    int lastTick() const {
        return kPileSettleTicks + windowTicks * static_cast<int>(particleWindowMs.size());
    }
};
PileComparison comparePiles(long balls = 2000, int windowTicks = 60, int windows = 3, int runs = 1,
                            PileShape shape = PileShape::Columns);

/// Which lead a pile is judged by: speedup() or speedupOverTuned().
using PileLead = double (PileComparison::*)() const;
/// The first pile (of `piles`, smallest first) whose lead is not above the lead of the
/// pile before it, or nullptr when the lead grows at every size.
const PileComparison* firstLeadThatDoesNotGrow(const std::vector<PileComparison>& piles,
                                               PileLead lead = &PileComparison::speedup);

/// Least-squares slope of log(cost) against log(n): 1 is linear scaling.
double scalingExponent(const std::vector<ScalingPoint>& points);

/// The 1-minute load average when a figure was taken (from /proc/loadavg; NAN where
/// the system does not say). The bench itself adds up to 1 while it runs.
double loadNow();
/// The first field of /proc/loadavg's text ("0.42 0.30 0.21 1/98 1234"), NAN if none.
double parseLoadAverage(const std::string& text);

/// Why the bench may not write its figures into docs/ now, "" when it may: figures for
/// the documentation need a quiet machine (1-minute load `load` at most 1; NAN: the
/// load cannot be read), unless `underLoad` (--under-load) marks them as taken under load.
std::string docsFiguresRefusal(double load, bool intoDocs, bool underLoad);

/// How far the slowest of a side's runs lies above its fastest: slowest / fastest - 1
/// (0 for fewer than two runs). Every run steps the same bits, so on a quiet host they
/// take the same time within a few percent.
double spreadOfRuns(const std::vector<double>& runMs);
/// Runs that spread wider than this were timed on a busy host, whatever the load average
/// says (docs/performance.md, "A slow host at a low load"): on the development machine
/// the piles' quiet runs spread by 0-8 %, those in the host's slow spells by 15-70 %, and
/// the slow spells slow Box2D more than the particles, so a lead taken in one is inflated.
inline constexpr double kBusyHostSpread = 0.12;
/// The same refusal after the run, for runs spread wider than kBusyHostSpread (`spread`),
/// "" when they are not, or the figures do not go into docs/, or are marked --under-load.
std::string busyHostRefusal(double spread, bool intoDocs, bool underLoad);

/// Particles in flight (gravity, quadratic drag relative to a wind) under one integrator,
/// side by side in one process with the reference kernel of that integrator's arithmetic
/// over the same arrays (flight_reference.h) and a memcpy moving the same number of bytes: per-step medians
/// of alternating repeats, so a burst of load from elsewhere hits all three.
struct FlightComparison {
    long n = 0;
    std::string integrator;   ///< "symplectic-euler" (the fused pass) or "velocity-verlet"
    double updateMs = 0;      ///< World::step
    double referenceMs = 0;   ///< flightReferenceStep (or flightReferenceVerletStep)
    double copyMs = 0;        ///< memcpy of n * kFlightBytesPerParticle / 2 bytes
    int referenceLanes = 0;   ///< 4 (AVX2), 2 (SSE2) or 1
    double load = NAN;        ///< 1-minute load average when measured
    double bytesPerParticle() const;
    double ratio() const { return referenceMs > 0 ? updateMs / referenceMs : 0; }
    /// Bytes moved per second (read + written), 1e9 B/s.
    double updateGBs() const;
    double referenceGBs() const;
    double copyGBs() const;
};
FlightComparison compareFlight(long n, bool velocityVerlet, int steps = 10, int repeats = 5);

/// Cloth of 64 x 64 with structural and shear springs, 8 sub-steps per 1/60 s frame:
/// milliseconds per frame (median).
double clothFrameMs(int side = 64, int frames = 30);

/// Everything `artillery bench scaling` measures in one run.
struct ScalingReport {
    std::vector<ScalingPoint> points; ///< every workload's sweep
    PileComparison pile;                 ///< the 2,000 balls (or the --quick size)
    std::vector<PileComparison> piles;   ///< every pile size compared, smallest first
    std::vector<PileComparison> heaps;   ///< the same sizes as staggered heaps
    std::vector<FlightComparison> flights;
    double clothMs = 0;                  ///< clothFrameMs(64)
    double clothLoad = NAN;
    double loadAtStart = NAN;            ///< before anything ran
    std::string machine;                 ///< Machine::describe() of where it ran
    bool underLoad = false;              ///< taken with the load above 1 (--under-load)
};

/// The points as CSV, with the load beside each; `underLoad` marks every row as taken
/// under load (--under-load).
std::string toCsv(const std::vector<ScalingPoint>& points, bool underLoad = false);

} // namespace game::bench
