// Where a method fails: the largest stable step of each integrator on an undamped spring
// x'' = -w^2 x, w = sqrt(k/m), from the amplification of one step on the test equation
// y' = i w y (Hairer, Norsett and Wanner, Solving Ordinary Differential Equations I,
// IV.2; for the symplectic family, Hairer, Lubich and Wanner, Geometric Numerical
// Integration, I.5):
//   explicit Euler   |R|^2 = 1 + (w dt)^2 > 1: the energy grows by 1 + (w dt)^2 a step,
//                    unstable at any dt without damping
//   midpoint (RK2)   |R|^2 = 1 + (w dt)^4/4: unstable at any dt, more slowly
//   symplectic Euler, Verlet, velocity Verlet, leapfrog   bounded for w dt < 2
//   RK4              |R|^2 = 1 - (w dt)^6/72 + (w dt)^8/576 <= 1 for w dt <= 2 sqrt 2
//                    (2.828; the 2.785 often quoted is RK4's limit on the negative real
//                    axis, a damper's, not a spring's)
//   implicit Euler   |R| < 1 at any dt
// The guard names this limit when a spring blows up; the Physics panel flags a spring
// past it before it does.
#pragma once

#include "physics/forces.h"
#include "physics/integrators.h"
#include "physics/particles.h"

#include <string>
#include <vector>

namespace phys {

/// Largest stable w dt of an integrator on an undamped spring: 0 for explicit Euler and
/// midpoint, 2 for the symplectic family, 2 sqrt 2 for RK4, infinity for implicit Euler.
double stableOmegaDt(Integrator m);

/// w = sqrt(k / m) of a mass m (kg) on a spring of stiffness k (N/m) to a fixed point.
double springOmega(double stiffness, double mass);

/// The largest step (s) at which `m` keeps that spring bounded: stableOmegaDt / w; 0 when
/// no step is stable (explicit Euler, midpoint), infinity when every one is.
double largestStableStep(Integrator m, double stiffness, double mass);

/// Explicit Euler's energy factor per step on an undamped spring: 1 + (w dt)^2, where the
/// energy is 1/2 m v^2 + 1/2 k x^2.
double explicitEulerEnergyGrowth(double omegaDt);

/// The spring whose w is the highest, with the mass that sets it (the reduced mass of its
/// two ends, or its one end's on an anchor); stiffness 0 when there is none.
struct StiffestSpring {
    double stiffness = 0.0; ///< N/m
    double mass = 0.0;      ///< kg
    double omega = 0.0;     ///< rad/s
};
StiffestSpring stiffestSpring(const std::vector<Spring>& springs, const ParticleSet& particles);

/// What the panel says of a spring of stiffness k on mass m stepped at dt by `method`:
/// "k = 5000 N/m with 1 kg needs dt < 0.028 s with symplectic-euler (now 0.033 s)" past
/// the limit, "... gains energy at any dt with explicit-euler (x1.08 a step)" for the
/// methods stable at none, "" when it is stable.
std::string stiffnessWarning(Integrator method, double stiffness, double mass, double dt);

} // namespace phys
