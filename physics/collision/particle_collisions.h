// The collide and resolve phases of the world step for particles: broad phase over
// the paths of one sub-step, narrow phase to the time of impact, and the response at
// that time, after which the rest of the sub-step follows the bounced path.
//
// One sub-step, after the integrator has moved every particle from S0 to S1:
//   paths    each particle's path over the step, the parabola through S0 and S1
//            (time_of_impact.h); for a particle that nothing touches, S1 stands as it is
//   passes   up to maxPasses times: broad phase on the boxes of the remaining paths,
//            narrow phase to each pair's time of impact, then in time order: move the
//            particles to that time, apply the impulse (equation 4 with the pair's
//            restitution, Coulomb friction), and replace the rest of their path by the
//            one leaving the contact with the new velocity; a pass that resolves
//            nothing ends the loop
//   finish   a particle that was hit takes the end of its new path as its state
//   solve    if the passes ran out, or left resting pairs to it, the contact solver
//            settles the contacts of the end state at once: sequential impulses, then
//            projection, from the ground up (relaxContacts)
// With the integrators exact under constant acceleration, this makes a bounce exact:
// an apex depends on e and H only, not on where the impact fell within the step.
//
// Resting contact (Millington): a contact closing slower than restingSpeed + |a.n| dt
// is resting (for a pair, at least what the forces on both build in a step). It does
// not bounce. On a static shape or an immovable particle the surface then supports the
// particle for the rest of the step: the inward part of its acceleration is removed,
// and if static friction can hold the tangential part (|a_t| <= mu_s |a_n|) the particle
// does not slide. A particle resting on a surface so stays exactly where it is, with no
// jitter and no creep; one resting on two (a notch, a corner) is held by both at once.
// A resting pair of free particles (a stack, a pile) goes to the contact solver, which
// settles a pile in one step where passes would settle it one layer per pass, as does a
// sleeper lying on a free particle (weight that particle carries, not a surface it rests
// on). A particle that spends sleepTime in resting
// contact at a mean velocity below sleepSpeed (it strays less than sleepSpeed *
// sleepTime from where the time started) sleeps (kSleeping) until an impulse, a blast
// or a command wakes it, or what holds it up moves off or goes (held_sleepers.cpp);
// sleepers are immovable to the others.
// Particles tied to springs or constraints do not sleep.
//
// A sub-step works on the active particles only (selectActive): every particle but the
// settled ones, sleepers still as they were when a sub-step last worked on them. A sleeper
// does not move, so its path, boxes and the rest are still what that sub-step made them,
// and a heap whose balls mostly sleep costs its awake balls and their contacts, not its
// size. (A sleeper's state changes only as it wakes: ParticleSet::setPosition and
// setVelocity wake it, as contacts and blasts do.)
//
// The broad phase runs on fattened boxes and its pairs are kept while every particle's
// box stays inside its fat one, so most steps of a resting pile only filter the kept
// pairs by the exact boxes: the same pairs, for a fraction of the cost. A pass after the
// first detects again only what the pass before it changed (later_passes.cpp): the
// paths it changed, and the resting pairs it left to the solver.
#pragma once

#include "physics/collision/broadphase.h"
#include "physics/collision/collision_def.h"
#include "physics/collision/simd/contact_rows.h"
#include "physics/collision/time_of_impact.h"
#include "physics/collision/simd/pair_filter.h"
#include "physics/collision/simd/pair_starts.h"
#include "physics/collision/simd/path_boxes.h"
#include "physics/collision/shapes.h"
#include "physics/collision/time_order.h"
#include "physics/collision/wavefronts.h"
#include "physics/materials.h"
#include "physics/particles.h"
#include "physics/phase_clock.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace phys {

/// One resolved contact, for game events (hits) and diagnostics.
struct ContactEvent {
    ParticleId a = kNoParticle;
    ParticleId b = kNoParticle; ///< the other particle, or kNoParticle for a static shape
    ShapeRef shape;             ///< the static shape when b == kNoParticle
    double time = 0.0;          ///< s since the start of the tick
    Vec2 normal;                ///< unit, from b (or the shape) to a
    double closingSpeed = 0.0;  ///< -(v_a - v_b).n before the impulse, m/s
    double impulse = 0.0;       ///< normal impulse j_n, N s
    bool resting = false;       ///< resting contact (no bounce)
    Vec2 position;              ///< of a at the contact, m
    Vec2 velocity;              ///< of a just after the impulse, m/s
};

