// The world: particles, springs, rods and cables, static shapes, materials and the force
// model, advanced by World::step in fixed ticks. The step reads top to bottom as its
// phases (docs/architecture.md, "One tick"): per sub-step integrate, collide, resolve,
// constraints; per tick sleep and springs. Each phase is timed into StepProfile.
#pragma once

#include "physics/collision/collision_def.h"
#include "physics/constraints/rods_and_cables.h"
#include "physics/collision/particle_collisions.h"
#include "physics/collision/shapes.h"
#include "physics/diagnostics.h"
#include "physics/forces.h"
#include "physics/integrators.h"
#include "physics/materials.h"
#include "physics/model_pass.h"
#include "physics/particles.h"
#include "physics/phase_clock.h"

#include <cstdint>
#include <string>
#include <vector>

namespace phys {

/// How particles are moved: model no more than a scene needs.
enum class ModelPolicy {
    /// A particle that only uniform gravity acts on follows the closed form (exact at any
    /// dt, O(1)); drag, wind, water, springs, rods or point gravity hand it to the
    /// integrator, at the moment the condition changes, from its exact state.
    Auto,
    /// Every particle goes through the selected integrator, so the integrator toggle
    /// shows its effect even where the closed form would be exact.
    Integrate,
};
const char* modelPolicyName(ModelPolicy p);

/// World settings, with defaults and units.
struct WorldDef {
    ModelPolicy model = ModelPolicy::Auto;
    double tickSeconds = 1.0 / 120.0;  ///< fixed tick, s, > 0
    int substeps = 1;                  ///< integration sub-steps per tick, >= 1
    Integrator integrator = Integrator::VelocityVerlet;
    ForceDef forces;
    ImplicitDef implicit;
    CollisionDef collision; ///< contact model, continuous detection, resting, sleep, constraints
};

/// Time spent in each phase of the last step, microseconds (profiling only: the clock is
/// read around phases, never inside the simulation, so results do not depend on it).
struct StepProfile {
    double integrateUs = 0.0;   ///< forces and integration
    double collideUs = 0.0;     ///< broad phase, narrow phase, time of impact
    double resolveUs = 0.0;     ///< impulses, friction, resting contact, penalty, sleep
    double constraintsUs = 0.0; ///< rods and cables
    double springsUs = 0.0;     ///< plastic flow and breaking
    double totalUs = 0.0;
    // Which model each alive particle was in during the tick.
    int closedForm = 0; ///< on the closed form (kBallistic)
    int integrated = 0; ///< moved by the integrator
    int sleeping = 0;   ///< asleep: costs next to nothing
    int fixed = 0;      ///< infinite mass (anchors, pins)
};

/// Returns "" when the definition is usable, else what is wrong and the allowed range.
std::string validate(const WorldDef& def);

class World {
  public:
    explicit World(const WorldDef& def = {});

    /// Advances one tick of def().tickSeconds in def().substeps sub-steps.
    void step();

    ParticleSet particles;
    std::vector<Spring> springs;
    std::vector<DistanceConstraint> constraints; ///< rods and cables
    StaticShapes shapes;                         ///< terrain, walls, obstacles
    MaterialTable materials;

    const WorldDef& def() const { return def_; }
    /// Applies new settings from the next tick on. A new dt or integrator invalidates
    /// multi-step history (Verlet, leapfrog), which is re-bootstrapped.
    void setDef(const WorldDef& def);

    std::uint64_t tick() const { return tick_; }
    /// Simulated time, s: the sum of the ticks so far (the tick length may change).
    double time() const { return time_; }
    const StepProfile& profile() const { return profile_; }
    /// Whether step() times its phases into profile() (on by default). A world stepped
    /// many times for a look ahead turns it off; the results are the same either way.
    void setProfiling(bool on);
    std::uint64_t hash() const;
    /// Springs broken since the world was made.
    int brokenSprings() const { return brokenSprings_; }
    /// Contacts resolved during the last tick (hits for the game, bounces for tests).
    const std::vector<ContactEvent>& contacts() const { return collisions_.events(); }
    const CollisionStats& collisionStats() const { return collisions_.stats(); }
    /// Wakes every sleeping particle. Call after editing `shapes` (a crater in the
    /// terrain): a sleeper does not notice that its support has gone.
    void wakeAll();
    /// Largest relative length error of a rod or cable after the last tick.
    double constraintError() const { return constraintError_; }

  private:
    WorldDef def_;
    /// How this tick runs: with collisions; through the fused flight sweep, and which.
    struct TickPlan {
        bool colliding = false, fused = false;
        FlightScheme scheme = FlightScheme::VelocityVerlet;
    };
    TickPlan planTick(const Dynamics& dynamics) const;
    void substep(int s, const Dynamics& dynamics, const ModelRule& rule, const TickPlan& plan,
                 ModelCounts& counts);
    void collideAndResolve(double h, double tickTime);
    void markTethered();
    ModelCounts chooseModels(const ModelRule& rule);
    ModelCounts countModels() const;
    void launchBallistic(double now);
    void advanceBallistic(double now);
    IntegratorScratch scratch_;
    SpringTerms springTerms_; ///< the springs as the force loop reads them, this tick
    ParticleCollisions collisions_;
    ConstraintScratch constraintScratch_;
    std::vector<std::uint8_t> tethered_; ///< per slot; empty when no spring or rod exists
    double constraintError_ = 0.0;
    StepProfile profile_;
    PhaseClock clock_;
    std::uint64_t tick_ = 0;
    double time_ = 0.0;
    int brokenSprings_ = 0;
};

} // namespace phys
