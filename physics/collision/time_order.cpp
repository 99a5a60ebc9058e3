#include "physics/collision/time_order.h"

#include <algorithm>
#include <array>
#include <bit>

namespace phys {

namespace {

// The bits of a double as an unsigned integer in the doubles' order: negative ones flipped
// whole, the others with the sign bit set; -0 as +0, which compares equal to it.
std::uint64_t ordered(double t) {
    const auto b = std::bit_cast<std::uint64_t>(t == 0.0 ? 0.0 : t);
    return (b >> 63) != 0 ? ~b : b | (std::uint64_t{1} << 63);
}

} // namespace

void orderByTime(std::vector<TimeKey>& keys, std::vector<TimeKey>& scratch) {
    if (keys.size() < kRadixSortFrom) {
        std::sort(keys.begin(), keys.end(), [](const TimeKey& x, const TimeKey& y) {
            return x.time < y.time || (x.time == y.time && x.index < y.index);
        });
        return;
    }
    const std::size_t n = keys.size();
    scratch.resize(n);
    // The eight bytes' counts in one pass: a byte's counts do not depend on the order the
    // earlier passes leave the keys in.
    std::array<std::array<std::uint32_t, 257>, 8> start{};
    for (const TimeKey& k : keys) {
        const std::uint64_t u = ordered(k.time);
        for (int byte = 0; byte < 8; ++byte)
            ++start[byte][((u >> (8 * byte)) & 0xff) + 1];
    }
    for (int byte = 0; byte < 8; ++byte) {
        std::array<std::uint32_t, 257>& at = start[byte];
        if (std::find(at.begin() + 1, at.end(), n) != at.end()) continue; // all alike
        for (std::size_t d = 1; d < at.size(); ++d)
            at[d] += at[d - 1];
        const int shift = 8 * byte;
        for (const TimeKey& k : keys)
            scratch[at[(ordered(k.time) >> shift) & 0xff]++] = k;
        keys.swap(scratch);
    }
}

} // namespace phys
