#include "physics/collision/broadphase.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace phys {

namespace {
ProxyPair ordered(std::uint32_t a, std::uint32_t b) {
    return a < b ? ProxyPair{a, b} : ProxyPair{b, a};
}
} // namespace

void allPairs(std::span<const Aabb> boxes, std::span<const ProxyKind> kinds,
              std::vector<ProxyPair>& out) {
    out.clear();
    const auto n = static_cast<std::uint32_t>(boxes.size());
    for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t j = i + 1; j < n; ++j)
            if (pairable(kinds[i], kinds[j]) && boxes[i].overlaps(boxes[j])) out.push_back({i, j});
}

namespace {
// Cell index of a coordinate, clamped so that far-away boxes cannot overflow.
std::int64_t cellOf(double x, double inv) {
    const double c = std::floor(x * inv);
    return static_cast<std::int64_t>(std::clamp(c, -1e15, 1e15));
}
// More than `most` cells in the range x0..x1, y0..y1; in doubles, as a box that reached
// far out spans up to 2e15 cells a side, whose product would overflow.
bool coversMoreThan(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1,
                    std::int64_t most) {
    const double cells = (static_cast<double>(x1) - static_cast<double>(x0) + 1.0) *
                         (static_cast<double>(y1) - static_cast<double>(y0) + 1.0);
    return !(cells <= static_cast<double>(most));
}
// The mean of (width + height) / 2 over the boxes whose kind `counts` accepts, or 0 when
// none of them has any extent: what the grids size their cells by.
template <class Counts>
double meanExtent(std::span<const Aabb> boxes, std::span<const ProxyKind> kinds, Counts counts) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i)
        if (counts(kinds[i])) {
            sum += (boxes[i].hi.x - boxes[i].lo.x) + (boxes[i].hi.y - boxes[i].lo.y);
            ++count;
        }
    return count > 0 && sum > 0.0 ? sum / (2.0 * count) : 0.0;
}
// Bucket of a cell: two large odd multipliers, then the high half folded onto the low
// half (the low bits of a product depend on the low bits of the factors only).
std::uint64_t cellHash(std::int64_t cx, std::int64_t cy) {
    const std::uint64_t h = static_cast<std::uint64_t>(cx) * 0x9E3779B97F4A7C15ull +
                            static_cast<std::uint64_t>(cy) * 0xC2B2AE3D27D4EB4Full;
    return h ^ (h >> 29) ^ (h >> 47);
}
} // namespace

void CellBuckets::bucket() {
    const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(2 * entries_.size(), 16));
    bucketStart_.assign(buckets + 1, 0);
    bucketOf_.resize(entries_.size());
    for (std::size_t k = 0; k < entries_.size(); ++k) {
        bucketOf_[k] =
            static_cast<std::uint32_t>(cellHash(entries_[k].cx, entries_[k].cy) & (buckets - 1));
        ++bucketStart_[bucketOf_[k] + 1];
    }
    for (std::size_t b = 0; b < buckets; ++b)
        bucketStart_[b + 1] += bucketStart_[b];
    sorted_.resize(entries_.size());
    for (std::size_t k = 0; k < entries_.size(); ++k)
        sorted_[bucketStart_[bucketOf_[k]]++] = entries_[k];
    // bucketStart_[b] now holds the end of bucket b, which is where bucket b + 1 starts.
}

std::span<const CellBuckets::Entry> CellBuckets::bucketOf(std::int64_t cx, std::int64_t cy) const {
    const std::size_t b = cellHash(cx, cy) & (bucketStart_.size() - 2);
    const std::uint32_t begin = b == 0 ? 0 : bucketStart_[b - 1];
    return {sorted_.data() + begin, sorted_.data() + bucketStart_[b]};
}

