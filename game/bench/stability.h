// Where each method fails: the largest stable w dt on an undamped spring (by an energy
// growth criterion) and the stiffest spring a hanging rope survives at the game's tick.
#pragma once

#include "physics/integrators.h"

#include <functional>
#include <string>
#include <vector>

namespace game::bench {

/// Energy growth of the undamped unit spring over at least `minSteps` steps and 20
/// periods at w dt: the ratio of
/// the mean energy in the second half of the run to the mean in the first half. A
/// stable method stays at (or below) 1; an unstable one grows as |lambda|^steps.
double energyGrowth(phys::Integrator m, double omegaDt, int minSteps = 4000);

/// Unstable when energyGrowth exceeds this. The mean of a stable method's oscillating
/// energy settles to within 0.2 % over 20 periods (measured on a dense scan of w dt for
/// the symplectic family and RK4), while explicit Euler at w dt = 1e-3 already grows 6 %.
inline constexpr double kGrowthTolerance = 1.003;

/// Search range of w dt.
inline constexpr double kMinOmegaDt = 1e-3, kMaxOmegaDt = 1e3;

/// Largest stable w dt found by bisection (to 1e-4 relative): 0 when the method is
/// unstable already at kMinOmegaDt, infinity when it is stable up to kMaxOmegaDt.
double maxStableOmegaDt(phys::Integrator m);

struct RopeDef {
    int particles = 20;            ///< links of the rope
    double linkLength = 0.1;       ///< m
    double particleMass = 0.1;     ///< kg
    double tickSeconds = 1.0 / 120.0; ///< the game's tick
    double seconds = 2.0;          ///< simulated time of each trial
};

/// True when a rope of springs of stiffness k (N/m), released horizontal from an anchor,
/// swings for def.seconds without any particle exceeding 100 m/s or becoming non-finite.
bool ropeSurvives(phys::Integrator m, double stiffness, const RopeDef& def = {});

/// Stiffest spring (N/m, bisection on log k between 1 and 1e12) the rope survives;
/// 0 when not even k = 1 survives, infinity when even 1e12 does.
double stiffestRopeSpring(phys::Integrator m, const RopeDef& def = {});

struct StabilityRow {
    phys::Integrator integrator;
    double maxOmegaDt;      ///< see maxStableOmegaDt
    double theoryOmegaDt;   ///< what theory says (0: unstable at any dt; inf: never unstable)
    double ropeStiffness;   ///< N/m, see stiffestRopeSpring
};

/// Theory's limit for the undamped spring: 0 for explicit Euler (|lambda|^2 = 1 + (w dt)^2)
/// and midpoint (1 + (w dt)^4 / 4), 2 for the symplectic family, 2 sqrt 2 for RK4,
/// infinity for implicit Euler.
double theoreticalOmegaDt(phys::Integrator m);

std::vector<StabilityRow> runStability(const std::function<void(int, int)>& progress = {},
                                       const RopeDef& rope = {});

/// Energy growth of one integrator across a sweep of w dt: the curve the stability chart
/// draws, so it shows where (and how violently) each method fails.
struct GrowthCurve {
    phys::Integrator integrator;
    std::vector<double> omegaDt; ///< rad (w dt is dimensionless)
    std::vector<double> growth;  ///< energyGrowth at each w dt (may be infinite)
};

/// `samples` values of w dt spaced evenly in log between lo and hi, for every integrator.
std::vector<GrowthCurve> energyGrowthCurves(double lo, double hi, int samples,
                                            const std::function<void(int, int)>& progress = {});

/// CSV: integrator,max_omega_dt,theory_omega_dt,rope_max_stiffness_n_per_m
std::string toCsv(const std::vector<StabilityRow>& rows);

} // namespace game::bench
