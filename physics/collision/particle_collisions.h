// The collide and resolve phases of the world step for particles: broad phase over
// the paths of one sub-step, narrow phase to the time of impact, and the response at
// that time, after which the rest of the sub-step follows the bounced path.
//
// One sub-step, after the integrator has moved every particle from S0 to S1:
//   paths    each particle's path over the step, the parabola through S0 and S1
//            (narrowphase.h); for a particle that nothing touches, S1 stands as it is
//   passes   up to maxPasses times: broad phase on the boxes of the remaining paths,
//            narrow phase to each pair's time of impact, then in time order: move the
//            particles to that time, apply the impulse (equation 4 with the pair's
//            restitution, Coulomb friction), and replace the rest of their path by the
//            one leaving the contact with the new velocity; a pass that resolves
//            nothing ends the loop
//   finish   a particle that was hit takes the end of its new path as its state; if
//            the passes ran out before contacts stopped, overlaps left at the end are
//            projected apart
// With the integrators exact under constant acceleration, this makes a bounce exact:
// an apex depends on e and H only, not on where the impact fell within the step.
//
// Resting contact (Millington): a contact closing slower than restingSpeed + |a.n| dt
// is resting. It does not bounce, and for the rest of the step the surface supports the
// particle: the inward part of its acceleration is removed, and if static friction can
// hold the tangential part (|a_t| <= mu_s |a_n|) the particle does not slide. A
// particle resting on a surface so stays exactly where it is, with no jitter and no
// creep; after sleepTime below sleepSpeed it sleeps (kSleeping) until an impulse, a
// blast or a command wakes it. Particles tied to springs or constraints do not sleep.
#pragma once

#include "physics/collision/broadphase.h"
#include "physics/collision/collision_def.h"
#include "physics/collision/narrowphase.h"
#include "physics/collision/shapes.h"
#include "physics/materials.h"
#include "physics/particles.h"

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
    int pairs = 0;    ///< broad-phase pairs, summed over passes
    int impacts = 0;  ///< contacts resolved (bounces and resting)
    int passes = 0;   ///< detect-and-resolve passes
    int sleeping = 0; ///< particles asleep after the step
};

class ParticleCollisions {
  public:
    /// Saves the state the sub-step starts from (call before integrating).
    void beginSubstep(const ParticleSet& set);
    /// Collide and resolve with the impulse model over a sub-step of h seconds that
    /// starts tickTime seconds into the tick (for event times).
    void impulsePhase(ParticleSet& set, const StaticShapes& shapes, const MaterialTable& mats,
                      const CollisionDef& def, double h, double tickTime);
    /// Collide and resolve with the penalty model (overlaps at the end of the step).
    void penaltyPhase(ParticleSet& set, const StaticShapes& shapes, const MaterialTable& mats,
                      const CollisionDef& def, double h, double tickTime);
    /// Puts resting particles to sleep after dt of rest; `tethered[i]` != 0 never sleeps.
    void updateSleep(ParticleSet& set, const CollisionDef& def, double dt,
                     const std::vector<std::uint8_t>& tethered);

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

  private:
    struct Candidate {
        std::uint32_t a;
        std::uint32_t b; // particle, or kNoParticle for shape
        ShapeRef shape;
        double time;
    };
    void buildPaths(const ParticleSet& set, double h);
    void buildProxies(const ParticleSet& set, const StaticShapes& shapes, const CollisionDef& def,
                      double h, bool atEndOnly);
    void findPairs(const CollisionDef& def);
    void detect(const ParticleSet& set, const StaticShapes& shapes, const CollisionDef& def,
                double h);
    bool resolveStatic(const Candidate& c, ParticleSet& set, const StaticShapes& shapes,
                       const MaterialTable& mats, const CollisionDef& def, double h,
                       double tickTime);
    bool resolvePair(const Candidate& c, ParticleSet& set, const MaterialTable& mats,
                     const CollisionDef& def, double h, double tickTime);
    void rebase(std::size_t i, double t);
    void support(std::size_t i, Vec2 n, Vec2 vNew, const PairProperties& pp, double remaining);
    void finish(ParticleSet& set, double h);
    void projectOverlaps(ParticleSet& set, const StaticShapes& shapes, const CollisionDef& def,
                         double h);
    bool moving(const ParticleSet& set, std::size_t i) const {
        return set.invMass[i] > 0.0 && (set.flags[i] & (kAlive | kSleeping | kNoCollide)) == kAlive;
    }

    // Start of the sub-step (S0).
    std::vector<double> x0_, y0_, vx0_, vy0_;
    // Paths: position, path velocity, path acceleration at t0; state velocity and its
    // rate at t0 (the velocity the integrator reports, which for explicit Euler differs
    // from the path's slope); the path's start time.
    std::vector<PathMotion> path_;
    std::vector<Vec2> sv_, sa_;
    std::vector<std::uint8_t> touched_, resting_;
    std::vector<double> sleepTimer_;
    // Broad phase.
    std::vector<Aabb> boxes_;
    std::vector<ProxyKind> kinds_;
    std::vector<ProxyPair> pairs_;
    StaticShapeIndex staticIndex_;
    std::vector<std::uint32_t> staticHits_;
    SortAndSweep sweep_;
    UniformGrid grid_;
    std::vector<Candidate> candidates_;
    std::vector<ContactEvent> events_;
    CollisionStats stats_;
    double detectMicros_ = 0.0;
    ToiSettings toi_;
};

} // namespace phys