void UniformGrid::findPairs(std::span<const Aabb> boxes, std::span<const ProxyKind> kinds,
                            std::vector<ProxyPair>& out, double cellSize) {
    out.clear();
    const auto n = static_cast<std::uint32_t>(boxes.size());
    if (!(cellSize > 0.0)) {
        const double extent =
            meanExtent(boxes, kinds, [](ProxyKind k) { return k == ProxyKind::Moving; });
        cellSize = extent > 0.0 ? 2.0 * extent : 1.0;
    }
    const double inv = 1.0 / cellSize;

    // Enter every box in the cells it covers (too big: aside).
    ranges_.resize(n);
    placed_.assign(n, 0);
    cells_.clear();
    oversize_.clear();
    for (std::uint32_t i = 0; i < n; ++i) {
        if (kinds[i] == ProxyKind::None) continue;
        const CellRange r{cellOf(boxes[i].lo.x, inv), cellOf(boxes[i].lo.y, inv),
                          cellOf(boxes[i].hi.x, inv), cellOf(boxes[i].hi.y, inv)};
        if (coversMoreThan(r.x0, r.y0, r.x1, r.y1, kMaxCellsPerBox)) {
            oversize_.push_back(i);
            continue;
        }
        ranges_[i] = r;
        placed_[i] = 1;
        for (std::int64_t cx = r.x0; cx <= r.x1; ++cx)
            for (std::int64_t cy = r.y0; cy <= r.y1; ++cy)
                cells_.add(cx, cy, i);
    }
    cells_.bucket();

    // Each box gathers its partners of higher index from the cells it covers (and among
    // the oversized boxes); sorted, they extend the sorted output. A pair sharing several
    // cells counts in the lowest of them, the low corner of where their cell ranges meet.
    // The tests of an entry are combined without branches: which entries pass is as good
    // as random, and a mispredicted branch costs more than the whole test.
    partners_.resize(n); // room for every partner a box can have
    for (std::uint32_t i = 0; i < n; ++i) {
        if (kinds[i] == ProxyKind::None) continue;
        std::uint32_t found = 0;
        auto meet = [&](std::uint32_t c) {
            if (pairable(kinds[i], kinds[c]) && boxes[i].overlaps(boxes[c])) partners_[found++] = c;
        };
        if (placed_[i]) {
            const CellRange& r = ranges_[i];
            const Aabb& box = boxes[i];
            const bool moving = kinds[i] == ProxyKind::Moving;
            for (std::int64_t cx = r.x0; cx <= r.x1; ++cx)
                for (std::int64_t cy = r.y0; cy <= r.y1; ++cy)
                    for (const CellBuckets::Entry& e : cells_.bucketOf(cx, cy)) {
                        const std::uint32_t c = e.id;
                        const CellRange& rc = ranges_[c];
                        const Aabb& o = boxes[c];
                        const std::int64_t lowX = std::max(r.x0, rc.x0),
                                           lowY = std::max(r.y0, rc.y0);
                        unsigned hit = c > i;
                        hit &= (e.cx == cx) & (e.cy == cy) & (lowX == cx) & (lowY == cy);
                        hit &= moving | (kinds[c] == ProxyKind::Moving);
                        hit &= (box.lo.x <= o.hi.x) & (o.lo.x <= box.hi.x);
                        hit &= (box.lo.y <= o.hi.y) & (o.lo.y <= box.hi.y);
                        partners_[found] = c;
                        found += hit;
                    }
            for (const std::uint32_t c : oversize_)
                if (c > i) meet(c);
        } else { // oversized: against every box after it
            for (std::uint32_t c = i + 1; c < n; ++c)
                if (kinds[c] != ProxyKind::None) meet(c);
        }
        std::sort(partners_.begin(), partners_.begin() + found);
        for (std::uint32_t k = 0; k < found; ++k)
            out.push_back({i, partners_[k]});
    }
}

