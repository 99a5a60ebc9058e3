// The world: particles, springs and the force model, advanced by World::step in fixed
// ticks. The step reads top to bottom as its phases (DESIGN.md, "Data flow of one
// tick"); each phase is timed into StepProfile.
#pragma once

#include "physics/diagnostics.h"
#include "physics/forces.h"
#include "physics/integrators.h"
#include "physics/particles.h"

#include <cstdint>
#include <string>
#include <vector>

namespace phys {

/// World settings, with defaults and units.
struct WorldDef {
    double tickSeconds = 1.0 / 120.0;  ///< fixed tick, s, > 0
    int substeps = 1;                  ///< integration sub-steps per tick, >= 1
    Integrator integrator = Integrator::VelocityVerlet;
    ForceDef forces;
    ImplicitDef implicit;
};

/// Time spent in each phase of the last step, microseconds (profiling only: the clock is
/// read around phases, never inside the simulation, so results do not depend on it).
struct StepProfile {
    double integrateUs = 0.0;
    double springsUs = 0.0;
    double totalUs = 0.0;
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

    const WorldDef& def() const { return def_; }
    /// Applies new settings from the next tick on. A new dt or integrator invalidates
    /// multi-step history (Verlet, leapfrog), which is re-bootstrapped.
    void setDef(const WorldDef& def);

    std::uint64_t tick() const { return tick_; }
    double time() const { return static_cast<double>(tick_) * def_.tickSeconds; }
    const StepProfile& profile() const { return profile_; }
    std::uint64_t hash() const;
    /// Springs broken since the world was made.
    int brokenSprings() const { return brokenSprings_; }

  private:
    WorldDef def_;
    IntegratorScratch scratch_;
    StepProfile profile_;
    std::uint64_t tick_ = 0;
    int brokenSprings_ = 0;
};

} // namespace phys
