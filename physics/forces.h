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

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
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

/// Submerged depth of a sphere of radius r centred at y below a surface at level.
inline double submergedDepth(double y, double r, double level) {
    return std::clamp(level - (y - r), 0.0, 2.0 * r);
}

/// Volume of a spherical cap of depth h on a sphere of radius r: pi h^2 (3r - h) / 3.
inline double capVolume(double h, double r) {
    return std::numbers::pi * h * h * (3.0 * r - h) / 3.0;
}

/// The per-particle force laws with their parameters resolved, small enough to copy into
/// a kernel's locals: a loop that also writes the state arrays can then keep every
/// parameter in registers (the compiler cannot assume a store to vx[i] leaves a
/// ForceDef field unchanged, so through a reference it would reload them all).
struct LocalForceLaw {
    DragModel drag = DragModel::None;
    double linearDrag = 0.0;
    double halfRhoPi = 0.0;        ///< 1/2 rho_air pi
    double windX = 0.0, windY = 0.0;
    bool water = false;
    double waterLevel = 0.0, waterDensity = 0.0, halfRhoWaterPi = 0.0;
    double g = 0.0, upX = 0.0, upY = 1.0; ///< |gravity| and the unit vector against it

    explicit LocalForceLaw(const ForceDef& d)
        : drag(d.drag), linearDrag(d.linearDrag),
          halfRhoPi(0.5 * d.airDensity * std::numbers::pi), windX(d.wind.x), windY(d.wind.y),
          water(d.water), waterLevel(d.waterLevel), waterDensity(d.waterDensity),
          halfRhoWaterPi(0.5 * d.waterDensity * std::numbers::pi), g(length(d.gravity)) {
        if (g > 0.0) {
            upX = -d.gravity.x / g;
            upY = -d.gravity.y / g;
        }
    }

    /// Drag relative to the wind, buoyancy and water drag on one particle. Newtons.
    Vec2 force(std::uint32_t flags, double r, double cd, double y, double vx, double vy) const {
        Vec2 f;
        if (!(flags & kNoDrag)) {
            const double ux = vx - windX, uy = vy - windY;
            if (drag == DragModel::Linear) {
                f.x -= linearDrag * ux;
                f.y -= linearDrag * uy;
            } else if (drag == DragModel::Quadratic) {
                // F = -1/2 rho Cd A |u| u with u = v - wind, A = pi r^2.
                const double k = halfRhoPi * cd * r * r * std::sqrt(ux * ux + uy * uy);
                f.x -= k * ux;
                f.y -= k * uy;
            }
        }
        // Buoyancy (Archimedes: rho_w V_submerged |g|, against gravity) and water drag
        // on the submerged fraction of each particle, which is treated as a sphere.
        if (water && (flags & kAlive)) {
            const double h = submergedDepth(y, r, waterLevel);
            if (h > 0.0) {
                const double lift = waterDensity * capVolume(h, r) * g;
                f.x += lift * upX;
                f.y += lift * upY;
                const double k = halfRhoWaterPi * cd * r * r * (h / (2.0 * r)) *
                                 std::sqrt(vx * vx + vy * vy);
                f.x -= k * vx;
                f.y -= k * vy;
            }
        }
        return f;
    }
};

/// The unbroken springs as the force loop reads them, in their order: the two ends and
/// the three coefficients, 32 bytes a spring instead of a Spring's 80, so that a cloth's
/// springs stay in cache across the sub-steps of a tick. The world builds it once per
/// tick (springs break and yield only between ticks).
struct SpringTerms {
    struct Term {
        ParticleId a = kNoParticle;
        ParticleId b = kNoParticle; ///< kNoParticle: to anchors[k]
        double restLength = 0.0, stiffness = 0.0, damping = 0.0;
    };
    std::vector<Term> terms;
    std::vector<Vec2> anchors; ///< anchors[k] for a term k that ends at an anchor; else unset
    /// Rebuilds from `springs` (keeps its buffers).
    void build(const std::vector<Spring>& springs);
};