void SortAndSweep::findPairs(std::span<const Aabb> boxes, std::span<const ProxyKind> kinds,
                             std::vector<ProxyPair>& out) {
    out.clear();
    const auto n = static_cast<std::uint32_t>(boxes.size());
    // Keep the previous order (nearly sorted frame to frame); add new proxies, drop gone ones.
    std::erase_if(order_, [&](std::uint32_t i) { return i >= n || kinds[i] == ProxyKind::None; });
    {
        // Mark which proxies are already in order_ using the active_ buffer as a bitmap.
        active_.assign(n, 0);
        for (auto i : order_)
            active_[i] = 1;
        for (std::uint32_t i = 0; i < n; ++i)
            if (!active_[i] && kinds[i] != ProxyKind::None) order_.push_back(i);
    }
    // Sweep axis: the larger spread of box centres.
    double mx = 0, my = 0, sx = 0, sy = 0;
    for (auto i : order_) {
        mx += boxes[i].lo.x + boxes[i].hi.x;
        my += boxes[i].lo.y + boxes[i].hi.y;
    }
    const double m = order_.empty() ? 1.0 : static_cast<double>(order_.size());
    mx /= m;
    my /= m;
    for (auto i : order_) {
        const double dx = boxes[i].lo.x + boxes[i].hi.x - mx,
                     dy = boxes[i].lo.y + boxes[i].hi.y - my;
        sx += dx * dx;
        sy += dy * dy;
    }
    const bool alongX = sx >= sy;
    auto lo = [&](std::uint32_t i) { return alongX ? boxes[i].lo.x : boxes[i].lo.y; };
    auto hi = [&](std::uint32_t i) { return alongX ? boxes[i].hi.x : boxes[i].hi.y; };
    // Ties broken by index, so the order (and so the pair list) never depends on history.
    std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
        return lo(a) < lo(b) || (lo(a) == lo(b) && a < b);
    });
    active_.clear();
    for (const std::uint32_t i : order_) {
        const double start = lo(i);
        // Close intervals that ended before this one starts.
        std::erase_if(active_, [&](std::uint32_t a) { return hi(a) < start; });
        for (const std::uint32_t a : active_)
            if (pairable(kinds[a], kinds[i]) && boxes[a].overlaps(boxes[i]))
                out.push_back(ordered(a, i));
        active_.push_back(i);
    }
    std::sort(out.begin(), out.end());
}

void BoxQueryGrid::build(std::span<const Aabb> boxes, std::span<const ProxyKind> kinds) {
    const auto n = static_cast<std::uint32_t>(boxes.size());
    const double extent =
        meanExtent(boxes, kinds, [](ProxyKind k) { return k != ProxyKind::None; });
    inv_ = 1.0 / (extent > 0.0 ? extent : 1.0);
    cells_.clear();
    oversize_.clear();
    for (std::uint32_t i = 0; i < n; ++i) {
        if (kinds[i] == ProxyKind::None) continue;
        const std::int64_t x0 = cellOf(boxes[i].lo.x, inv_), y0 = cellOf(boxes[i].lo.y, inv_),
                           x1 = cellOf(boxes[i].hi.x, inv_), y1 = cellOf(boxes[i].hi.y, inv_);
        if (coversMoreThan(x0, y0, x1, y1, UniformGrid::kMaxCellsPerBox)) {
            oversize_.push_back(i);
            continue;
        }
        for (std::int64_t cx = x0; cx <= x1; ++cx)
            for (std::int64_t cy = y0; cy <= y1; ++cy)
                cells_.add(cx, cy, i);
    }
    cells_.bucket();
    movedMark_.assign(n, 0);
    moved_.clear();
    listed_.assign(n, 0);
    queries_ = 0;
}

void BoxQueryGrid::moved(std::uint32_t i) {
    if (movedMark_[i]) return;
    movedMark_[i] = 1;
    moved_.push_back(i);
}

bool BoxQueryGrid::query(const Aabb& box, std::vector<std::uint32_t>& out) {
    const std::int64_t x0 = cellOf(box.lo.x, inv_), y0 = cellOf(box.lo.y, inv_),
                       x1 = cellOf(box.hi.x, inv_), y1 = cellOf(box.hi.y, inv_);
    if (!cells_.bucketed() || coversMoreThan(x0, y0, x1, y1, kMaxQueryCells)) return false;
    if (++queries_ == 0) { // the marks wrapped: clear them
        std::fill(listed_.begin(), listed_.end(), 0u);
        queries_ = 1;
    }
    auto list = [&](std::uint32_t i) {
        if (listed_[i] == queries_) return;
        listed_[i] = queries_;
        out.push_back(i);
    };
    for (std::int64_t cx = x0; cx <= x1; ++cx)
        for (std::int64_t cy = y0; cy <= y1; ++cy)
            for (const CellBuckets::Entry& e : cells_.bucketOf(cx, cy))
                if (e.cx == cx && e.cy == cy && !movedMark_[e.id]) list(e.id);
    for (const std::uint32_t i : oversize_)
        if (!movedMark_[i]) list(i);
    for (const std::uint32_t i : moved_)
        list(i);
    return true;
}

