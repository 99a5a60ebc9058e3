// Force generators over the whole particle set, and the right-hand side of the
// equations of motion dS/dt = <v, F/m> that every integrator evaluates.
//
// Every generator is a pure function of the state it is handed (positions and
// velocities may be a multi-stage method's trial state), so the integrators can
// re-evaluate forces at each stage. What must happen once per step (plastic flow,
// breaking springs) lives in updateSprings(), which the world calls after the step.
#pragma once

#include "physics/particles.h"
#include "physics/vec2.h"

#include <limits>
#include <string_view>
#include <optional>
#include <vector>

namespace phys {

/// Standard gravity presets (m/s^2, magnitude; gravity points down, -y).
struct GravityPreset {
    const char* name;
    double g;
};
inline constexpr GravityPreset kGravityPresets[] = {
    {"earth", 9.81}, {"moon", 1.62}, {"mars", 3.71}, {"jupiter", 24.79}};
std::optional<double> gravityFromPlanet(std::string_view name);

/// Sea-level air density, kg/m^3 (ISA, 15 degC).
inline constexpr double kAirDensitySeaLevel = 1.225;
/// Fresh water density, kg/m^3.
inline constexpr double kWaterDensity = 1000.0;

enum class DragModel {
    None,      ///< no air resistance
    Linear,    ///< F = -b (v - w): Stokes-like, b = linearDrag
    Quadratic, ///< F = -1/2 rho Cd A |v - w| (v - w), A = pi r^2
};

/// Global force settings, with defaults and units.
struct ForceDef {
    Vec2 gravity{0.0, -9.81};              ///< uniform gravity, m/s^2
    DragModel drag = DragModel::None;      ///< air drag law
    double airDensity = kAirDensitySeaLevel; ///< rho, kg/m^3 (quadratic drag)
    double linearDrag = 0.0;               ///< b, kg/s, per particle (linear drag)
    Vec2 wind{0.0, 0.0};                   ///< velocity of the air, m/s; drag acts on v - wind
    bool pointGravity = false;             ///< inverse-square gravity between kAttractor particles
    double gravitationalConstant = 6.674e-11; ///< G, N m^2/kg^2 (scenes may scale it up)
    double pointGravitySoftening = 0.01;   ///< epsilon, m: F = G m1 m2 / (r^2 + eps^2)
    bool water = false;                    ///< buoyancy and water drag below waterLevel
    double waterLevel = 0.0;               ///< y of the water surface, m
    double waterDensity = kWaterDensity;   ///< kg/m^3
};

/// A damped Hooke spring between two particles, or from a particle to a fixed anchor.
/// F_a = -(k (L - L0) + c (v_a - v_b).n) n, n = (p_a - p_b)/L; F_b = -F_a.
struct Spring {
    ParticleId a = kNoParticle;
    ParticleId b = kNoParticle;  ///< kNoParticle: the spring ends at `anchor`
    Vec2 anchor;                 ///< m, used when b == kNoParticle
    double restLength = 1.0;     ///< L0, m
    double stiffness = 100.0;    ///< k, N/m
    double damping = 0.0;        ///< c, N s/m, along the spring
    /// Plastic flow: past this strain |L - L0|/L0 the rest length creeps toward the
    /// current length at plasticRate (1/s). Infinity = perfectly elastic.
    double yieldStrain = std::numeric_limits<double>::infinity();
    double plasticRate = 0.0;    ///< 1/s
    /// The spring breaks (stops acting) past this strain. Infinity = unbreakable.
    double breakStrain = std::numeric_limits<double>::infinity();
    bool broken = false;
};

/// Radial blast: an instantaneous impulse J(d) = J0 (1 - d/R) away from the centre for
/// d < R (linear falloff), applied as dv = J / m. Returns the number of particles pushed.
struct Blast {
    Vec2 center;          ///< m
    double impulse = 0.0; ///< J0, N s at the centre
    double radius = 1.0;  ///< R, m
};
int applyBlast(ParticleSet& set, const Blast& blast);

/// Applies plastic flow and breaking to every spring, once per step of length dt.
/// Returns how many springs broke.
int updateSprings(std::vector<Spring>& springs, const ParticleSet& set, double dt);

/// The right-hand side of the equations of motion for a particle set: given a trial
/// state, the acceleration of every slot. Fixed, dead and sleeping slots get 0.
class Dynamics {
  public:
    Dynamics(const ForceDef& def, const std::vector<Spring>& springs, const ParticleSet& set)
        : def_(def), springs_(springs), set_(set) {}

    /// a = g + F/m for every slot, at state (px, py, vx, vy).
    void accelerations(const double* px, const double* py, const double* vx, const double* vy,
                       double* ax, double* ay) const;

    /// Every force except uniform gravity, in newtons (for the implicit solver).
    void nonGravityForces(const double* px, const double* py, const double* vx,
                          const double* vy, double* fx, double* fy) const;

    /// df = dF/dx . w + dF/dv . u (force Jacobian times a direction), for the implicit
    /// solver. Springs and drag are differentiated exactly (the transverse spring term is
    /// clamped at zero under compression, which keeps the system positive definite, as in
    /// Baraff & Witkin 1998); point gravity and buoyancy are treated explicitly.
    void forceJacobianProduct(const double* px, const double* py, const double* vx,
                              const double* vy, const double* wx, const double* wy,
                              const double* ux, const double* uy, double* dfx,
                              double* dfy) const;

    /// True when the particle is moved by forces (alive, not fixed, not asleep).
    bool active(std::size_t i) const {
        return set_.invMass[i] > 0.0 && (set_.flags[i] & (kAlive | kSleeping)) == kAlive;
    }
    /// Gravity acting on slot i (0 for inactive or kNoGravity particles).
    Vec2 gravityOn(std::size_t i) const;

    const ForceDef& def() const { return def_; }
    const ParticleSet& set() const { return set_; }
    const std::vector<Spring>& springs() const { return springs_; }

  private:
    const ForceDef& def_;
    const std::vector<Spring>& springs_;
    const ParticleSet& set_;
};

} // namespace phys
