// Conserved quantities and a state hash: what tests, the guard and the stats panel read.
#pragma once

#include "physics/forces.h"
#include "physics/particles.h"

#include <cstdint>

namespace phys {

struct EnergyReport {
    double kinetic = 0.0;   ///< sum 1/2 m |v|^2, J
    double potential = 0.0; ///< gravitational, -m g.p (zero at the origin), J
    double elastic = 0.0;   ///< sum 1/2 k (L - L0)^2 over unbroken springs, J
    double total() const { return kinetic + potential + elastic; }
};

/// Energy of the moving (non-fixed) particles and springs.
EnergyReport energy(const ParticleSet& set, const std::vector<Spring>& springs,
                    const ForceDef& forces);
/// Total linear momentum sum m v of the moving particles, kg m/s.
Vec2 momentum(const ParticleSet& set);

/// FNV-1a 64-bit hash over the exact bits of every alive particle's state and flags.
/// Equal hashes after equal ticks is how determinism is tested.
std::uint64_t stateHash(const ParticleSet& set, std::uint64_t seed = 0xcbf29ce484222325ull);
/// Continues an FNV-1a hash over raw bytes.
std::uint64_t hashBytes(std::uint64_t h, const void* data, std::size_t size);

} // namespace phys