/// Per-step statistics.
struct CollisionStats {
    int pairs = 0;        ///< broad-phase pairs tested, summed over passes
    int impacts = 0;      ///< contacts resolved (bounces and resting)
    int passes = 0;       ///< detect-and-resolve passes
    int broadPhases = 0;  ///< broad phases run (the others reused their pairs)
    int cachePatches = 0; ///< passes that mended the kept pairs where a few proxies escaped
    int changesOnly = 0;  ///< passes that detected only what the pass before changed
    int active = 0;       ///< particles the sub-steps worked on (the others were settled)
    int sleeping = 0;     ///< particles asleep after the step
    /// The contact solver's contacts, and the rows its sweeps take for them: one a
    /// contact, plus the padding of the runs of fewer than four in the AVX2 lanes.
    int solverContacts = 0;
    int solverRows = 0;
};

class ParticleCollisions {
  public:
    /// Saves the state the sub-step starts from (call before integrating).
    void beginSubstep(const ParticleSet& set);
    /// Collide and resolve with the impulse model over a sub-step of h seconds that
    /// starts tickTime seconds into the tick (for event times).
    /// `up` is the unit vector against gravity (zero without gravity): what holds what up
    /// in a pile.
    void impulsePhase(ParticleSet& set, const StaticShapes& shapes, const MaterialTable& mats,
                      const CollisionDef& def, double h, double tickTime, Vec2 up = {});
    /// Collide and resolve with the penalty model (overlaps at the end of the step).
    void penaltyPhase(ParticleSet& set, const StaticShapes& shapes, const MaterialTable& mats,
                      const CollisionDef& def, double h, double tickTime);
    /// Puts resting particles to sleep after dt of rest; `tethered[i]` != 0 never sleeps.
    void updateSleep(ParticleSet& set, const CollisionDef& def, double dt,
                     const std::vector<std::uint8_t>& tethered);
    /// In place of updateSleep for a tick without collisions: nothing rested, so nothing
    /// falls asleep and every awake particle's rest timer restarts (done on the next
    /// updateSleep). `asleep` is the number of sleeping particles, for the stats.
    void noContactsThisTick(int asleep) {
        stats_.sleeping = asleep;
        restTimersStale_ = true;
    }

    /// Contacts of the last tick (cleared by clearEvents, which World::step calls).
    const std::vector<ContactEvent>& events() const { return events_; }
    void clearEvents() {
        events_.clear();
        stats_ = {};
    }
    const CollisionStats& stats() const { return stats_; }
    /// Microseconds spent detecting (broad + narrow phase) since construction, a running
    /// total the world differences to split its profile (profile only).
    double detectMicros() const { return detectMicros_; }
    /// Whether detectMicros() is timed (World::setProfiling).
    void setProfiling(bool on) { clock_.on = on; }

