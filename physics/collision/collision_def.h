// Settings of particle collision detection and response, with defaults and units.
// Every feature has a switch so its effect can be seen (as box2d-lite's demo toggles).
#pragma once

#include <string>

namespace phys {

enum class ContactModel {
    Impulse, ///< instantaneous response at the time of impact (contact_impulse.h)
    Penalty, ///< gradual response: a stiff damped spring while overlapping (penalty.h)
    None,    ///< no collisions at all
};

enum class BroadPhase {
    Grid,         ///< uniform grid, O(n) for boxes spread over a level (default)
    SortAndSweep, ///< plane sweep, O(n log n + k); O(n^1.5) over a 2D field
    AllPairs,     ///< every pair, O(n^2): the reference
};

struct CollisionDef {
    ContactModel model = ContactModel::Impulse;
    BroadPhase broadPhase = BroadPhase::Grid;
    double gridCellSize = 0.0; ///< m; 0 = twice the mean size of the moving boxes
    /// The broad phase's kept pairs are mended where a few particles left their fattened
    /// boxes, instead of rebuilt: the same pairs, so the same bits, for less work. Off:
    /// every escape rebuilds them.
    bool patchPairs = true;
    /// Swept-sphere detection with conservative advancement (no tunnelling). Off: the
    /// overlap testing at the end of the step with bisection in time (time_of_impact.h).
    bool continuous = true;
    int bisectionHalvings = 5;     ///< halvings of an overlap bracket, 0..60
    double toiTolerance = 1e-9;    ///< m: a gap this small counts as touching, > 0
    int maxAdvanceIterations = 64; ///< conservative-advancement steps per pair, >= 1
    /// Detect-and-resolve passes per sub-step: each finds the impacts that the previous
    /// pass's bounces lead to later in the same step, >= 1.
    int maxPasses = 8;
    /// A pass after the first detects again only what the pass before it changed (the
    /// paths of the particles it bounced, and the resting pairs it left to the solver):
    /// the same candidates, so the same bits, for the cost of the changes. Off: every
    /// pass detects over every particle.
    bool redetectChangesOnly = true;
    /// A sub-step works only on the active particles: a sleeper still as a sub-step left
    /// it (settled) keeps its path and boxes, and costs nothing but its contacts with the
    /// awake. The same bits, for the cost of the awake particles. Off: every sub-step
    /// works on every particle.
    bool skipSettled = true;
    /// Resting contacts between two free particles (a pile, a stack) go to the contact
    /// solver at the end of the step, which settles them all at once, instead of pass
    /// after pass settling them one layer at a time; so does a sleeper lying on a free
    /// particle (which carries it).
    /// Impacts, and the other resting contacts with static shapes and immovable
    /// particles, stay exact at their time of impact.
    bool restingPairsToSolver = true;
    /// Sweeps of the end-of-step contact solver (sequential impulses, then projection),
    /// which settles the contacts the passes leave: of velocity impulses (>= 1), and the
    /// most of position projection over all contacts (>= 1; after the first, only while a
    /// sweep pushed some pair apart by more than a tenth of a radius).
    int relaxVelocitySweeps = 8;
    int relaxPositionSweeps = 4;
    /// The solver's sweeps take their contacts in wavefronts (contacts sharing no
    /// particle), four at a time where the processor has AVX2: the same bits as one at a
    /// time in their own order, for less time. Off: one at a time in their own order.
    bool contactLanes = true;
    bool particlePairs = true; ///< particles collide with each other, not only with shapes
    /// m/s: a contact closing slower than this plus the speed its acceleration builds in
    /// one step (|a.n| dt, Millington's resting-contact rule) is resting: no bounce,
    /// and the surface supports the particle for the rest of the step.
    double restingSpeed = 0.01;
    bool sleep = true;          ///< resting particles sleep (kSleeping) until woken
    double sleepSpeed = 1e-3;   ///< m/s: a mean velocity below this in resting contact ...
    double sleepTime = 0.5;     ///< s: ... over this long puts a particle to sleep
    double penaltyHertz = 10.0; ///< penalty contact stiffness, cycles per second (k = m (2 pi f)^2)
    int constraintIterations = 4;      ///< most Newton steps of the rod/cable projection, >= 1
    double constraintTolerance = 1e-6; ///< relative length error at which they stop, [0, 1)
};

/// "" when usable, else what is wrong and the allowed range.
std::string validate(const CollisionDef& d);
const char* contactModelName(ContactModel m);
const char* broadPhaseName(BroadPhase b);

} // namespace phys
