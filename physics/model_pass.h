// The model pass: which model moves each particle this tick (model no more than a scene
// needs), the closed form's launch and advance, and the count of each model,
// per particle so that the world can run them fused with the integrator in one sweep.
//
// The same sweep fuses velocity Verlet (the game's default integrator) the same way.
//
// A million shells in flight under drag is a streaming problem: the step costs what it
// takes to read and write the state arrays once. Separate sweeps to choose models, to
// (re)launch and advance the closed form, to integrate and to count would each read the
// flags again; symplecticFlightPass() does all of it in one. It is the symplectic Euler
// step with local forces (Integrator::SymplecticEuler, Dynamics::onlyLocalForces), bit for
// bit the same as integrate() (tests/physics/model_pass_test.cpp compares them), four
// particles at a time where the processor has AVX2, else two with SSE2 (sqrt and the IEEE
// operations give the same bits in any width).
#pragma once

#include "physics/forces.h"
#include "physics/particles.h"

#include <cstdint>

namespace phys {

/// How many alive particles are in each model (StepProfile), counted as the world reports
/// them: fixed first, then asleep, then on the closed form, the rest integrated.
struct ModelCounts {
    int closedForm = 0; ///< kBallistic
    int integrated = 0;
    int sleeping = 0; ///< asleep with finite mass
    int fixed = 0;    ///< infinite mass
    int asleep = 0;   ///< every alive particle with kSleeping, fixed ones included
};

/// The model rule (World, ModelPolicy) resolved for a sweep: a particle follows the closed
/// form when it is alive, free, awake, has gravity, and nothing but gravity reaches it.
struct ModelRule {
    bool closedFormAllowed = true; ///< ModelPolicy::Auto
    /// Closed form needs (flags & mask) == expect (alive, awake, with gravity, and with
    /// kNoDrag when there is air drag, without kAttractor under point gravity).
    std::uint32_t mask = 0, expect = 0;
    const std::uint8_t* tethered = nullptr; ///< nonzero: on a spring or rod; null: none are
    bool water = false;                     ///< the particle must stay clear of the water all tick
    double waterLevel = 0.0;                ///< m
    double gravity = 0.0;                   ///< |g|, m/s^2
    double tickSeconds = 0.0;