  private:
    struct Candidate {
        std::uint32_t a;
        std::uint32_t b; // particle, or kNoParticle for shape
        ShapeRef shape;
        double time;
        std::uint32_t proxy; // b, or slots + the shape's index: the pair order's key
        bool carried;        // a resting pair the last pass left to the solver, found again
    };
    /// The particles this sub-step works on (active_); `all`: every one (the penalty
    /// model, which keeps no settled state).
    void selectActive(const ParticleSet& set, const CollisionDef& def, bool all);
    /// Particle i, settled at the sub-step's start, is worked on from here on.
    void activate(std::size_t i) {
        if (activeMark_[i]) return;
        activeMark_[i] = 1;
        active_.push_back(static_cast<std::uint32_t>(i));
        ++stats_.active;
        touched_[i] = 0; // as buildPaths would have left it
        if (settledFlags_[i] & kAlive) --settledAsleep_;
    }
    /// The solver's boxes of the particles that may be settled in the next sub-step, when
    /// this one ran no solver.
    void boxSettlingForSolver(const ParticleSet& set, const CollisionDef& def);
    void buildPaths(const ParticleSet& set, double h);
    /// Boxes of the paths (or of the end positions), radii grown by `grow` of themselves.
    void buildProxies(const ParticleSet& set, const StaticShapes& shapes, const CollisionDef& def,
                      double h, bool atEndOnly, double grow = 0.0);
    /// Particle i's proxy kind (kinds_[i]), noting whether it changed from the live one.
    ProxyKind setProxyKind(const ParticleSet& set, std::size_t i);
    /// Particle i's proxy: its kind and the box of its path.
    void buildProxy(const ParticleSet& set, const CollisionDef& def, std::size_t i, double h,
                    bool atEndOnly, double grow);
    void findPairs(const ParticleSet& set, const CollisionDef& def, double h);
    enum class CacheState { Holds, Patch, Rebuild };
    CacheState checkPairCache(const CollisionDef& def);
    void buildPairCache(const ParticleSet& set, const CollisionDef& def, double h);
    void patchPairCache(const ParticleSet& set, double h);
    /// Particle i's box grown by kFatBoxPlay radii and a step of its path's motion.
    Aabb fatBox(const ParticleSet& set, std::size_t i, double h) const;
    static constexpr double kFatBoxPlay = 0.5; ///< radii of play in a fat box (fatBox)
    void selectLivePairs();
    /// Pair p can pair with these kinds of the particles (a shape is Resting).
    static bool pairableAs(const std::vector<ProxyKind>& kinds, const ProxyPair& p) {
        const std::size_t n = kinds.size();
        return pairable(kinds[p.first], p.second < n ? kinds[p.second] : ProxyKind::Resting);
    }
    /// A cached pair that the live kinds can make: one of livePairs_.
    bool isLive(const ProxyPair& p) const { return pairableAs(liveKinds_, p); }
    void takeCachedPairsAsLive();
    void detect(const ParticleSet& set, const StaticShapes& shapes, const CollisionDef& def,
                double h);
    /// candidates_: the pairs of pairs_ that meet within the step, in pair order.
    void addCandidates(const ParticleSet& set, const StaticShapes& shapes, const CollisionDef& def,
                       double h);
    /// A pair of the broad phase that meets within the step becomes a candidate.
    void addCandidate(const ParticleSet& set, const StaticShapes& shapes, const CollisionDef& def,
                      ProxyPair pair, double h);
    /// Candidates in the order they are resolved: by time, ties in pair order.
    void orderCandidates();
    /// The detection of a pass after the first from what the last pass changed; false
    /// when a changed particle left what the kept pairs cover (detect runs instead).
    bool detectChanges(const ParticleSet& set, const StaticShapes& shapes, const CollisionDef& def,
                       double h);
    /// pairs_: the changed particles' kept pairs that overlap, in pair order, each once,
    /// by marks in keptMarks_ (no strays); false when the sort is the cheaper way.
    bool markKeptPairs();
    /// detectChanges from pairs_ on: their candidates, those carried, the order.
    bool finishLaterPass(const ParticleSet& set, const StaticShapes& shapes,
                         const CollisionDef& def, double h, PhaseClock::TimePoint t0);
    std::vector<std::uint64_t> keptMarks_; ///< a bit a kept pair (markKeptPairs)
    void indexCachedPairs();
    /// Proxy i's pairs among all proxies and the shapes, by their exact boxes.
    void pairsOfStray(std::uint32_t i);
    /// Kept pair p of changed particle i is one of this pass: live, and its exact boxes
    /// (i's and the other particle's or the shape's) overlap.
    bool keptPairMeets(std::uint32_t i, const ProxyPair& p) const;
    /// Proxies i and j (particles) may pair, by their kinds and exact boxes.
    bool overlapping(std::uint32_t i, std::uint32_t j) const;
    /// A path changed by a contact of this pass: the particle is active, and not settled
    /// in the next sub-step.
    void markChanged(std::size_t i) {
        if (pathChanged_[i] != pass_) changed_.push_back(static_cast<std::uint32_t>(i));
        pathChanged_[i] = pass_;
        activate(i);
        settledFlags_[i] = kUnsettled;
    }
    /// What resolving a candidate did: nothing (no contact any more), a resting contact,
    /// an impact, or nothing yet (a resting pair, left to the contact solver).
    enum class Resolution { None, Resting, Impact, Deferred };
    double restingLimit(std::size_t i, std::size_t j, double an, const CollisionDef& def,
                        double h) const;
    Resolution resolveStatic(const Candidate& c, ParticleSet& set, const StaticShapes& shapes,
                             const MaterialTable& mats, const CollisionDef& def, double h,
                             double tickTime);
    /// `up` as for impulsePhase: a sleeper lying on a free particle goes to the solver.
    Resolution resolvePair(const Candidate& c, ParticleSet& set, const MaterialTable& mats,
                           const CollisionDef& def, double h, double tickTime, Vec2 up);
    /// A sleeping particle that an impulse could wake (not a fixed one).
    static bool asleep(const ParticleSet& set, std::size_t k) {
        return (set.flags[k] & kSleeping) && set.invMass[k] > 0.0;
    }
    /// One of the pair is free (wi, wj: its inverse mass, 0 if immovable) and the other
    /// asleep.
    static bool onSleeper(const ParticleSet& set, std::size_t i, std::size_t j, double wi,
                          double wj) {
        return (wi > 0.0 && asleep(set, j)) || (wj > 0.0 && asleep(set, i));
    }
    void rebase(std::size_t i, double t);
    /// supportAlong, held by the surface that last supported i in this sub-step too
    /// (`surface`: the proxy of what supports it, a particle or slots + a shape's index).
    void support(std::size_t i, Vec2 n, Vec2 vNew, const PairProperties& pp, double remaining,
                 std::uint32_t surface);
    void supportAlong(std::size_t i, Vec2 n, Vec2 vNew, const PairProperties& pp, double remaining);
    struct LastSupport {
        Vec2 normal;
        std::uint32_t surface = 0;
        std::uint64_t substep = 0; ///< substep_ when it supported
    };
    std::vector<LastSupport> lastSupport_;
    std::uint64_t substep_ = 0; ///< counts the impulse sub-steps over the world's life
    void finish(ParticleSet& set, double h);
    void relaxContacts(ParticleSet& set, const StaticShapes& shapes, const MaterialTable& mats,
                       const CollisionDef& def, double h, Vec2 up);
    void orderContactsByLevel();
    bool moving(const ParticleSet& set, std::size_t i) const {
        return set.invMass[i] > 0.0 && (set.flags[i] & (kAlive | kSleeping | kNoCollide)) == kAlive;
    }

