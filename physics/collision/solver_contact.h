// One contact of the end-of-step contact solver (contact_solver.h), as its build leaves
// it for the sweep order (sweep_order.h), the sweeps and the held sleepers.
#pragma once

#include "physics/collision/shapes.h"
#include "physics/vec2.h"

#include <cstdint>

namespace phys {

// The build writes every field where it builds a contact. The constructor leaves them
// (but shape and normal, whose types set themselves): with one the compiler provides,
// contacts_.emplace_back() first zeroes the whole contact, which the build then waits on
// before it writes each field again.
struct SolverContact {
    SolverContact() {} // NOLINT: deliberately leaves the fields to the builder
    std::uint32_t a;
    std::uint32_t b;     ///< kNoParticle for a static shape
    std::uint32_t proxy; ///< b, or slots + the shape's index
    ShapeRef shape;
    Vec2 normal;                          ///< from b (or the shape) to a
    double depth;                         ///< overlap, m (negative: a gap)
    double closing;                       ///< m/s the gap lets the contact close in a step
    double wa, wb;                        ///< inverse masses, 0 for immovable
    double friction;                      ///< mu_s
    int support;                          ///< 1: b (or the shape) holds a up; -1: a holds b
    double normalImpulse, tangentImpulse; ///< accumulated, N s
    /// The key of the warm start and of the events: a << 32 | proxy.
    std::uint64_t key() const { return (std::uint64_t{a} << 32) | proxy; }
};

} // namespace phys
