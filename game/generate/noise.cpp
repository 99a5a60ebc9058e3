#include "game/generate/noise.h"

#include "game/generate/seeded_random.h"

#include <cmath>

namespace game::generate {

namespace {

/// The random value in [-1, 1) at lattice point i of one octave.
double latticeValue(std::uint64_t seed, int octave, std::int64_t i) {
    const std::uint64_t key = mix64(seed ^ mix64(static_cast<std::uint64_t>(octave) + 1)) ^
                              static_cast<std::uint64_t>(i) * 0x9e3779b97f4a7c15ull;
    return 2.0 * unitFromBits(mix64(key)) - 1.0;
}

/// One octave: lattice values at floor(u) and floor(u) + 1, smoothstep between.
double octaveNoise(std::uint64_t seed, int octave, double u) {
    const double cell = std::floor(u);
    const double t = u - cell;
    const double s = t * t * (3.0 - 2.0 * t);
    const auto i = static_cast<std::int64_t>(cell);
    const double a = latticeValue(seed, octave, i), b = latticeValue(seed, octave, i + 1);
    return a + (b - a) * s;
}

} // namespace

double valueNoise(std::uint64_t seed, const NoiseDef& def, double x) {
    double sum = 0.0, amplitude = 1.0, total = 0.0, frequency = 1.0 / def.wavelength;
    for (int k = 0; k < def.octaves; ++k) {
        sum += amplitude * octaveNoise(seed, k, x * frequency);
        total += amplitude;
        amplitude *= def.persistence;
        frequency *= 2.0;
    }
    return sum / total;
}

} // namespace game::generate
