// The integrators: each a named function of the state vector S = <p, v>, with
// dS/dt = <v, F/m> evaluated by a Dynamics at every stage the method needs.
//
//   name               order  force evaluations per step   notes
//   explicit-euler     1      1                             energy grows by 1+(w dt)^2 per step
//   symplectic-euler   1      1                             a.k.a. Euler-Cromer; stable for w dt < 2
//   verlet             1*     1                             position Verlet, Euler bootstrap
//   velocity-verlet    2      2                             exact under constant acceleration
//   leapfrog           2      1                             staggered half-step velocities
//   midpoint           2      2                             RK2
//   rk4                4      4                             stable for w dt < 2 sqrt(2)
//   implicit-euler     1      2 + CG iterations             backward Euler, stable at any dt
//
// * the recursion is order 2; the Euler bootstrap of Rabin's "Real-time Game Physics"
//   (Introduction to Game Development, 4.3) makes the result order 1.
//
// Toggling the integrator is a value (Integrator), not a subclass.
#pragma once

#include "physics/forces.h"
#include "physics/particles.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace phys {

enum class Integrator {
    ExplicitEuler,
    SymplecticEuler,
    Verlet,
    VelocityVerlet,
    Leapfrog,
    Midpoint,
    RK4,
    ImplicitEuler,
};

struct IntegratorInfo {
    Integrator id;
    const char* name;    ///< canonical command-line name
    const char* alias;   ///< other accepted name, or nullptr
    int order;           ///< global order of accuracy in dt
    int evaluations;     ///< force evaluations per step (implicit: plus solver iterations)
    bool exactUnderConstantAcceleration; ///< reproduces p0 + v0 t + g t^2/2 exactly
    const char* summary;
};

/// Every integrator, in order from simplest to most elaborate.
std::span<const IntegratorInfo> integrators();
const IntegratorInfo& info(Integrator id);
/// Parses a name or alias ("euler-cromer"); nullopt when unknown.
std::optional<Integrator> integratorFromName(std::string_view name);
/// "explicit-euler, symplectic-euler (euler-cromer), ..." for error messages and --help.
std::string integratorNameList();

/// Settings of the implicit solver.
struct ImplicitDef {
    int maxIterations = 200;  ///< conjugate-gradient iterations per step
    double tolerance = 1e-12; ///< relative residual at which CG stops
};

/// Buffers the integrators reuse between steps (no allocation per step once sized).
struct IntegratorScratch {
    std::vector<double> ax, ay, bx, by, cx, cy, dx, dy;  // stage accelerations
    std::vector<double> tpx, tpy, tvx, tvy;              // trial state
    std::vector<double> rx, ry, qx, qy, sx, sy, zx, zy;  // implicit solver vectors
    int lastSolverIterations = 0;
    void resize(std::size_t n);
};

/// Advances every active particle by dt with the chosen integrator.
void integrate(Integrator method, const Dynamics& dyn, ParticleSet& set, double dt,
               IntegratorScratch& scratch, const ImplicitDef& implicit = {});

} // namespace phys
