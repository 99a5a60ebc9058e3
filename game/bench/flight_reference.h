// The hardware's limit for the flight update: a reference kernel that reads and writes
// the same arrays as the particle layer's update and does the same arithmetic (symplectic
// Euler under gravity and quadratic drag relative to the wind), written for speed alone:
// four particles at a time with AVX2 where the processor has it (chosen at run time, as
// physics/model_pass.cpp does), two with SSE2 otherwise, no model choice, no counts, no
// closed form. Its bits need not match the game's; its bytes and its arithmetic do.
// The velocity Verlet reference does that integrator's arithmetic (two drag evaluations).
// Beside it, a copy of as many bytes with memcpy: what the memory moves in this process.
#pragma once

#include "physics/particles.h"
#include "physics/vec2.h"

#include <cstddef>

namespace game::bench {

/// Bytes the flight update and the reference move per particle: it reads px, py, vx, vy,
/// invMass, radius, dragCd (7 doubles) and the flags word, and writes px, py, vx, vy.
inline constexpr std::size_t kFlightBytesRead = 7 * sizeof(double) + sizeof(std::uint32_t);
inline constexpr std::size_t kFlightBytesWritten = 4 * sizeof(double);
inline constexpr std::size_t kFlightBytesPerParticle = kFlightBytesRead + kFlightBytesWritten;

/// The constants of one reference step.
struct FlightReferenceStep {
    double h = 1.0 / 120.0;         ///< s
    phys::Vec2 gravity{0.0, -9.81}; ///< m/s^2
    phys::Vec2 wind{};              ///< m/s
    double halfRhoPi = 0.0;         ///< 1/2 rho_air pi, kg/m^3 (drag k = this Cd r^2 |u|)
};

/// One step of every awake, massive particle of `s`:
///   u = v - wind, k = 1/2 rho pi Cd r^2 |u|, v' = v + h (g - k u / m), p' = p + h v'
/// (others drift: p' = p + h v). `lanes` caps the width (1, 2 or 4) as in the flight pass.
void flightReferenceStep(phys::ParticleSet& s, const FlightReferenceStep& step, int lanes = 4);

/// The same for velocity Verlet, the same bytes and twice the force arithmetic:
///   a = g - k(v) u(v) / m,  p' = p + h v + h^2/2 a,  v~ = v + h a,
///   b = g - k(v~) u(v~) / m,  v' = v + h/2 (a + b)
/// (others drift). Four lanes with AVX2, else one.
void flightReferenceVerletStep(phys::ParticleSet& s, const FlightReferenceStep& step,
                               int lanes = 4);
/// The widest lanes the velocity Verlet reference takes here (4 with AVX2, else 1).
int flightReferenceVerletLanes();

/// The widest lanes the reference takes on this processor (4 with AVX2, else 2 or 1).
int flightReferenceLanes();

/// Copies `bytes` from `from` to `to` with memcpy: the copy bandwidth probe.
void copyBytes(void* to, const void* from, std::size_t bytes);

} // namespace game::bench