/// The right-hand side of the equations of motion for a particle set: given a trial
/// state, the acceleration of every slot. Fixed, dead and sleeping slots get 0.
class Dynamics {
  public:
    /// `terms`, when given, is SpringTerms built from `springs`, which the force loop then
    /// reads instead (same forces, same bits).
    Dynamics(const ForceDef& def, const std::vector<Spring>& springs, const ParticleSet& set,
             const SpringTerms* terms = nullptr);

    /// a = g + F/m for every slot, at state (px, py, vx, vy).
    void accelerations(const double* px, const double* py, const double* vx, const double* vy,
                       double* ax, double* ay) const;

    /// Every force except uniform gravity, in newtons (for the implicit solver).
    void nonGravityForces(const double* px, const double* py, const double* vx,
                          const double* vy, double* fx, double* fy) const;

    /// df = dF/dx . w + dF/dv . u (force Jacobian times a direction), for the implicit
    /// solver. Springs, drag, point gravity and buoyancy are differentiated exactly, except
    /// that the transverse spring term is clamped at zero under compression, which keeps
    /// the system positive definite (Baraff & Witkin 1998), and the water drag's
    /// dependence on depth is left out.
    void forceJacobianProduct(const double* px, const double* py, const double* vx,
                              const double* vy, const double* wx, const double* wy,
                              const double* ux, const double* uy, double* dfx,
                              double* dfy) const;

    /// Forces that act on particle i alone, at the given state: drag relative to the
    /// wind, buoyancy and water drag. Newtons.
    Vec2 localForce(std::size_t i, double x, double y, double vx, double vy) const;

    /// True when every force is local (no springs, no point gravity), so a particle's
    /// acceleration depends on its own state only and integrators may fuse force
    /// evaluation into their update loop (one pass over memory instead of three).
    bool onlyLocalForces() const { return springs_.empty() && !def_.pointGravity; }

    /// a = g + F/m for an active particle, 0 otherwise. Gravity is added as an
    /// acceleration, not as m g / m, so that under gravity alone the integrators see g
    /// to the last bit (the closed form's g).
    Vec2 accelerationFrom(std::size_t i, Vec2 force) const {
        if (!active(i)) return {};
        const double im = set_.invMass[i];
        if (set_.flags[i] & kNoGravity) return {im * force.x, im * force.y};
        return {def_.gravity.x + im * force.x, def_.gravity.y + im * force.y};
    }

    /// True when the particle is moved by forces (alive, not fixed, not asleep, not on
    /// the closed form).
    bool active(std::size_t i) const {
        return set_.invMass[i] > 0.0 &&
               (set_.flags[i] & (kAlive | kSleeping | kBallistic)) == kAlive;
    }
    /// Gravity acting on slot i (0 for inactive or kNoGravity particles).
    Vec2 gravityOn(std::size_t i) const;

    const ForceDef& def() const { return def_; }
    const ParticleSet& set() const { return set_; }
    const LocalForceLaw& localLaw() const { return local_; }
    const std::vector<Spring>& springs() const { return springs_; }

  private:
    void springForces(const double* px, const double* py, const double* vx, const double* vy,
                      double* fx, double* fy) const;
    /// The arguments of forceJacobianProduct, for its terms.
    struct JacobianTerms {
        const double *px, *py, *vx, *vy, *wx, *wy, *ux, *uy;
        double *dfx, *dfy;
    };
    void dragJacobian(const JacobianTerms& d) const;
    void springJacobian(const JacobianTerms& d) const;
    void pointGravityJacobian(const JacobianTerms& d) const;
    void waterJacobian(const JacobianTerms& d) const;
    const ForceDef& def_;
    const std::vector<Spring>& springs_;
    const SpringTerms* terms_;
    const ParticleSet& set_;
    LocalForceLaw local_;
};

inline Vec2 Dynamics::localForce(std::size_t i, double, double y, double vx, double vy) const {
    return local_.force(set_.flags[i], set_.radius[i], set_.dragCd[i], y, vx, vy);
}

} // namespace phys
