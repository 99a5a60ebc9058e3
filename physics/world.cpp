#include "physics/world.h"

#include <chrono>
#include <cmath>

namespace phys {

namespace {
using ProfileClock = std::chrono::steady_clock;
double microsSince(ProfileClock::time_point t0) {
    return std::chrono::duration<double, std::micro>(ProfileClock::now() - t0).count();
}
} // namespace

std::string validate(const WorldDef& d) {
    if (!(d.tickSeconds > 0.0) || !(d.tickSeconds <= 1.0))
        return "tick must be in (0, 1] s";
    if (d.substeps < 1 || d.substeps > 1000) return "substeps must be in 1..1000";
    const ForceDef& f = d.forces;
    if (!std::isfinite(f.gravity.x) || !std::isfinite(f.gravity.y))
        return "gravity must be finite";
    if (!(f.airDensity >= 0.0) || !std::isfinite(f.airDensity))
        return "air density must be >= 0 kg/m^3";
    if (!(f.linearDrag >= 0.0) || !std::isfinite(f.linearDrag))
        return "linear drag must be >= 0 kg/s";
    if (!std::isfinite(f.wind.x) || !std::isfinite(f.wind.y)) return "wind must be finite";
    if (!(f.waterDensity >= 0.0) || !std::isfinite(f.waterDensity))
        return "water density must be >= 0 kg/m^3";
    return {};
}

World::World(const WorldDef& def) : def_(def) {}

void World::setDef(const WorldDef& def) {
    if (def.tickSeconds != def_.tickSeconds || def.substeps != def_.substeps ||
        def.integrator != def_.integrator)
        particles.resetHistory();
    def_ = def;
}

void World::step() {
    const auto t0 = ProfileClock::now();
    const double h = def_.tickSeconds / def_.substeps;
    const Dynamics dynamics(def_.forces, springs, particles);

    // 1-2. Forces and integration, per sub-step: the integrator evaluates the force
    // generators at every stage it needs.
    auto t = ProfileClock::now();
    for (int s = 0; s < def_.substeps; ++s)
        integrate(def_.integrator, dynamics, particles, h, scratch_, def_.implicit);
    profile_.integrateUs = microsSince(t);

    // Springs yield and break once per tick, from the state the tick ended in.
    t = ProfileClock::now();
    brokenSprings_ += updateSprings(springs, particles, def_.tickSeconds);
    profile_.springsUs = microsSince(t);

    ++tick_;
    profile_.totalUs = microsSince(t0);
}

std::uint64_t World::hash() const {
    std::uint64_t h = hashBytes(0xcbf29ce484222325ull, &tick_, sizeof tick_);
    return stateHash(particles, h);
}

} // namespace phys
