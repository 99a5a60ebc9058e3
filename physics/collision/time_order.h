// The order in which a pass resolves its candidate contacts: by time of impact, ties in
// the order the candidates are listed (pair order), so that the result never depends on
// the sort.
#pragma once

#include <cstdint>
#include <vector>

namespace phys {

struct TimeKey {
    double time;
    std::uint32_t index; ///< the candidate's place in its list
};

/// Sorts keys given in index order by (time, index). Past kRadixSortFrom keys (a heap's
/// passes list thousands) by a stable radix sort on the times' bits, byte by byte from
/// the lowest, instead of by comparisons, most of them mispredicted: the same order, as
/// ties keep the index order they start in. `scratch` is the radix sort's other buffer.
void orderByTime(std::vector<TimeKey>& keys, std::vector<TimeKey>& scratch);

/// Below this many keys the comparison sort is as fast (a radix sort pays eight passes).
inline constexpr std::size_t kRadixSortFrom = 1024;

} // namespace phys
