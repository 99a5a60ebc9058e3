// Value noise in one dimension, summed over octaves ("fractal" noise; Perlin, "An image
// synthesizer", SIGGRAPH 1985, uses the same sum of halving amplitudes): random heights
// at integer lattice points, hashed from the seed, the octave and the lattice index,
// joined by the smoothstep 3t^2 - 2t^3 so the slope is continuous. Only +, -, * on
// doubles: the same bits on every IEEE build (the project compiles with
// -ffp-contract=off, so no fused multiply-add changes a rounding).
#pragma once

#include <cstdint>

namespace game::generate {

struct NoiseDef {
    double wavelength = 80.0; ///< m between lattice points of the first octave
    int octaves = 4;          ///< each halves the wavelength
    double persistence = 0.5; ///< amplitude ratio from one octave to the next
};

/// Fractal value noise at x (m), in [-1, 1] (normalised by the sum of the amplitudes).
double valueNoise(std::uint64_t seed, const NoiseDef& def, double x);

} // namespace game::generate
