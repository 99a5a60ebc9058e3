// Scenes with a known answer, shared by the work-precision benchmark, its tests and the
// in-game Charts panel: each builds a world and measures how wrong its state is.
#pragma once

#include "physics/world.h"

#include <memory>
#include <optional>
#include <span>
#include <string_view>

namespace game::bench {

enum class AccuracyScene {
    ProjectileDrag, ///< one shell with quadratic drag and wind; reference: RK4 at a tiny dt
    Spring,         ///< undamped mass on a spring; reference: the analytic cosine
    Orbit,          ///< two equal bodies on a circular orbit; reference: the analytic circle
    PendulumRods,   ///< a 5-link pendulum of rods; reference: same scene, RK4, 64x finer dt
    Cloth,          ///< 12x12 cloth of springs pinned at two corners; reference: RK4, fine dt
};

struct AccuracySceneInfo {
    AccuracyScene id;
    const char* name;       ///< command-line name
    const char* reference;  ///< what the error is measured against
    double seconds;         ///< simulated time of one run
};

std::span<const AccuracySceneInfo> accuracyScenes();
const AccuracySceneInfo& info(AccuracyScene s);
std::optional<AccuracyScene> accuracySceneFromName(std::string_view name);

/// A world set up for the scene, with the given integrator and dt.
std::unique_ptr<phys::World> makeAccuracyWorld(AccuracyScene s, phys::Integrator m, double dt);

/// Number of steps of length dt that cover the scene's time (dt is snapped by the
/// caller so this is whole: see snapDt).
long stepsFor(AccuracyScene s, double dt);
/// The dt nearest to `dt` that divides the scene's time into a whole number of steps.
double snapDt(AccuracyScene s, double dt);

/// Error of a world that has run the scene to its end, in metres (RMS over particles
/// for many-particle scenes).
double accuracyError(AccuracyScene s, const phys::World& w);

} // namespace game::bench
