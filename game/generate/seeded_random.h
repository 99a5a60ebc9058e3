// The generator's own random numbers: SplitMix64 (Steele, Lea and Flood, "Fast
// splittable pseudorandom number generators", OOPSLA 2014) in 64-bit integer arithmetic,
// and doubles made from its top 53 bits by exact operations. Nothing here depends on
// the standard library's distributions (whose algorithms differ between
// implementations) or on the platform, so a seed gives the same level on every build.
#pragma once

#include <cstdint>

namespace game::generate {

/// One SplitMix64 output for a state: the mixing function alone, also used to hash
/// lattice coordinates for noise.
constexpr std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/// A value in [0, 1): the top 53 bits of `bits` times 2^-53 (exact in a double).
constexpr double unitFromBits(std::uint64_t bits) {
    return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

class SeededRandom {
  public:
    explicit constexpr SeededRandom(std::uint64_t seed) : state_(seed) {}

    /// The next 64 random bits: the state advances by the golden-ratio increment.
    constexpr std::uint64_t next() {
        state_ += 0x9e3779b97f4a7c15ull;
        return mix64(state_);
    }
    /// Uniform in [0, 1).
    constexpr double unit() { return unitFromBits(next()); }
    /// Uniform in [lo, hi).
    constexpr double between(double lo, double hi) { return lo + (hi - lo) * unit(); }
    /// Uniform integer in [0, n), 0 < n < 2^31 (the multiply-shift of Lemire, 2019, on
    /// the top 32 bits, without its rejection step: the bias, n / 2^32, is far below
    /// anything a level shows).
    constexpr int below(int n) {
        return static_cast<int>(((next() >> 32) * static_cast<std::uint64_t>(n)) >> 32);
    }
    /// True with probability p.
    constexpr bool chance(double p) { return unit() < p; }

  private:
    std::uint64_t state_;
};

} // namespace game::generate
