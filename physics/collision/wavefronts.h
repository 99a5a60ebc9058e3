// Wavefronts of a Gauss-Seidel sweep: the rows of a sweep (contacts, each reading and
// writing the state of a few slots) regrouped so that no two rows of a wavefront share a
// slot, while every two rows that do share one keep their order. Rows that share no slot
// commute exactly (neither reads what the other writes), so sweeping the wavefronts one
// after the other, and the rows of a wavefront in any order or all at once, gives the
// same bits as the sweep in its own order.
//
// A row's wavefront is one past the latest wavefront of the rows before it that share a
// slot with it (a list schedule, as for the levels of a triangular solve). In a resting
// pile the contacts, listed band by band from the ground up and by pair within a band
// (those with something immovable last), fall into far fewer wavefronts than
// contacts: most of them wide enough for vector lanes.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace phys {

class Wavefronts {
  public:
    /// Marks a padding place in order(): no row.
    static constexpr std::uint32_t kPadding = 0xffffffffu;
    /// Starts a sweep over `slots` slots; slots at or past `slots` (a place that is never
    /// written, or one whose value is never read) order nothing.
    void begin(std::size_t slots);
    /// The next row of the sweep, in its order: `kind` 0 or 1 (the rows of each kind
    /// gather in a wavefront, for kernels that take one kind at a time), touching up to
    /// three slots (repeats and slots past the sweep's count are ignored).
    void add(std::uint32_t row, std::uint32_t kind, std::uint32_t s0, std::uint32_t s1,
             std::uint32_t s2) {
        const std::uint32_t front = place(latest_.data(), spare_, base_, s0, s1, s2);
        top_ = std::max(top_, front);
        entries_.push_back({row, 2 * (front - first_ - 1) + kind});
    }
    /// add() for each row k of `sequence` in turn, `slots(k)` giving its kind and slots,
    /// with a barrier() before each place of `parts` (ascending; those at the end too).
    template <class Slots>
    void add(const std::vector<std::uint32_t>& sequence, const std::vector<std::uint32_t>& parts,
             Slots&& slots) {
        // The counters in locals: the stores to latest_ could alias members, not locals.
        std::uint32_t* const latest = latest_.data();
        const std::uint32_t spare = spare_, first = first_;
        std::uint32_t base = base_, top = top_;
        const std::size_t begin = entries_.size();
        entries_.resize(begin + sequence.size());
        Entry* const out = entries_.data() + begin;
        std::size_t next = 0;
        for (std::size_t i = 0; i < sequence.size(); ++i) {
            for (; next < parts.size() && parts[next] == i; ++next)
                base = top, barriers_.push_back(top);
            const std::uint32_t k = sequence[i];
            const auto [kind, s0, s1, s2] = slots(k);
            const std::uint32_t front = place(latest, spare, base, s0, s1, s2);
            top = std::max(top, front);
            out[i] = {k, 2 * (front - first - 1) + kind};
        }
        for (; next < parts.size(); ++next)
            base = top, barriers_.push_back(top);
        base_ = base, top_ = top;
    }
    /// The rows added after this start in a wavefront after all the wavefronts so far:
    /// a sweep made of parts, each of which is also swept on its own.
    void barrier() {
        base_ = top_;
        barriers_.push_back(top_);
    }
    /// The rows by wavefront, and within one by kind then sweep order; each kind's run
    /// of a wavefront padded with kPadding to a multiple of `width`.
    const std::vector<std::uint32_t>& order(std::uint32_t width);
    /// Where in order() the rows after each barrier start, in the order of the barriers.
    const std::vector<std::uint32_t>& barrierStarts() const { return barrierStarts_; }
    /// The number of wavefronts of the last order().
    std::uint32_t count() const { return waves_; }

  private:
    struct Entry {
        std::uint32_t row, key; ///< key: 2 * wavefront (from 0) + kind
    };
    // latest_[s]: the last wavefront to touch slot s, counted over every sweep since the
    // count restarted, so that a sweep starts past all the wavefronts before it (base_)
    // and nothing needs clearing between sweeps; latest_[spare_] stays 0.
    std::vector<std::uint32_t> latest_;
    // A row's wavefront: one past the latest of its slots' and of the base; its slots
    // take it. Slots past the count all read the spare slot, which stays 0.
    static std::uint32_t place(std::uint32_t* latest, std::uint32_t spare, std::uint32_t base,
                               std::uint32_t s0, std::uint32_t s1, std::uint32_t s2) {
        const std::uint32_t i0 = std::min(s0, spare), i1 = std::min(s1, spare),
                            i2 = std::min(s2, spare);
        const std::uint32_t front = std::max({base, latest[i0], latest[i1], latest[i2]}) + 1;
        latest[i0] = latest[i1] = latest[i2] = front;
        latest[spare] = 0;
        return front;
    }
    std::uint32_t spare_ = 0, base_ = 0, top_ = 0;
    std::uint32_t first_ = 0; ///< the last wavefront before this sweep
    std::vector<Entry> entries_;
    std::vector<std::uint32_t> start_, order_, barriers_, barrierStarts_;
    std::uint32_t waves_ = 0;
};

} // namespace phys
