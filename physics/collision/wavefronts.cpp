#include "physics/collision/wavefronts.h"

namespace phys {

void Wavefronts::begin(std::size_t slots) {
    // A sweep has fewer wavefronts than rows, and the rows are counted in 32 bits: past
    // half the range, the count restarts before it could wrap.
    if (top_ > 0x7fffffffu || latest_.size() < slots + 1) {
        latest_.assign(std::max(latest_.size(), slots + 1), 0u);
        top_ = 0;
    }
    spare_ = static_cast<std::uint32_t>(slots);
    first_ = base_ = top_;
    entries_.clear();
    barriers_.clear();
}

// A counting sort by key (stable: sweep order within a key), each key's run padded.
const std::vector<std::uint32_t>& Wavefronts::order(std::uint32_t width) {
    waves_ = top_ - first_;
    start_.assign(2 * static_cast<std::size_t>(waves_) + 1, 0u);
    for (const Entry& e : entries_)
        ++start_[e.key + 1];
    for (std::size_t k = 1; k < start_.size(); ++k) {
        const std::uint32_t run = start_[k];
        start_[k] = start_[k - 1] + (run + width - 1) / width * width;
    }
    barrierStarts_.clear();
    for (const std::uint32_t b : barriers_) // the first key after it, 2 (b - first_)
        barrierStarts_.push_back(start_[2 * static_cast<std::size_t>(b - first_)]);
    order_.assign(start_.back(), kPadding);
    for (const Entry& e : entries_)
        order_[start_[e.key]++] = e.row;
    return order_;
}

} // namespace phys
