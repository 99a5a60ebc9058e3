#include "physics/collision/narrowphase.h"

#include <algorithm>
#include <array>
#include <bit>
#include <span>

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

// The candidates of `pairs`, in pair order. Most pairs of a pile start touching: their
// times need no search.
void NarrowPhase::findCandidates(const Substep& sub, const std::vector<ProxyPair>& pairs,
                                 const SubstepPaths& paths) {
    candidates_.clear();
    pairStarts_.resize(pairs.size());
    const PathDiscs discs{paths.paths(sub.set.slots()), sub.set.radius};
    classifyPairStarts(pairs, discs, sub.h, toi_, pairStarts_.data());
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const PairStart& start = pairStarts_[k];
        if (start.kind == PairStart::Search)
            addCandidate(sub, pairs[k], paths);
        else if (start.kind == PairStart::Contact && sub.def.particlePairs)
            candidates_.push_back(
                {pairs[k].first, pairs[k].second, {}, start.time, pairs[k].second, false});
    }
}

void NarrowPhase::addCandidate(const Substep& sub, ProxyPair pair, const SubstepPaths& paths) {
    const ParticleSet& set = sub.set;
    const auto n = static_cast<std::uint32_t>(set.slots());
    const std::uint32_t a = pair.first,
                        b = pair.second; // (clang 14 cannot capture a structured binding)
    if (b >= n) {
        if (!movable(set, a)) return;
        const ShapeRef ref = sub.shapes.ref(b - n);
        const auto t = withShape(sub.shapes, ref, [&](const auto& shape) {
            return timeOfImpact(shape, set.radius[a], paths.path(a), sub.h, toi_);
        });
        if (t) candidates_.push_back({a, kNoParticle, ref, *t, b, false});
    } else if (sub.def.particlePairs) {
        const PathMotion rel = paths.path(a).relativeTo(paths.path(b));
        const auto t =
            timeOfImpact(Circle{{0.0, 0.0}, set.radius[b]}, set.radius[a], rel, sub.h, toi_);
        if (t) candidates_.push_back({a, b, {}, *t, b, false});
    }
}

void NarrowPhase::mergeCarried(const std::vector<Candidate>& carried) {
    auto pairOrder = [](const Candidate& x, const Candidate& y) {
        return x.a < y.a || (x.a == y.a && x.proxy < y.proxy);
    };
    merged_.resize(candidates_.size() + carried.size());
    std::merge(candidates_.begin(), candidates_.end(), carried.begin(), carried.end(),
               merged_.begin(), pairOrder);
    candidates_.swap(merged_);
}

// Time order; ties in a fixed order so the result never depends on the sort: the order of
// the pairs (a, then b, shapes after particles, shapes in ref order), in which the
// candidates are listed. So a sort of (time, index) keys is enough.
void NarrowPhase::orderByTime() {
    order_.resize(candidates_.size());
    for (std::size_t k = 0; k < candidates_.size(); ++k)
        order_[k] = {candidates_[k].time, static_cast<std::uint32_t>(k)};
    phys::orderByTime(order_, orderScratch_);
}

} // namespace phys
