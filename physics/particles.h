// The particle set: structure of arrays, one slot per particle.
//
// A particle is a sphere of finite radius with no rotation (Rabin, Introduction to
// Game Development, 4.3). Slots are stable: removing a particle marks its slot dead and puts it
// on a free list that the next add reuses, so indices held by springs, rods and the
// game stay valid and the arrays are never reallocated during a step. A dead slot
// has inverse mass 0 and velocity 0, so every whole-array kernel may run over it
// without a branch and leave it unchanged.
#pragma once

#include "physics/vec2.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace phys {

using ParticleId = std::uint32_t;
constexpr ParticleId kNoParticle = 0xffffffffu;

/// Bits of ParticleSet::flags.
enum ParticleFlag : std::uint32_t {
    kAlive = 1u << 0,         ///< slot holds a particle
    kNoGravity = 1u << 1,     ///< uniform gravity does not act on it
    kNoDrag = 1u << 2,        ///< air drag and wind do not act on it
    kAttractor = 1u << 3,     ///< takes part in inverse-square point gravity
    kNoCollide = 1u << 4,     ///< ignored by collision detection
    kVerletPrimed = 1u << 5,  ///< position Verlet has a previous position for it
    kLeapfrogPrimed = 1u << 6,///< leapfrog has a staggered half-step velocity for it
    kSleeping = 1u << 7,      ///< at rest; skipped until something wakes it
    kProjectile = 1u << 8,    ///< fired by a cannon (game events track it)
    /// Moved by the closed form p0 + v0 t + g t^2/2 from its launch state (World, model
    /// policy Auto): only uniform gravity acts on it, so the integrators leave it alone.
    kBallistic = 1u << 9,
};

/// Definition of one particle, with defaults and units.
struct ParticleDef {
    Vec2 position;               ///< m
    Vec2 velocity;               ///< m/s
    double mass = 1.0;           ///< kg; 0 or infinity makes it fixed (inverse mass 0)
    double radius = 0.1;         ///< m, > 0
    double dragCoefficient = 0.47; ///< Cd, dimensionless (0.47: smooth sphere)
    std::uint16_t material = 0;  ///< index into the material table
    std::uint32_t flags = 0;     ///< extra ParticleFlag bits (kAlive is implied)
};

struct ParticleSet {
    // State vector S = <p, v>, split by component so kernels stream.
    std::vector<double> px, py;  ///< position, m
    std::vector<double> vx, vy;  ///< velocity, m/s
    // Properties.
    std::vector<double> invMass; ///< 1/kg; 0 = fixed or dead
    std::vector<double> radius;  ///< m
    std::vector<double> dragCd;  ///< drag coefficient Cd
    std::vector<std::uint16_t> material;
    std::vector<std::uint32_t> flags;
    // Integrator history (position Verlet's previous position, leapfrog's v_{n+1/2}).
    std::vector<double> prevX, prevY;
    std::vector<double> halfVx, halfVy;
    // Closed-form launch state of kBallistic particles: position, velocity and the world
    // time (s) they were launched at.
    std::vector<double> launchX, launchY, launchVx, launchVy, launchT;

    /// Adds a particle; reuses a dead slot when there is one. Returns its id.
    ParticleId add(const ParticleDef& def);
    /// Removes a particle; its id may be reused by a later add.
    void remove(ParticleId id);
    /// Pre-allocates room for n slots so adds up to n never reallocate.
    void reserve(std::size_t n);
    void clear();

    /// Number of slots (alive and dead); the bound of every kernel loop.
    std::size_t slots() const { return px.size(); }
    /// Number of alive particles.
    std::size_t count() const { return px.size() - freeSlots_.size(); }
    bool alive(ParticleId id) const { return id < slots() && (flags[id] & kAlive); }

    Vec2 position(ParticleId i) const { return {px[i], py[i]}; }
    Vec2 velocity(ParticleId i) const { return {vx[i], vy[i]}; }
    double mass(ParticleId i) const { return invMass[i] > 0.0 ? 1.0 / invMass[i] : 0.0; }
    /// Sets the position (and wakes the particle if it slept).
    void setPosition(ParticleId i, Vec2 p);
    /// Sets the velocity, wakes the particle, and forgets integrator history that
    /// assumed the old one (blasts and commands change velocity through here).
    void setVelocity(ParticleId i, Vec2 v);
    /// Forgets the Verlet/leapfrog history of every particle (after a dt change).
    void resetHistory();

  private:
    std::vector<ParticleId> freeSlots_;
};

} // namespace phys