    // The active particles of this sub-step (selectActive), marked in activeMark_. A
    // particle's settledFlags_ and settledX_, settledY_, settledRadius_ are its flags and place
    // when a sub-step last worked on it asleep (or on its empty slot), or the flags are
    // kUnsettled: it is settled while its state stays that one bit for bit, at rest, and
    // no contact changes its path.
    struct Place {
        double x, y, radius;
    };
    /// Where each sleeper fell asleep (radius 0: awake since, or never asleep), and the
    /// sleepers that woke or went since the last sub-step.
    std::vector<Place> sleptAt_;
    std::vector<std::uint32_t> wokeOrGone_;
    static constexpr std::uint32_t kUnsettled = 0xffffffffu;
    std::vector<std::uint32_t> active_;
    std::vector<std::uint8_t> activeMark_;
    std::vector<std::uint32_t> settledFlags_;
    std::vector<double> settledX_, settledY_, settledRadius_; ///< the places, by slot
    std::size_t settledAsleep_ = 0; ///< alive particles settled (so asleep) at the start
    double settledTolerance_ = 0.0; ///< what the settled boxes were built with

    // Start of the sub-step (S0).
    std::vector<double> x0_, y0_, vx0_, vy0_;
    // Paths: position, path velocity, path acceleration at t0; state velocity and its
    // rate at t0 (the velocity the integrator reports, which for explicit Euler differs
    // from the path's slope); the path's start time.
    std::vector<PathMotion> path_;
    std::vector<Vec2> sv_, sa_;
    std::vector<std::uint8_t> touched_, resting_;
    std::vector<double> sleepTimer_; ///< s in resting contact within the rest window
    std::vector<Vec2> restAnchor_;   ///< where the rest window started
    bool restTimersStale_ = false;   ///< ticks without contacts passed since updateSleep
    // Broad phase. boxes_: those of the passes, or, while the solver detects, of the
    // solver (its contacts reach kSpeculative further); each keeps a settled particle's.
    std::vector<Aabb> boxes_, solverBoxes_;
    bool kindsChanged_ = true; ///< a kind may differ from liveKinds_ (buildProxy)
    bool kindsRose_ = true;    ///< a kind may pair with more than in liveKinds_
    /// A proxy of kind `now` may pair with more than it could as `before`: it came back
    /// (from None), or it moves again (Resting to Moving). pairable() only loses pairs
    /// otherwise.
    static bool pairsWithMore(ProxyKind now, ProxyKind before) {
        return (before == ProxyKind::None && now != ProxyKind::None) ||
               (before == ProxyKind::Resting && now == ProxyKind::Moving);
    }
    std::vector<ProxyKind> kinds_;
    std::vector<ProxyPair> pairs_;
    std::vector<NearPair> nearPairs_; ///< the solver's pairs near enough to be contacts
    std::vector<PairStart> pairStarts_; ///< what the start of each pair's path tells
    std::vector<std::uint32_t> boxed_;  ///< the active particles with a proxy
    // The pair cache: broad phase over fat boxes (exact box grown by fatBox), kept
    // while every exact box stays inside its fat box and nothing else changes.
    std::vector<Aabb> fatBoxes_;
    std::vector<ProxyKind> fatKinds_;
    std::vector<ProxyPair> cachedPairs_, particlePairs_, staticPairs_;
    // The cached pairs that can pair with the kinds of liveKinds_ (selectLivePairs).
    std::vector<ProxyPair> livePairs_;
    std::vector<ProxyKind> liveKinds_;
    // Proxies that escaped the cache this pass (checkPairCache), at most kMostPatched:
    // more rebuild it.
    static constexpr std::size_t kMostPatched = 64;
    std::vector<std::uint32_t> escaped_;
    std::vector<std::uint8_t> escapedMark_;
    std::vector<ProxyPair> fresh_, mergedPairs_; ///< the escaped proxies' new pairs; scratch
    // The fat boxes in a grid, for the partners of an escaped proxy or a stray: built
    // when first needed after the cache is rebuilt, and again when many have moved.
    BoxQueryGrid fatGrid_;
    bool fatGridStale_ = true;
    static constexpr std::size_t kMostMovedInGrid = 128;
    std::vector<std::uint32_t> near_; ///< a query's answer
    /// The proxies whose fat boxes may overlap `box` (near_), or false: test them all.
    bool nearFatBoxes(const Aabb& box);
    bool cacheValid_ = false;
    std::uint64_t cachedShapes_ = 0;
    BroadPhase cachedBroadPhase_ = BroadPhase::Grid;
    double cachedCellSize_ = 0.0;
    StaticShapeIndex staticIndex_;
    std::vector<std::uint32_t> staticHits_;
    SortAndSweep sweep_;
    UniformGrid grid_;
    std::vector<Candidate> candidates_;
    std::vector<TimeKey> order_;             ///< candidates in the order they are resolved
    std::vector<TimeKey> orderScratch_;      ///< orderByTime's other buffer
    std::uint32_t pass_ = 0;                 ///< counts passes over the world's life
    std::vector<std::uint32_t> pathChanged_; ///< pass_ when a contact last changed the path
    std::vector<std::uint32_t> changed_;     ///< the particles whose paths this pass changed
    std::vector<std::uint8_t> leftToSolver_; ///< per candidate: a resting pair deferred
    std::vector<Candidate> carried_, mergedCandidates_; ///< scratch of detectChanges
    // The cached pairs by particle (offsets into a flat list of their indices), built when
    // a later pass needs them, for the cache of cachedPairsVersion_: once per build or
    // mend of the cache, not each time the live pairs are selected again (as particles
    // fall asleep, once a tick).
    std::vector<std::uint32_t> pairStart_, pairsOf_, pairFill_;
    std::uint64_t cachedPairsVersion_ = 0, indexedVersion_ = ~std::uint64_t{0};
    // Particles a later pass changed beyond what the live pairs cover (their boxes left
    // their fat boxes, or they woke), until the next full detection mends the cache: at
    // most kMostStrays, more run the full detection.
    static constexpr std::size_t kMostStrays = 32;
    std::vector<std::uint32_t> strays_;
    std::vector<std::uint8_t> strayMark_;
    // The end-of-step contact solver (relaxContacts).
    // relaxContacts writes every field where it builds a contact. The constructor leaves
    // them (but shape and normal, whose types set themselves): with one the compiler
    // provides, contacts_.emplace_back() first zeroes the whole contact, 104 bytes (a
    // `rep stos`, a tenth of the contact build's time in a pile).
    struct RelaxContact {
        RelaxContact() {} // NOLINT: deliberately leaves the fields to the builder
        std::uint32_t a;
        std::uint32_t b;     ///< kNoParticle for a static shape
        std::uint32_t proxy; ///< b, or slots + the shape's index
        ShapeRef shape;
        Vec2 normal;                          ///< from b (or the shape) to a
        double depth;                         ///< overlap, m (negative: a gap)
        double closing;                       ///< m/s the gap lets the contact close in a step
        double wa, wb;                        ///< inverse masses, 0 for immovable
        double friction;                      ///< mu_s
        int support;                          ///< 1: b (or the shape) holds a up; -1: a holds b
        double normalImpulse, tangentImpulse; ///< accumulated, N s
    };
    // Sleepers that lose what holds them up wake (held_sleepers.cpp).
    struct Hold {
        std::uint32_t holder, held; ///< an awake particle and the sleeper it holds up
        Vec2 holderAt;              ///< where the holder was when it began to
        std::uint64_t key() const {
            return (std::uint64_t{std::min(holder, held)} << 32) | std::max(holder, held);
        }
    };
    /// The holds of this sub-step's contacts, and those kept from the last sub-step, in
    /// pair order; the sleepers that wake when the tick ends.
    std::vector<Hold> heldNow_, held_, heldOn_;
    std::vector<std::uint32_t> toWake_;
    /// A particle of `radius` at `at` holds sleeper s up: near enough for the solver, and
    /// s above it within kSupport of vertical.
    bool holdsUp(const ParticleSet& set, Vec2 at, double radius, std::uint32_t s,
                 const CollisionDef& def) const;
    /// The hold of a contact of the solver between two particles, one of them immovable
    /// (if it holds a sleeper up), into heldNow_.
    void collectHold(const ParticleSet& set, const RelaxContact& c);
    /// The awake particles that hold up s, which falls asleep now, into held_ (unsorted).
    void holdsOfNewSleeper(const ParticleSet& set, const CollisionDef& def, std::uint32_t s);
    void sortHolds(); ///< held_ in pair order, each pair once
    Vec2 up_;         ///< the up of the last impulse sub-step (holdsUp's)
    /// What the sleepers of wokeOrGone_ held up where they slept, into held_.
    void holdsOfWoken(const ParticleSet& set, const CollisionDef& def);
    /// The holds of now and of before, one list: a sleeper whose holder moved too far or
    /// is gone wakes when the tick ends.
    void wakeWhereHoldersMoved(const ParticleSet& set, const CollisionDef& def);
    /// At the tick's end: toWake_ wake (asleepCount: the sleepers, less those that woke).
    void wakeHeldSleepers(ParticleSet& set, int& asleepCount);
    static constexpr std::uint32_t kUnsupported = 0xffffffffu;
    /// The level of the contact's upper particle (kUnsupported if it has none).
    std::uint32_t bandOf(const RelaxContact& c) const {
        return c.b == kNoParticle ? level_[c.a] : std::max(level_[c.a], level_[c.b]);
    }
    std::vector<RelaxContact> contacts_;
    struct WarmStart {
        std::uint64_t key; ///< a << 32 | proxy
        double normalImpulse, tangentImpulse;
    };
    std::vector<WarmStart> warm_; ///< the contacts at the end of the last sub-step
    std::vector<double> accel0_;  ///< |acceleration| over the sub-step before contacts, m/s^2
    struct Deferred {             ///< a resting pair left to the contact solver this sub-step
        std::uint64_t key;        ///< a << 32 | b
        std::uint32_t order;
        double time, closingSpeed;
        Vec2 normal, position;
    };
    std::vector<Deferred> deferred_;
    void reportDeferred(const ParticleSet& set);
    std::vector<std::uint32_t> contactOrder_, level_, bandStart_;
    // The particles of the solver's contacts (bodies_, marked in bodyMark_): all that its
    // levels and sweeps read or write; bodyIndex_[i]: i's place in bodies_.
    std::vector<std::uint32_t> bodies_, bodyIndex_;
    std::vector<std::uint8_t> bodyMark_;
    bool mostAreBodies(std::size_t slots) const { return 2 * bodies_.size() > slots; }
    void addBody(std::uint32_t i) {
        if (bodyMark_[i]) return;
        bodyMark_[i] = 1;
        bodyIndex_[i] = static_cast<std::uint32_t>(bodies_.size());
        bodies_.push_back(i);
    }
    /// The sweeps over contacts_ (relax_sweeps.cpp): warm start, velocity, position, on
    /// copies of the velocities and positions (copyForSweeps, copyAfterSweeps).
    void sweepContacts(ParticleSet& set, const StaticShapes& shapes, const CollisionDef& def);
    void copyForSweeps(const ParticleSet& set);
    void copyAfterSweeps(ParticleSet& set) const;
    void warmStart();
    void layOutRows(const ParticleSet& set);
    void sweepImpulses(const CollisionDef& def);
    void sweepProjections(const StaticShapes& shapes, const CollisionDef& def);
    /// The inverse masses of contact c under shock propagation in its band: the particle
    /// that holds the other up, if it is settled already (a lower level), is immovable.
    std::pair<double, double> shockMasses(const RelaxContact& c, std::uint32_t band) const {
        double wa = c.wa, wb = c.wb;
        if (c.support == 1 && c.b != kNoParticle && level_[c.b] < band) wb = 0.0;
        if (c.support == -1 && level_[c.a] < band) wa = 0.0;
        return {wa, wb};
    }
    /// The slots of the sweeps' copies past the particles (simd/contact_rows.h): still, at
    /// rest, and sink, which takes the push on an immovable side.
    std::uint32_t stillSlot() const {
        return static_cast<std::uint32_t>(sweepVelocity_.size() - 2);
    }
    std::uint32_t sinkSlot() const { return stillSlot() + 1; }
    bool lanes_ = false; ///< this solve's sweeps run in wavefronts of four lanes
    /// Per band: its sweeps run in lanes (else one row at a time, in its own order).
    std::vector<std::uint8_t> bandLanes_;
    const std::vector<std::uint32_t>&
    keepLanesWhereTheyFill(const std::vector<std::uint32_t>& wavefronts);
    /// A band whose wavefronts take more rows than this a contact is swept one row at a
    /// time (measured on a staggered heap: 1.5 was slower, 3 no faster).
    static constexpr double kMostRowsPerContact = 2.0;
    std::vector<std::uint32_t> mixedOrder_;
    struct SweepRun {
        std::uint32_t from, to;
        bool lanes;
    };
    std::vector<SweepRun> sweepRuns_;
    void joinBandsIntoRuns();
    /// The rows of every sweep, in contactOrder_'s order (in its wavefronts when the lanes
    /// run, with padding rows); each band's from rowStart_[band].
    ContactRows rows_;
    std::vector<std::uint32_t> rowStart_;
    Wavefronts wavefronts_;
    std::vector<Vec2> sweepVelocity_, sweepPosition_; ///< the particles', then still, sink
    /// Sweeps over each band, from the ground up, with the bands below immovable.
    static constexpr int kShockSweeps = 4;
    /// The position sweeps over all contacts go on (up to relaxPositionSweeps) only while
    /// one pushed a pair apart by more than this share of its cap: a tenth of the smaller
    /// radius. One sweep leaves a resting pile's overlaps (about a hundredth of a radius)
    /// to the bands; more would only move its balls about.
    static constexpr double kDeepPush = 0.5;
    /// Contacts up to this gap, in radii (of the pair's sum), are constraints too.
    static constexpr double kSpeculative = 0.1;
    /// A contact holds a particle up when its normal is this close to vertical (cosine).
    static constexpr double kSupport = 0.2;
    /// Gaps below this, in radii, count as touching (no closing allowed).
    static constexpr double kSlop = 1e-3;
    std::vector<std::uint32_t> adjacencyStart_, adjacency_, fill_, frontier_, keyStart_,
        contactKey_;
    /// Who holds whom up among the movable particles, one entry per such contact, in the
    /// contacts' order (the build lists them; the levels read these, not the contacts).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> holds_; ///< holder, held
    std::vector<ContactEvent> events_;
    CollisionStats stats_;
    double detectMicros_ = 0.0;
    PhaseClock clock_;
    ToiSettings toi_;
};

} // namespace phys