    ModelRule(const ForceDef& forces, bool closedFormAllowed, double tickSeconds,
              const std::uint8_t* tethered);
};

/// Whether a particle with these flags and inverse mass may follow the closed form, as far
/// as its flags and mass say (the tether and the water are checked by chooseModel). The
/// game asks it of a shell before it is fired, to name the model that will fly it.
inline bool closedFormCandidate(const ModelRule& r, std::uint32_t flags, double invMass) {
    return r.closedFormAllowed && (flags & r.mask) == r.expect && invMass > 0.0;
}

/// Applies the rule to particle i: sets kBallistic (launch pending) or hands it to the
/// integrator (clearing kBallistic and multi-step history). Returns its new flags.
std::uint32_t chooseModel(ParticleSet& s, std::size_t i, const ModelRule& rule);

/// Adds particle i (flags f) to the counts.
inline void countModel(ModelCounts& c, std::uint32_t f, double invMass) {
    if (!(f & kAlive)) return;
    c.asleep += (f & kSleeping) ? 1 : 0;
    if (invMass <= 0.0)
        ++c.fixed;
    else if (f & kSleeping)
        ++c.sleeping;
    else if (f & kBallistic)
        ++c.closedForm;
    else
        ++c.integrated;
}

/// A kBallistic particle whose state is off its parabola (new, bounced, pushed) is
/// relaunched from where it is at world time `now`.
void launchBallistic(ParticleSet& s, std::size_t i, Vec2 gravity, double now);
/// Sets a kBallistic particle to its closed form at world time `now`: exact at any step.
void advanceBallistic(ParticleSet& s, std::size_t i, Vec2 gravity, double now);

/// Symplectic Euler for particle i (flags f) under local forces:
///   v' = v + h (g + F(p, v)/m),  p' = p + h v'
/// A particle that takes no forces (fixed, asleep, dead) keeps its velocity and drifts.
/// integrate(SymplecticEuler) and the flight pass both step a particle through this.
inline void symplecticLocalStep(ParticleSet& s, std::size_t i, std::uint32_t f,
                                const LocalForceLaw& law, Vec2 g, double h) {
    const double im = s.invMass[i];
    if (im > 0.0 && (f & (kAlive | kSleeping)) == kAlive) {
        const Vec2 force = law.force(f, s.radius[i], s.dragCd[i], s.py[i], s.vx[i], s.vy[i]);
        const double gx = (f & kNoGravity) ? 0.0 : g.x, gy = (f & kNoGravity) ? 0.0 : g.y;
        s.vx[i] += h * (gx + im * force.x);
        s.vy[i] += h * (gy + im * force.y);
    }
    s.px[i] += h * s.vx[i];
    s.py[i] += h * s.vy[i];
}

/// Velocity Verlet for particle i (flags f) under local forces, the same operations in the
/// same order as integrate(VelocityVerlet) makes them in its separate sweeps:
///   a = g + F(p, v)/m,  p' = p + (h v + h^2/2 a),  v~ = v + h a,
///   b = g + F(p', v~)/m,  v' = v + h/2 (a + b)
/// with a = b = 0 for a particle that takes no forces (fixed, asleep, dead).
inline void velocityVerletLocalStep(ParticleSet& s, std::size_t i, std::uint32_t f,
                                    const LocalForceLaw& law, Vec2 g, double h) {
    const double im = s.invMass[i];
    const bool active = im > 0.0 && (f & (kAlive | kSleeping | kBallistic)) == kAlive;
    const bool gravity = !(f & kNoGravity);
    const double r = s.radius[i], cd = s.dragCd[i];
    const double vx = s.vx[i], vy = s.vy[i];
    double ax = 0.0, ay = 0.0, bx = 0.0, by = 0.0;
    if (active) {
        const Vec2 force = law.force(f, r, cd, s.py[i], vx, vy);
        ax = gravity ? g.x + im * force.x : im * force.x;
        ay = gravity ? g.y + im * force.y : im * force.y;
    }
    const double half = 0.5 * h * h;
    s.px[i] += h * vx + half * ax;
    s.py[i] += h * vy + half * ay;
    const double tvx = vx + h * ax, tvy = vy + h * ay;
    if (active) {
        const Vec2 force = law.force(f, r, cd, s.py[i], tvx, tvy);
        bx = gravity ? g.x + im * force.x : im * force.x;
        by = gravity ? g.y + im * force.y : im * force.y;
    }
    s.vx[i] = vx + 0.5 * h * (ax + bx);
    s.vy[i] = vy + 0.5 * h * (ay + by);
}

/// The integrators the flight pass fuses with the model choice.
enum class FlightScheme { SymplecticEuler, VelocityVerlet };

/// One sub-step of h seconds, from world time `start` to `end`, over every particle, for
/// symplectic Euler with local forces only (no springs, no point gravity): the model
/// choice first when `rule` is given (the tick's first sub-step), then the closed form or
///   v' = v + h (g + F(p, v)/m),  p' = p + h v'
/// and the count of the models the particles are in. `lanes` caps how many particles a
/// step takes at once (1, 2 with SSE2, 4 with AVX2 where the processor has it): the
/// results are the same bits whatever it is, which the tests check.
ModelCounts symplecticFlightPass(ParticleSet& s, const ForceDef& forces, const ModelRule* rule,
                                 double h, double start, double end, int lanes = 4);

/// The same sweep for either scheme: velocity Verlet takes velocityVerletLocalStep()
/// where symplectic Euler takes symplecticLocalStep(), bit for bit the same as
/// integrate(VelocityVerlet) between the closed form's launch and advance.
ModelCounts flightPass(ParticleSet& s, const ForceDef& forces, const ModelRule* rule, double h,
                       double start, double end, FlightScheme scheme, int lanes = 4);

} // namespace phys
