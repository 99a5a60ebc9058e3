// What every stage of the collision sub-step reads and reports (particle_collisions.h
// runs the stages): the sub-step's inputs, the contacts it resolved, its statistics, and
// the few rules about particles that every stage applies alike.
#pragma once

#include "physics/collision/collision_def.h"
#include "physics/collision/shapes.h"
#include "physics/materials.h"
#include "physics/particles.h"
#include "physics/phase_clock.h"

#include <bit>
#include <cstdint>
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

/// The wall time spent detecting (broad and narrow phase), a running total the world
/// differences to split its profile; read only while profiling is on.
struct DetectClock {
    PhaseClock clock;
    double micros = 0.0;
};

/// One sub-step as the stages see it: what they work on, with what settings, over which
/// span of the tick, and where they report.
struct Substep {
    ParticleSet& set;
    const StaticShapes& shapes;
    const MaterialTable& mats;
    const CollisionDef& def;
    double h;        ///< s, the sub-step's length
    double tickTime; ///< s into the tick at which the sub-step starts (for event times)
    Vec2 up;         ///< unit, against gravity (zero without gravity): what holds what up
    std::vector<ContactEvent>& events;
    CollisionStats& stats;
    DetectClock& detect;
};

class AwakeSet;
class SubstepPaths;
class Proxies;
class PairCache;
class NarrowPhase;
class Sleep;
class HeldSleepers;

/// The stages of the sub-step (particle_collisions.h), for those that drive or tell others.
struct SubstepStages {
    AwakeSet& awake;
    SubstepPaths& paths;
    Proxies& proxies;
    PairCache& cache;
    NarrowPhase& narrow;
    Sleep& sleep;
    HeldSleepers& held;
};

/// The flags of the multi-step integrators' history: a particle a contact moved
/// restarts them from its new state.
inline constexpr std::uint32_t kHistory = kVerletPrimed | kLeapfrogPrimed;

/// Contacts up to this gap, in radii (of the pair's sum), are constraints of the contact
/// solver too: a gap that may close within one step.
inline constexpr double kSpeculative = 0.1;
/// A contact holds a particle up when its normal is this close to vertical (cosine).
inline constexpr double kSupport = 0.2;

/// Particle i moves under contacts: alive, colliding, awake and of finite mass.
inline bool movable(const ParticleSet& set, std::size_t i) {
    return set.invMass[i] > 0.0 && (set.flags[i] & (kAlive | kSleeping | kNoCollide)) == kAlive;
}

/// A sleeping particle that an impulse could wake (not a fixed one).
inline bool wakeableSleeper(const ParticleSet& set, std::size_t k) {
    return (set.flags[k] & kSleeping) && set.invMass[k] > 0.0;
}

/// Both components +0 (not -0): then v / h is +0 for any h > 0, without dividing.
inline bool isPositiveZero(Vec2 v) {
    return (std::bit_cast<std::uint64_t>(v.x) | std::bit_cast<std::uint64_t>(v.y)) == 0;
}

inline bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// Grows v to n elements; never shrinks it (what lies past a smaller world stays).
template <class T> void growTo(std::vector<T>& v, std::size_t n) {
    if (v.size() < n) v.resize(n);
}

} // namespace phys
