// Broad phase: which proxies (particles' swept boxes, static shapes' boxes) might touch.
//
// Uniform grid (the default; spatial partitioning, as in Claypool, "Basic Game Physics"):
// every box is entered in
// the cells it covers, the entries are bucketed by a hash of their cell with a counting
// sort into flat arrays, and only boxes sharing a cell are tested. Each box then looks
// up the cells it covers for partners of higher index (a partner met in several cells
// counts once), so the pairs come out sorted, without a sort of the whole list. With
// cells about the size of the boxes, each box covers a few cells and meets a few
// neighbours: O(n) for n boxes spread over a level. Boxes too big for the grid (a long
// floor segment) are kept aside and tested against every box.
//
// Sort and sweep (the plane sweep of the same lecture): sort the boxes by their low end on
// one axis, sweep, and keep an active list of boxes whose interval is still open;
// only boxes in the active list can overlap on that axis, and only those are tested
// on the other. Cost O(n log n + k) for k overlapping pairs (the sort starts from the
// previous frame's order, which is nearly sorted). The axis is the one along which the
// box centres are spread the most, so a column of particles does not degrade it.
//
// allPairs() is the naive O(n^2) reference the tests compare it with.
#pragma once

#include "physics/collision/shapes.h"

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace phys {

/// What a proxy is, for pairing: a moving proxy pairs with everything; two resting
/// proxies (static shapes, fixed or sleeping particles) never pair; None is skipped.
enum class ProxyKind : std::uint8_t { None, Moving, Resting };

using ProxyPair = std::pair<std::uint32_t, std::uint32_t>; ///< first < second

/// Two proxies may pair: neither is gone and at least one moves (without branches).
inline bool pairable(ProxyKind a, ProxyKind b) {
    return (a != ProxyKind::None) & (b != ProxyKind::None) &
           ((a == ProxyKind::Moving) | (b == ProxyKind::Moving));
}

/// The reference: every overlapping pair by testing all of them, sorted.
void allPairs(std::span<const Aabb> boxes, std::span<const ProxyKind> kinds,
              std::vector<ProxyPair>& out);

/// A uniform grid's contents: entries (cell, id) bucketed by a hash of their cell, with
/// a counting sort, into one flat array (O(entries), no per-cell containers).
class CellBuckets {
  public:
    struct Entry {
        std::int64_t cx, cy;
        std::uint32_t id;
    };
    void clear() { entries_.clear(); }
    void add(std::int64_t cx, std::int64_t cy, std::uint32_t id) {
        entries_.push_back({cx, cy, id});
    }
    /// Sorts what was added into its buckets: call after the adds, before the lookups.
    void bucket();
    bool bucketed() const { return !bucketStart_.empty(); }
    /// The entries in the bucket of cell (cx, cy): that cell's, and those of any cells
    /// that share its bucket (an entry's cx, cy say which).
    std::span<const Entry> bucketOf(std::int64_t cx, std::int64_t cy) const;

  private:
    std::vector<Entry> entries_, sorted_;
    std::vector<std::uint32_t> bucketOf_;    ///< per entry
    std::vector<std::uint32_t> bucketStart_; ///< counting sort offsets, buckets + 1
};

class UniformGrid {
  public:
    /// The overlapping pairs, sorted; `out` is cleared first. cellSize (m) <= 0 picks
    /// twice the mean extent of the moving boxes. Keeps its buffers between calls.
    void findPairs(std::span<const Aabb> boxes, std::span<const ProxyKind> kinds,
                   std::vector<ProxyPair>& out, double cellSize = 0.0);
    /// Boxes covering more than this many cells are tested against all others instead.
    static constexpr int kMaxCellsPerBox = 64;

  private:
    struct CellRange {
        std::int64_t x0, y0, x1, y1;
    };
    std::vector<CellRange> ranges_;    ///< per proxy: the cells its box covers
    std::vector<std::uint8_t> placed_; ///< per proxy: entered in the grid
    CellBuckets cells_;                ///< (cell, proxy)
    std::vector<std::uint32_t> oversize_;
    std::vector<std::uint32_t> partners_; ///< one proxy's partners, before sorting
};

/// Which of many boxes may overlap one box: the boxes entered in a uniform grid (cells
/// hashed into buckets by a counting sort, as in UniformGrid), for the broad phase's kept
/// pairs, where a few proxies that escaped their fat boxes need their partners among
/// thousands: a query costs the boxes near it, not a test of every box. A box may change
/// after the build; it is then set aside (moved) and every query lists it, until the
/// next build.
class BoxQueryGrid {
  public:
    /// Enters boxes[i] for every i whose kind is not None, in cells of about the mean box
    /// size; forgets what moved.
    void build(std::span<const Aabb> boxes, std::span<const ProxyKind> kinds);
    /// Box i (or its kind) changed since the build.
    void moved(std::uint32_t i);
    std::size_t movedCount() const { return moved_.size(); }
    /// Appends to `out` each box that may overlap `box`, once: those of the build that
    /// share a cell with it (moved ones aside) and every moved one; the caller tests them.
    /// False, with `out` unchanged, when `box` covers more than kMaxQueryCells cells:
    /// testing every box is then as cheap.
    bool query(const Aabb& box, std::vector<std::uint32_t>& out);
    static constexpr std::int64_t kMaxQueryCells = 256;

  private:
    double inv_ = 1.0;  ///< 1 / cell size
    CellBuckets cells_; ///< (cell, box)
    std::vector<std::uint32_t> oversize_, moved_;
    std::vector<std::uint8_t> movedMark_;
    std::vector<std::uint32_t> listed_; ///< per box: the query that last listed it
    std::uint32_t queries_ = 0;
};

/// The static shapes in a grid of their own, built once per StaticShapes::version():
/// shapes never move, so only the moving particles' boxes are looked up each pass,
/// instead of entering hundreds of terrain segments into the broad phase every pass.
class StaticShapeIndex {
  public:
    /// Rebuilds the index if the shapes changed since the last call (cheap otherwise).
    void update(const StaticShapes& shapes);
    /// Indices (in StaticShapes::ref order) of the shapes whose box overlaps `box`,
    /// sorted and unique; appended to `out` after clearing it.
    void query(const Aabb& box, std::vector<std::uint32_t>& out) const;
    /// The box of shape i (StaticShapes::ref order), as of the last update.
    const Aabb& box(std::size_t i) const { return boxes_[i]; }
    /// Every shape's box, in the same order.
    std::span<const Aabb> boxes() const { return boxes_; }
    /// StaticShapes::version() of the last update.
    std::uint64_t version() const { return version_; }

  private:
    std::uint64_t version_ = 0;
    std::size_t count_ = 0;
    double cell_ = 1.0;
    Vec2 origin_;
    std::int64_t nx_ = 0, ny_ = 0;
    std::vector<Aabb> boxes_;
    std::vector<std::uint32_t> cellStart_, items_, oversize_;
};

class SortAndSweep {
  public:
    /// The overlapping pairs, sorted; `out` is cleared first. Keeps its buffers between
    /// calls, so once warm it does not allocate.
    void findPairs(std::span<const Aabb> boxes, std::span<const ProxyKind> kinds,
                   std::vector<ProxyPair>& out);

  private:
    std::vector<std::uint32_t> order_;
    std::vector<std::uint32_t> active_;
};

} // namespace phys
