// Constraints for what springs cannot do (Millington's rods and cables, in the style
// of his contact generators): a rod keeps two particles at a fixed distance, a cable
// keeps them no farther apart than its length. A spring stiff enough to do the same
// needs w dt < 2 (w = sqrt(k/m)) to stay stable; a constraint has no stiffness to blow up.
//
// Solved after the step by projection, all constraints together:
//   position: C_c = L_c - L0_c for every rod and every taut cable, J the Jacobian of C
//             (row c: n_c at a, -n_c at b, n_c = (p_a - p_b)/L), W the inverse masses.
//             Newton steps  (J W J^T) lambda = -C,  dp = W J^T lambda  until every
//             |C_c| / L0_c is within the tolerance (usually 1-3 steps).
//   velocity: the same matrix removes the velocity along each rod (and the stretching
//             velocity of taut cables): (J W J^T) mu = -J v,  v += W J^T mu.
// J W J^T is symmetric positive (semi)definite. Constraints that share a particle are
// coupled in it, so when the constraints are listed along their chains (a rope's links
// in order), it is banded: row c couples only rows within b of c (b = 1 for ropes).
// Such a system is solved directly, by banded Cholesky, J W J^T = L L^T with L of
// bandwidth b (Golub & Van Loan, Matrix Computations, 4.3.5): O(m b^2) per solve
// instead of CG's O(m^2) on a chain. Where the band is wider than kDirectBandwidth, or a
// pivot vanishes (a dependent set: a taut straight rope pinned at both ends), the solve
// is conjugate gradients, matrix-free and Jacobi-preconditioned. Unlike Gauss-Seidel, which needs
// on the order of n^2 sweeps to pass a correction along a chain of n links, CG solves a chain in at
// most n iterations of O(n) each: a whipping 20-link rope keeps its length to 1e-5.
// Moving a particle by projection invalidates position-Verlet and leapfrog history for
// it, which is re-bootstrapped.
#pragma once

#include "physics/particles.h"
#include "physics/vec2.h"

#include <string>
#include <vector>

namespace phys {

enum class ConstraintKind : unsigned char { Rod, Cable };

/// A rod or cable between two particles, or from a particle to a fixed anchor.
struct DistanceConstraint {
    ConstraintKind kind = ConstraintKind::Rod;
    ParticleId a = kNoParticle;
    ParticleId b = kNoParticle; ///< kNoParticle: the other end is `anchor`
    Vec2 anchor;                ///< m, used when b == kNoParticle
    double length = 1.0;        ///< L0, m, > 0
};

/// "" when usable with `set`, else what is wrong.
std::string validate(const DistanceConstraint& c, const ParticleSet& set);

/// |L - L0| / L0 of one constraint now (cables: 0 while slack).
double lengthError(const DistanceConstraint& c, const ParticleSet& set);

/// Buffers the solver reuses between steps (no allocation per step once sized).
struct ConstraintScratch {
    std::vector<Vec2> dir;                  // n_c per constraint
    std::vector<double> rhs, x, r, z, p, q; // per constraint
    std::vector<unsigned char> active;      // per constraint
    std::vector<Vec2> dp;                   // W J^T x, per particle slot
    int lastIterations = 0;                 // CG iterations of the last solve call, summed
    int lastDirectSolves = 0;               // solves done by banded Cholesky, same call
    std::vector<double> band;               // L of J W J^T, (bandwidth + 1) per row
    std::vector<int> lastRow;               // per particle slot: last constraint at it
};

/// The widest band (largest distance in the list between two constraints that share a
/// particle) that the solver factors directly.
inline constexpr int kDirectBandwidth = 8;

/// Projects every constraint (see the file comment): at most `newtonSteps` position
/// steps, stopping once every relative error is within `tolerance`, then the velocity
/// solve. Returns the largest relative length error left (cables: only if over-long).
double solveConstraints(const std::vector<DistanceConstraint>& constraints, ParticleSet& set,
                        ConstraintScratch& scratch, int newtonSteps = 4, double tolerance = 1e-6);

} // namespace phys
