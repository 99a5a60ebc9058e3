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
    for (int shift = 0; shift < 64; shift += 8) {
        std::array<std::uint32_t, 257> start{};
        for (const TimeKey& k : keys)
            ++start[((ordered(k.time) >> shift) & 0xff) + 1];
        if (std::find(start.begin() + 1, start.end(), n) != start.end()) continue; // all alike
        for (std::size_t d = 1; d < start.size(); ++d)
            start[d] += start[d - 1];
        for (const TimeKey& k : keys)
            scratch[start[(ordered(k.time) >> shift) & 0xff]++] = k;
        keys.swap(scratch);
    }
}

} // namespace phys
