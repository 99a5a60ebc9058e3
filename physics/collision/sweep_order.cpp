#include "physics/collision/sweep_order.h"

#include <array>

namespace phys {

void SweepOrder::prepare(std::size_t n) {
    if (level_.size() < n) level_.resize(n, kUnsupported);
    holds_.clear();
}

// order_: the contacts by band (the level of their upper particle), those with something
// immovable last in each band, a counting sort, so the pair order, which is fixed, breaks
// ties. Only the contacts' particles (bodies) are counted, by their places there.
void SweepOrder::orderByLevel(const std::vector<SolverContact>& contacts,
                              const std::vector<std::uint32_t>& bodies,
                              const std::vector<std::uint32_t>& bodyIndex) {
    findLevels(bodies, bodyIndex);
    sortIntoBands(contacts, bodies);
}

// Levels spread from the particles the ground holds up (level 1) to the particles they
// hold up, breadth first; particles that nothing connects to the ground this way keep no
// level. A particle's level is its distance from the ground, whatever order the search
// takes them in.
void SweepOrder::findLevels(const std::vector<std::uint32_t>& bodies,
                            const std::vector<std::uint32_t>& bodyIndex) {
    const std::size_t n = bodies.size();
    // Who holds whom up, among the movable particles: offsets into a flat list.
    adjacencyStart_.assign(n + 1, 0u);
    for (const auto& [holder, held] : holds_)
        ++adjacencyStart_[bodyIndex[holder] + 1];
    for (std::size_t i = 0; i < n; ++i)
        adjacencyStart_[i + 1] += adjacencyStart_[i];
    adjacency_.resize(adjacencyStart_[n]);
    fill_.assign(adjacencyStart_.begin(), adjacencyStart_.end() - 1);
    for (const auto& [holder, held] : holds_)
        adjacency_[fill_[bodyIndex[holder]]++] = held;
    // Breadth first from the ground.
    frontier_.clear();
    for (const std::uint32_t i : bodies)
        if (level_[i] == 1) frontier_.push_back(i);
    for (std::size_t head = 0; head < frontier_.size(); ++head) {
        const std::uint32_t p = frontier_[head], at = bodyIndex[p];
        for (std::uint32_t k = adjacencyStart_[at]; k < adjacencyStart_[at + 1]; ++k) {
            const std::uint32_t q = adjacency_[k];
            if (level_[q] != kUnsupported) continue;
            level_[q] = level_[p] + 1;
            frontier_.push_back(q);
        }
    }
}

// Bands: a contact belongs to the level of its upper particle (a static contact to its
// particle's); band 0 is never used (the ground does not move), the last band holds what
// no path of contacts connects to the ground. Within a band, the contacts with something
// immovable (a shape, a fixed or sleeping particle) come after the others: the projection
// then leaves nothing inside those, whatever else stays to do.
void SweepOrder::sortIntoBands(const std::vector<SolverContact>& contacts,
                               const std::vector<std::uint32_t>& bodies) {
    std::uint32_t top = 1;
    for (const std::uint32_t i : bodies)
        if (level_[i] != kUnsupported) top = std::max(top, level_[i]);
    const std::size_t unsupported = static_cast<std::size_t>(top) + 1;
    auto key = [&](const SolverContact& c) -> std::size_t {
        const std::uint32_t l = bandOf(c);
        const bool immovableSide = c.b == kNoParticle || c.wa == 0.0 || c.wb == 0.0;
        return 2 * (l == kUnsupported ? unsupported : l) + (immovableSide ? 1 : 0);
    };
    // Each contact's key once, in a column the placing pass reads instead of the contacts.
    keyStart_.assign(2 * unsupported + 3, 0u);
    contactKey_.resize(contacts.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const auto bucket = static_cast<std::uint32_t>(key(contacts[k]));
        contactKey_[k] = bucket;
        ++keyStart_[bucket + 1];
    }
    for (std::size_t k = 0; k + 1 < keyStart_.size(); ++k)
        keyStart_[k + 1] += keyStart_[k];
    bandStart_.resize(unsupported + 2);
    for (std::size_t b = 0; b < bandStart_.size(); ++b)
        bandStart_[b] = keyStart_[2 * b];
    order_.resize(contacts.size());
    for (std::uint32_t k = 0; k < contacts.size(); ++k)
        order_[keyStart_[contactKey_[k]]++] = k;
}

// The rows, one per contact, in the order of order_ (band by band from the ground up; in
// each band, the contacts with something immovable after the others), laid out in the
// wavefronts of that order when the lanes run, with a barrier before each band: one
// layout, which every sweep takes, those over all contacts and those over a band.
const std::vector<std::uint32_t>&
SweepOrder::layOut(bool lanes, const std::vector<SolverContact>& contacts, std::uint32_t still) {
    const std::vector<std::uint32_t>* rows = &order_;
    if (lanes) {
        wavefronts_.begin(still); // still and sink order nothing
        wavefronts_.add(order_, bandStart_, [&](std::uint32_t index) {
            const SolverContact& c = contacts[index];
            const bool shape = c.b == kNoParticle;
            const std::uint32_t b = shape ? still : c.b;
            return std::array<std::uint32_t, 4>{shape ? 1u : 0u, c.a, b, b};
        });
        const std::vector<std::uint32_t>& fronts = wavefronts_.order(4);
        rowStart_ = wavefronts_.barrierStarts();
        rows = &keepLanesWhereTheyFill(fronts);
    } else {
        rowStart_ = bandStart_;
        bandLanes_.assign(bandStart_.size() - 1, 0);
    }
    joinBandsIntoRuns();
    return *rows;
}

// The bands whose wavefronts are too narrow for the lanes are swept one row at a time
// instead, in their own order: the same bits (a band's wavefronts give the bits of its
// order), for less work where a padded lane would do one contact's work for four. A row
// of balls touching side by side, listed pair by pair, is a chain that takes one
// wavefront a contact: in a heap poured in staggered rows its bands take about three
// rows a contact in lanes. Returns the layout: `wavefronts` itself when every band
// keeps its lanes, else the bands' rows, each band's in the way it is swept.
const std::vector<std::uint32_t>&
SweepOrder::keepLanesWhereTheyFill(const std::vector<std::uint32_t>& wavefronts) {
    const std::size_t bands = bandStart_.size() - 1;
    bandLanes_.assign(bands, 1);
    bool mixed = false;
    for (std::size_t b = 0; b < bands; ++b) {
        const std::uint32_t rows = rowStart_[b + 1] - rowStart_[b];
        const std::uint32_t contacts = bandStart_[b + 1] - bandStart_[b];
        if (rows > kMostRowsPerContact * contacts) bandLanes_[b] = 0, mixed = true;
    }
    if (!mixed) return wavefronts;
    mixedOrder_.clear();
    for (std::size_t b = 0; b < bands; ++b) {
        const std::uint32_t from = static_cast<std::uint32_t>(mixedOrder_.size());
        if (bandLanes_[b])
            mixedOrder_.insert(mixedOrder_.end(), wavefronts.begin() + rowStart_[b],
                               wavefronts.begin() + rowStart_[b + 1]);
        else
            mixedOrder_.insert(mixedOrder_.end(), order_.begin() + bandStart_[b],
                               order_.begin() + bandStart_[b + 1]);
        rowStart_[b] = from;
    }
    rowStart_[bands] = static_cast<std::uint32_t>(mixedOrder_.size());
    return mixedOrder_;
}

// The sweeps over all contacts as runs of bands swept the same way: one run, [0, rows),
// unless some band is swept one row at a time.
void SweepOrder::joinBandsIntoRuns() {
    runs_.clear();
    for (std::size_t b = 0; b + 1 < rowStart_.size(); ++b) {
        const bool lanes = bandLanes_[b] != 0;
        if (!runs_.empty() && runs_.back().lanes == lanes)
            runs_.back().to = rowStart_[b + 1];
        else
            runs_.push_back({rowStart_[b], rowStart_[b + 1], lanes});
    }
}

} // namespace phys
