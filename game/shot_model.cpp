#include "game/shot_model.h"

#include "game/match.h"
#include "physics/integrators.h"
#include "physics/model_pass.h"
#include "physics/projectiles.h"

#include <cmath>

namespace game {

bool flownByClosedForm(const phys::WorldDef& world, const phys::ParticleDef& shell) {
    const phys::ModelRule rule(world.forces, world.model == phys::ModelPolicy::Auto,
                               world.tickSeconds, nullptr);
    const bool fixed = !(shell.mass > 0.0) || std::isinf(shell.mass);
    const std::uint32_t flags = shell.flags | phys::kAlive;
    return !rule.water && phys::closedFormCandidate(rule, flags, fixed ? 0.0 : 1.0 / shell.mass);
}

std::string shotModelName(const phys::WorldDef& world, const phys::ParticleDef& shell) {
    if (flownByClosedForm(world, shell)) return kClosedFormModel;
    return phys::info(world.integrator).name;
}

std::string shotModelName(const Match& match) {
    phys::ParticleDef shell = phys::particleDef(match.selectedAmmo().preset);
    shell.flags |= phys::kProjectile; // as Match::fire gives it
    return shotModelName(match.world().def(), shell);
}

std::string shotModelLabel(const std::string& modelName) {
    struct Label {
        const char* name;
        const char* label;
    };
    static constexpr Label kLabels[] = {
        {kClosedFormModel, "closed form (exact)"},  {"explicit-euler", "explicit Euler"},
        {"symplectic-euler", "symplectic Euler"},    {"verlet", "position Verlet"},
        {"velocity-verlet", "velocity Verlet"},      {"leapfrog", "leapfrog"},
        {"midpoint", "midpoint (RK2)"},              {"rk4", "RK4"},
        {"implicit-euler", "implicit Euler"},
    };
    for (const Label& l : kLabels)
        if (modelName == l.name) return l.label;
    return modelName;
}

} // namespace game