void StaticShapeIndex::update(const StaticShapes& shapes) {
    if (shapes.version() == version_ && shapes.count() == count_ && version_ != 0) return;
    version_ = shapes.version();
    count_ = shapes.count();
    boxes_.resize(count_);
    cellStart_.clear();
    items_.clear();
    oversize_.clear();
    nx_ = ny_ = 0;
    if (count_ == 0) return;
    Aabb all = shapes.bounds(shapes.ref(0));
    double extent = 0.0;
    for (std::size_t i = 0; i < count_; ++i) {
        const Aabb b = shapes.bounds(shapes.ref(i));
        boxes_[i] = b;
        all.lo = {std::min(all.lo.x, b.lo.x), std::min(all.lo.y, b.lo.y)};
        all.hi = {std::max(all.hi.x, b.hi.x), std::max(all.hi.y, b.hi.y)};
        extent += std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y);
    }
    // Cells about twice the mean shape size, at most ~64k of them over the shapes' bounds:
    // a world is indexed afresh for every trial shot, so a 20 km level must not cost
    // megabytes per index (a few shapes more per cell cost far less).
    const Vec2 size = all.hi - all.lo;
    cell_ = std::max({2.0 * extent / static_cast<double>(count_), 1e-3,
                      std::sqrt(std::max(size.x * size.y, 1e-12) / 65536.0)});
    origin_ = all.lo;
    nx_ = static_cast<std::int64_t>(size.x / cell_) + 1;
    ny_ = static_cast<std::int64_t>(size.y / cell_) + 1;
    // Counting sort of (cell, shape) entries into cellStart_/items_.
    std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
    auto cellsOf = [&](const Aabb& b, auto&& visit) {
        const std::int64_t x0 = static_cast<std::int64_t>((b.lo.x - origin_.x) / cell_);
        const std::int64_t x1 = static_cast<std::int64_t>((b.hi.x - origin_.x) / cell_);
        const std::int64_t y0 = static_cast<std::int64_t>((b.lo.y - origin_.y) / cell_);
        const std::int64_t y1 = static_cast<std::int64_t>((b.hi.y - origin_.y) / cell_);
        for (std::int64_t y = std::max<std::int64_t>(0, y0); y <= std::min(ny_ - 1, y1); ++y)
            for (std::int64_t x = std::max<std::int64_t>(0, x0); x <= std::min(nx_ - 1, x1); ++x)
                visit(static_cast<std::size_t>(y * nx_ + x));
    };
    auto cellCount = [&](const Aabb& b) {
        const double w = (b.hi.x - b.lo.x) / cell_ + 1.0, h = (b.hi.y - b.lo.y) / cell_ + 1.0;
        return w * h;
    };
    for (std::size_t i = 0; i < count_; ++i) {
        if (cellCount(boxes_[i]) > UniformGrid::kMaxCellsPerBox) {
            oversize_.push_back(static_cast<std::uint32_t>(i));
            continue;
        }
        cellsOf(boxes_[i], [&](std::size_t c) { ++count[c + 1]; });
    }
    for (std::size_t c = 1; c < count.size(); ++c)
        count[c] += count[c - 1];
    cellStart_ = count;
    items_.resize(count.back());
    for (std::size_t i = 0; i < count_; ++i) {
        if (cellCount(boxes_[i]) > UniformGrid::kMaxCellsPerBox) continue;
        cellsOf(boxes_[i],
                [&](std::size_t c) { items_[count[c]++] = static_cast<std::uint32_t>(i); });
    }
}

void StaticShapeIndex::query(const Aabb& box, std::vector<std::uint32_t>& out) const {
    out.clear();
    for (const std::uint32_t s : oversize_)
        if (boxes_[s].overlaps(box)) out.push_back(s);
    if (nx_ > 0) {
        const std::int64_t x0 =
            static_cast<std::int64_t>(std::floor((box.lo.x - origin_.x) / cell_));
        const std::int64_t x1 =
            static_cast<std::int64_t>(std::floor((box.hi.x - origin_.x) / cell_));
        const std::int64_t y0 =
            static_cast<std::int64_t>(std::floor((box.lo.y - origin_.y) / cell_));
        const std::int64_t y1 =
            static_cast<std::int64_t>(std::floor((box.hi.y - origin_.y) / cell_));
        for (std::int64_t y = std::max<std::int64_t>(0, y0); y <= std::min(ny_ - 1, y1); ++y)
            for (std::int64_t x = std::max<std::int64_t>(0, x0); x <= std::min(nx_ - 1, x1); ++x) {
                const std::size_t c = static_cast<std::size_t>(y * nx_ + x);
                for (std::uint32_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k)
                    if (boxes_[items_[k]].overlaps(box)) out.push_back(items_[k]);
            }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

} // namespace phys
