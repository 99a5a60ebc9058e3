#include "physics/collision/particle_collisions.h"

#include "physics/collision/contact_impulse.h"
#include "physics/collision/simd/pair_filter.h"
#include "physics/collision/simd/settled_scan.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <span>

namespace phys {

namespace {

constexpr std::uint32_t kHistory = kVerletPrimed | kLeapfrogPrimed;
// m/s: slower sliding than this is rounding residue of a stop, not motion.
constexpr double kRestSlide = 1e-9;

// Calls f with the concrete shape behind a reference (no virtual call per contact).
template <class F> auto withShape(const StaticShapes& shapes, ShapeRef ref, F&& f) {
    switch (ref.kind) {
    case ShapeKind::Circle:
        return f(shapes.circles[ref.index]);
    case ShapeKind::Polygon:
        return f(shapes.polygons[ref.index]);
    case ShapeKind::Segment:
        break;
    }
    return f(shapes.segments[ref.index]);
}

// Removes the part of `a` that pushes into the surface (normal n points out of it).
Vec2 withoutInward(Vec2 a, Vec2 n) {
    const double an = dot(a, n);
    return an < 0.0 ? a - n * an : a;
}

// Both components +0 (not -0): then v / h is +0 for any h > 0, without dividing.
bool isPositiveZero(Vec2 v) {
    return (std::bit_cast<std::uint64_t>(v.x) | std::bit_cast<std::uint64_t>(v.y)) == 0;
}

template <class T> void growTo(std::vector<T>& v, std::size_t n) {
    if (v.size() < n) v.resize(n);
}

// The limit of supports alternating between two surfaces, normals m (the first) and n:
// x, a rate (acceleration or velocity) that n's support left not pushing into n. If it
// pushes into m, taking that part away pushes it into n again when the two face each
// other (m.n < 0: a notch, a wedge), and so on: the alternation ends at rest between
// them. Otherwise (m.n >= 0) x slides along m, clear of n.
// (`rounding`: kVelocityRounding or kAccelRounding, as the time of impact takes them.)
Vec2 heldByBoth(Vec2 x, Vec2 m, Vec2 n, double rounding) {
    const double xm = dot(x, m);
    if (xm >= -rounding * atLeastOne(x)) return x;
    if (dot(m, n) < 0.0) return {};
    return x - m * xm;
}

bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

} // namespace

// One pass over the flags a sub-step (and over a sleeper's position and radius) finds the
// particles to work on, where a dozen passes over every particle did the work. A particle
// is settled when it is asleep at rest (velocity +0, as falling asleep leaves it) or its
// slot is empty, and its state is the one a sub-step worked on last, bit for bit, with
// the same tolerance (its boxes reach that far; at rest, they do not depend on the step),
// and no contact has changed its path since (markChanged). A sleeper the last sub-step
// worked on awake, or one that woke, has other flags than its record, so it is active.
void ParticleCollisions::selectActive(const ParticleSet& set, const CollisionDef& def, bool all) {
    const std::size_t n = set.slots();
    settledFlags_.resize(n, kUnsettled);
    settledX_.resize(n), settledY_.resize(n), settledRadius_.resize(n);
    activeMark_.resize(n);
    const bool sameTolerance = sameBits(def.toiTolerance, settledTolerance_);
    settledTolerance_ = def.toiTolerance;
    active_.resize(n);
    std::uint32_t* const active = active_.data();
    std::size_t count = 0;
    settledAsleep_ = 0;
    growTo(sleptAt_, n);
    wokeOrGone_.clear();
    // A sleeper that woke or went since the last sub-step (so one that is not settled).
    auto noteWaking = [&](std::size_t i, std::uint32_t f) {
        if (sleptAt_[i].radius > 0.0 && (f & (kAlive | kSleeping)) != (kAlive | kSleeping))
            wokeOrGone_.push_back(static_cast<std::uint32_t>(i));
    };
    const SettledRecords records{set.flags.data(),     set.vx.data(),    set.vy.data(),
                                 set.px.data(),        set.py.data(),    set.radius.data(),
                                 settledFlags_.data(), settledX_.data(), settledY_.data(),
                                 settledRadius_.data()};
    // Where a scan stops at once, the slots are likely awake: the next four one at a time.
    std::size_t scanFrom = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!all && sameTolerance && i >= scanFrom) {
            const std::size_t from = i;
            i = skipSettled(records, i, n, kAlive, kSleeping, activeMark_.data(), settledAsleep_);
            if (i == n) break;
            scanFrom = i == from ? i + 4 : i + 1;
        }
        const std::uint32_t f = set.flags[i];
        const bool rests =
            !all && (!(f & kAlive) || ((f & kSleeping) && isPositiveZero({set.vx[i], set.vy[i]})));
        active[count] = static_cast<std::uint32_t>(i);
        if (!rests) { // awake (or every particle): active, and not settled after
            noteWaking(i, f);
            activeMark_[i] = 1;
            ++count;
            settledFlags_[i] = kUnsettled;
            continue;
        }
        const bool settled =
            sameTolerance && f == settledFlags_[i] && sameBits(set.px[i], settledX_[i]) &&
            sameBits(set.py[i], settledY_[i]) && sameBits(set.radius[i], settledRadius_[i]);
        activeMark_[i] = settled ? 0 : 1;
        if (settled) {
            settledAsleep_ += (f & kAlive) ? 1 : 0;
            continue;
        }
        noteWaking(i, f);
        ++count;
        settledFlags_[i] = f;
        settledX_[i] = set.px[i], settledY_[i] = set.py[i], settledRadius_[i] = set.radius[i];
    }
    active_.resize(count);
    stats_.active += static_cast<int>(count);
}

void ParticleCollisions::beginSubstep(const ParticleSet& set) {
    const std::size_t n = set.slots();
    growTo(x0_, n), growTo(y0_, n), growTo(vx0_, n), growTo(vy0_, n);
    std::copy(set.px.begin(), set.px.end(), x0_.begin());
    std::copy(set.py.begin(), set.py.end(), y0_.begin());
    std::copy(set.vx.begin(), set.vx.end(), vx0_.begin());
    std::copy(set.vy.begin(), set.vy.end(), vy0_.begin());
}

// The parabola through the start and the end of the integrator's step (time_of_impact.h).
void ParticleCollisions::buildPaths(const ParticleSet& set, double h) {
    const std::size_t n = set.slots();
    growTo(path_, n), growTo(sv_, n), growTo(sa_, n), growTo(touched_, n), growTo(resting_, n);
    growTo(pathChanged_, n), growTo(accel0_, n), growTo(lastSupport_, n);
    const double k = 2.0 / (h * h);
    for (const std::uint32_t i : active_) {
        const Vec2 p0{x0_[i], y0_[i]}, v0{vx0_[i], vy0_[i]};
        const Vec2 p1{set.px[i], set.py[i]}, v1{set.vx[i], set.vy[i]};
        path_[i] = {p0, v0, (p1 - p0 - v0 * h) * k, 0.0};
        sv_[i] = v0;
        const Vec2 dv = v1 - v0;
        if (isPositiveZero(dv)) { // a sleeper, say: 0 / h is +0, no division, no root
            sa_[i] = {};
            accel0_[i] = 0.0;
        } else {
            sa_[i] = dv / h;
            accel0_[i] = length(sa_[i]);
        }
        touched_[i] = 0;
    }
}

void ParticleCollisions::buildProxies(const ParticleSet& set, const StaticShapes& shapes,
                                      const CollisionDef& def, double h, bool atEndOnly,
                                      double grow) {
    const std::size_t n = set.slots();
    boxes_.resize(n);
    kinds_.resize(n);
    staticIndex_.update(shapes);
    staticHits_.reserve(shapes.count()); // the most a query can return: no growth later
    // New slots: the live pairs are selected again before what these hold is read.
    if (liveKinds_.size() != n) {
        liveKinds_.resize(n, ProxyKind::None);
        kindsChanged_ = kindsRose_ = true;
    }
    boxed_.clear();
    for (const std::uint32_t i : active_)
        if (setProxyKind(set, i) != ProxyKind::None) boxed_.push_back(i);
    pathBoxes(boxed_, std::span<const PathMotion>(path_).first(n), set.radius,
              {h, grow, def.toiTolerance, atEndOnly}, boxes_.data());
}

void ParticleCollisions::boxSettlingForSolver(const ParticleSet& set, const CollisionDef& def) {
    solverBoxes_.resize(set.slots());
    for (const std::uint32_t i : active_) {
        if (settledFlags_[i] == kUnsettled || kinds_[i] == ProxyKind::None) continue;
        // At rest, and no contact changed its path: the solver's box of a path at rest
        // where it is.
        const PathMotion atRest{path_[i].p, {}, {}, 0.0};
        const Aabb box =
            pathBox(atRest, set.radius[i], {0.0, kSpeculative, def.toiTolerance, false});
        solverBoxes_[i] = box;
        // No solver checked this box against its fat box: one outside is checked (and the
        // cache mended) in the next sub-step, which works on it again.
        if (!(i < fatBoxes_.size() && fatBoxes_[i].contains(box))) settledFlags_[i] = kUnsettled;
    }
}

ProxyKind ParticleCollisions::setProxyKind(const ParticleSet& set, std::size_t i) {
    const ProxyKind kind = (set.flags[i] & (kAlive | kNoCollide)) != kAlive ? ProxyKind::None
                           : moving(set, i)                                 ? ProxyKind::Moving
                                                                            : ProxyKind::Resting;
    kindsChanged_ |= kind != liveKinds_[i];
    kindsRose_ |= pairsWithMore(kind, liveKinds_[i]);
    kinds_[i] = kind;
    return kind;
}

void ParticleCollisions::buildProxy(const ParticleSet& set, const CollisionDef& def, std::size_t i,
                                    double h, bool atEndOnly, double grow) {
    if (setProxyKind(set, i) != ProxyKind::None)
        boxes_[i] = pathBox(path_[i], set.radius[i], {h, grow, def.toiTolerance, atEndOnly});
}

// For the pair cache: room for half a radius of play (contacts push particles by up to
// centimetres in a pile) and a step of motion along the path the box was built from.
// Half a radius, not a whole one: in a packed pile the fat boxes of balls up to four
// radii apart overlap with a whole radius of play, up to three with half, so each pass
// filters 40 % fewer kept pairs (13,500 against 8,000 in the 2,000-ball pile, where
// 2,400 touch), for a few more mends while the pile still slides.
Aabb ParticleCollisions::fatBox(const ParticleSet& set, std::size_t i, double h) const {
    const double margin = kFatBoxPlay * set.radius[i] + length(path_[i].v) * h;
    return {boxes_[i].lo - Vec2{margin, margin}, boxes_[i].hi + Vec2{margin, margin}};
}

// The broad phase proper runs on fattened boxes (each particle's box grown by a margin
// and by a step of its motion) and its pairs are kept: a pass only filters them by the
// kinds of now and the exact boxes, which gives exactly the pairs a broad phase over the
// exact boxes would. That holds while every exact box lies in its fat box, no proxy can
// pair with more than when its pairs were found, and nothing else changed (slots,
// shapes, settings). A proxy that went to rest (Moving to Resting: a particle fell
// asleep) or away (to None) only loses pairs, so a pile whose particles fall asleep a few
// at a time keeps its broad phase; one more movable than at the build (Resting to Moving,
// None to anything) may have new pairs, as may one whose box left its fat box: these
// escaped the cache. A few escaped proxies are patched (patchPairCache); many, or any
// other change, rebuild the cache. A pile settling through eight passes a step, or
// resting for many steps, then costs one broad phase instead of one a pass.
ParticleCollisions::CacheState ParticleCollisions::checkPairCache(const CollisionDef& def) {
    const std::size_t n = boxes_.size();
    escaped_.clear();
    if (!cacheValid_ || fatBoxes_.size() != n || cachedShapes_ != staticIndex_.version() ||
        cachedBroadPhase_ != def.broadPhase || cachedCellSize_ != def.gridCellSize)
        return CacheState::Rebuild;
    // A settled particle passes: its kind and boxes are those it passed with (or that its
    // fat box was mended or rebuilt from), and the solver's box, kSpeculative radii
    // bigger than the passes', stays inside a fat box grown by kFatBoxPlay radii from
    // either (boxSettlingForSolver checks the one case where no solver did).
    for (const std::uint32_t i : active_) {
        const ProxyKind k = kinds_[i], f0 = fatKinds_[i];
        const bool fewerPairs = k == f0 || k == ProxyKind::None || f0 == ProxyKind::Moving;
        if (fewerPairs && (k == ProxyKind::None || fatBoxes_[i].contains(boxes_[i]))) continue;
        if (!def.patchPairs || escaped_.size() == kMostPatched) return CacheState::Rebuild;
        escaped_.push_back(i);
    }
    return escaped_.empty() ? CacheState::Holds : CacheState::Patch;
}

void ParticleCollisions::buildPairCache(const ParticleSet& set, const CollisionDef& def, double h) {
    const std::size_t n = boxes_.size();
    fatBoxes_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        fatBoxes_[i] = fatBox(set, i, h);
    fatKinds_ = kinds_;
    // Particle against particle: the chosen broad phase; each gives the pairs sorted.
    switch (def.broadPhase) {
    case BroadPhase::Grid:
        grid_.findPairs(fatBoxes_, fatKinds_, particlePairs_, def.gridCellSize);
        break;
    case BroadPhase::SortAndSweep:
        sweep_.findPairs(fatBoxes_, fatKinds_, particlePairs_);
        break;
    case BroadPhase::AllPairs:
        allPairs(fatBoxes_, fatKinds_, particlePairs_);
        break;
    }
    // Particle against static shape: moving particles look up the static index. A shape's
    // proxy number is slots + its index, as the narrow phase expects; these come out
    // sorted too, so one merge gives the whole list in order.
    const auto slots = static_cast<std::uint32_t>(n);
    staticPairs_.clear();
    for (std::uint32_t i = 0; i < slots; ++i) {
        if (fatKinds_[i] != ProxyKind::Moving) continue;
        staticIndex_.query(fatBoxes_[i], staticHits_);
        for (const std::uint32_t s : staticHits_)
            staticPairs_.push_back({i, slots + s});
    }
    cachedPairs_.resize(particlePairs_.size() + staticPairs_.size());
    std::merge(particlePairs_.begin(), particlePairs_.end(), staticPairs_.begin(),
               staticPairs_.end(), cachedPairs_.begin());
    takeCachedPairsAsLive();
    cacheValid_ = true;
    cachedShapes_ = staticIndex_.version();
    cachedBroadPhase_ = def.broadPhase;
    cachedCellSize_ = def.gridCellSize;
    fatGridStale_ = true;
    ++stats_.broadPhases;
}

bool ParticleCollisions::nearFatBoxes(const Aabb& box) {
    if (fatGridStale_ || fatGrid_.movedCount() > kMostMovedInGrid) {
        fatGrid_.build(fatBoxes_, fatKinds_);
        fatGridStale_ = false;
    }
    near_.clear();
    return fatGrid_.query(box, near_);
}

// The cache mended where proxies escaped it: each escaped proxy gets a new fat box and
// kind, loses its kept pairs, and is tested against the fat boxes near it (fatGrid_, or
// every proxy's if its box is too big for the grid) and looked up in the static index
// for new ones: a ball bouncing out of its box in a resting heap no longer rebuilds the
// heap's pairs, nor tests all of them. The cache stays a superset of the overlapping
// pairs, sorted, so the pairs a pass keeps, and the bits, are those a rebuild would give.
void ParticleCollisions::patchPairCache(const ParticleSet& set, double h) {
    const auto n = static_cast<std::uint32_t>(boxes_.size());
    growTo(escapedMark_, n);
    for (const std::uint32_t e : escaped_) {
        fatBoxes_[e] = fatBox(set, e, h);
        escapedMark_[e] = 1;
        if (!fatGridStale_) fatGrid_.moved(e);
    }
    // The pass over every kept pair is paid anyway, so it also drops the pairs the kinds
    // of now cannot make (both asleep, say), and the cache takes the kinds of now: a pile
    // falling asleep otherwise drags its early pairs through every patch (26,000 kept
    // against 9,400 live in the toppling 4,000-ball pile). A particle that wakes later
    // can pair with more than its cached kind, so it escapes and is patched in turn.
    auto dropped = [&](const ProxyPair& p) {
        const bool shape = p.second >= n;
        return escapedMark_[p.first] != 0 || (!shape && escapedMark_[p.second] != 0) ||
               !pairableAs(kinds_, p);
    };
    std::erase_if(particlePairs_, dropped);
    std::erase_if(staticPairs_, dropped);
    // Each kind went down or stayed (else the proxy escaped), and the query grid tests
    // the kinds of fatKinds_ at the time of the query, so it stands.
    fatKinds_ = kinds_;
    fresh_.clear();
    for (const std::uint32_t e : escaped_) {
        const ProxyKind ke = fatKinds_[e];
        if (ke == ProxyKind::None) continue;
        const Aabb& box = fatBoxes_[e];
        // Branchless: which proxies overlap is as good as random.
        auto test = [&](std::uint32_t c, std::size_t& found) {
            unsigned hit = (c != e) & pairable(ke, fatKinds_[c]);
            hit &= !(escapedMark_[c] != 0 && c < e); // a pair of two escaped ones: once
            hit &= box.overlapsBranchless(fatBoxes_[c]);
            fresh_[found] = c < e ? ProxyPair{c, e} : ProxyPair{e, c};
            found += hit;
        };
        std::size_t found = fresh_.size();
        if (nearFatBoxes(box)) {
            fresh_.resize(found + near_.size());
            for (const std::uint32_t c : near_)
                test(c, found);
        } else {
            fresh_.resize(found + n);
            for (std::uint32_t c = 0; c < n; ++c)
                test(c, found);
        }
        fresh_.resize(found);
        if (ke == ProxyKind::Moving) {
            staticIndex_.query(box, staticHits_);
            for (const std::uint32_t s : staticHits_)
                staticPairs_.push_back({e, n + s});
        }
    }
    for (const std::uint32_t e : escaped_)
        escapedMark_[e] = 0;
    std::sort(fresh_.begin(), fresh_.end());
    // (std::inplace_merge would take a buffer from the heap each time.)
    mergedPairs_.resize(particlePairs_.size() + fresh_.size());
    std::merge(particlePairs_.begin(), particlePairs_.end(), fresh_.begin(), fresh_.end(),
               mergedPairs_.begin());
    particlePairs_.swap(mergedPairs_);
    std::sort(staticPairs_.begin(), staticPairs_.end());
    cachedPairs_.resize(particlePairs_.size() + staticPairs_.size());
    std::merge(particlePairs_.begin(), particlePairs_.end(), staticPairs_.begin(),
               staticPairs_.end(), cachedPairs_.begin());
    ++stats_.cachePatches;
}

// The cached pairs the proxies can make with the kinds of now (at least one moving, none
// gone; a shape pairs only with a moving particle), again only when a kind changed: once
// a tick as particles fall asleep, not once a pass. The full cache is kept, so a
// particle that falls asleep and wakes again while its box stays in its fat box gets its
// pairs back without a broad phase (until a patch drops them: it is then patched).
// While kinds only fall (particles fall asleep: Moving to Resting), a pair live now was
// live before, so the live pairs of now are those of before that the kinds still make,
// in the same order: filtered from the last live pairs, not from the whole cache. As a
// pile falls asleep, a tick then filters a shrinking list, not the 8,000 kept pairs of the
// 2,000-ball pile each tick. Which pairs stay is a coin toss: each is written and the
// count moves on only if it stays.
void ParticleCollisions::selectLivePairs() {
    liveKinds_ = kinds_;
    const std::vector<ProxyPair>& from = kindsRose_ ? cachedPairs_ : livePairs_;
    const std::size_t count = from.size();
    if (kindsRose_) livePairs_.resize(count);
    const ProxyPair* in = from.data();
    ProxyPair* out = livePairs_.data(); // in place when from is livePairs_: out never passes in
    std::size_t kept = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const ProxyPair p = in[k];
        out[kept] = p;
        kept += isLive(p) ? 1 : 0;
    }
    livePairs_.resize(kept);
    kindsChanged_ = kindsRose_ = false;
}

// Right after a build or a patch every cached pair can pair with the kinds of the cache.
void ParticleCollisions::takeCachedPairsAsLive() {
    livePairs_ = cachedPairs_;
    liveKinds_ = fatKinds_;
    kindsChanged_ = kindsRose_ = false;
    ++cachedPairsVersion_;
}

void ParticleCollisions::findPairs(const ParticleSet& set, const CollisionDef& def, double h) {
    for (const std::uint32_t i : strays_) // the cache check below covers them
        strayMark_[i] = 0;
    strays_.clear();
    switch (checkPairCache(def)) {
    case CacheState::Rebuild:
        buildPairCache(set, def, h);
        break;
    case CacheState::Patch:
        patchPairCache(set, h);
        takeCachedPairsAsLive();
        break;
    case CacheState::Holds:
        break;
    }
    if (kindsChanged_) selectLivePairs();
    pairs_.resize(livePairs_.size());
    pairs_.resize(keepOverlapping(livePairs_, boxes_, staticIndex_.boxes(), pairs_.data()));
}

void ParticleCollisions::detect(const ParticleSet& set, const StaticShapes& shapes,
                                const CollisionDef& def, double h) {
    const auto t0 = clock_.now(); // profile only
    buildProxies(set, shapes, def, h, false);
    findPairs(set, def, h);
    stats_.pairs += static_cast<int>(pairs_.size());
    addCandidates(set, shapes, def, h);
    orderCandidates();
    ++pass_; // paths are as detected until a contact of this pass changes them
    detectMicros_ += clock_.microsSince(t0);
}

// The candidates of pairs_, in pair order. Most pairs of a pile start touching: their
// times need no search (pair_starts.h).
void ParticleCollisions::addCandidates(const ParticleSet& set, const StaticShapes& shapes,
                                       const CollisionDef& def, double h) {
    candidates_.clear();
    pairStarts_.resize(pairs_.size());
    const PathDiscs discs{std::span<const PathMotion>(path_).first(set.slots()), set.radius};
    classifyPairStarts(pairs_, discs, h, toi_, pairStarts_.data());
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
        const PairStart& start = pairStarts_[k];
        if (start.kind == PairStart::Search)
            addCandidate(set, shapes, def, pairs_[k], h);
        else if (start.kind == PairStart::Contact && def.particlePairs)
            candidates_.push_back(
                {pairs_[k].first, pairs_[k].second, {}, start.time, pairs_[k].second, false});
    }
}

void ParticleCollisions::addCandidate(const ParticleSet& set, const StaticShapes& shapes,
                                      const CollisionDef& def, ProxyPair pair, double h) {
    const auto n = static_cast<std::uint32_t>(set.slots());
    const std::uint32_t a = pair.first,
                        b = pair.second; // (clang 14 cannot capture a structured binding)
    if (b >= n) {
        if (!moving(set, a)) return;
        const ShapeRef ref = shapes.ref(b - n);
        const auto t = withShape(shapes, ref, [&](const auto& shape) {
            return timeOfImpact(shape, set.radius[a], path_[a], h, toi_);
        });
        if (t) candidates_.push_back({a, kNoParticle, ref, *t, b, false});
    } else if (def.particlePairs) {
        const PathMotion rel = path_[a].relativeTo(path_[b]);
        const auto t = timeOfImpact(Circle{{0.0, 0.0}, set.radius[b]}, set.radius[a], rel, h, toi_);
        if (t) candidates_.push_back({a, b, {}, *t, b, false});
    }
}

// Time order; ties in a fixed order so the result never depends on the sort: the order of
// the pairs (a, then b, shapes after particles, shapes in ref order), in which the
// candidates are listed. So a sort of (time, index) keys is enough.
void ParticleCollisions::orderCandidates() {
    order_.resize(candidates_.size());
    for (std::size_t k = 0; k < candidates_.size(); ++k)
        order_[k] = {candidates_[k].time, static_cast<std::uint32_t>(k)};
    orderByTime(order_, orderScratch_);
}

// Moves particle i's path start to time t (state velocity carried with its own rate).
void ParticleCollisions::rebase(std::size_t i, double t) {
    const PathMotion m = path_[i];
    sv_[i] = sv_[i] + sa_[i] * (t - m.t0);
    path_[i] = {m.position(t), m.velocity(t), m.a, t};
}

// supportAlong n, and a particle resting on two surfaces in one sub-step (a ball in the
// notch of two sleepers, or against a wall and a sleeper) held by both: the second
// support, along n, can bend its motion back into the first, along m, and the passes
// then alternated between the two, each taking a fraction of what was left, until they
// ran out (all eight, every step, for the last awake balls of a heap). Both hold it at
// once instead, as the alternation's limit (heldByBoth).
void ParticleCollisions::support(std::size_t i, Vec2 n, Vec2 vNew, const PairProperties& pp,
                                 double remaining, std::uint32_t surface) {
    supportAlong(i, n, vNew, pp, remaining);
    LastSupport& last = lastSupport_[i];
    if (last.substep == substep_ && last.surface != surface) {
        const Vec2 m0 = last.normal;
        PathMotion& m = path_[i];
        m.a = heldByBoth(m.a, m0, n, kAccelRounding);
        sa_[i] = heldByBoth(sa_[i], m0, n, kAccelRounding);
        m.v = heldByBoth(m.v, m0, n, kVelocityRounding);
        sv_[i] = heldByBoth(sv_[i], m0, n, kVelocityRounding);
    }
    last = {n, surface, substep_};
}

// Resting contact: the surface (normal n) carries particle i for the `remaining` time of
// the step. The inward part of its acceleration is removed (the normal force), and
// Coulomb friction acts through the acceleration, bounded by mu |a.n|:
// - not sliding and |a_t| <= mu_s |a.n|: static friction holds, no tangential motion;
// - sliding: dynamic friction decelerates at mu_d |a.n| against the slide; if that stops
//   the slide within the step (and static friction then holds), the particle ends the
//   step at the stopping point, v^2 / (2 a), at rest, rather than sliding back.
void ParticleCollisions::supportAlong(std::size_t i, Vec2 n, Vec2 vNew, const PairProperties& pp,
                                      double remaining) {
    PathMotion& m = path_[i];
    const double normalAccel = std::max(-std::min(dot(m.a, n), dot(sa_[i], n)), 0.0);
    m.a = withoutInward(m.a, n);
    sa_[i] = withoutInward(sa_[i], n);
    const Vec2 at = m.a - n * dot(m.a, n), sat = sa_[i] - n * dot(sa_[i], n);
    const Vec2 vt = vNew - n * dot(vNew, n);
    const double speedT = length(vt), accelT = length(at);
    const bool holds = accelT <= pp.staticFriction * normalAccel;
    if (speedT <= kRestSlide) {
        if (holds) {
            m.v -= vt; // (rounding residue)
            sv_[i] -= vt;
            m.a -= at;
            sa_[i] -= sat;
        } else { // starts to slide along a_t
            const Vec2 dir = at / accelT;
            m.a -= dir * (pp.dynamicFriction * normalAccel);
            sa_[i] -= dir * (pp.dynamicFriction * normalAccel);
        }
        return;
    }
    const Vec2 dir = vt / speedT;
    const double dec = pp.dynamicFriction * normalAccel - dot(at, dir); // net deceleration
    if (holds && dec > 0.0 && speedT <= dec * remaining && remaining > 0.0) {
        // Stops within the step: a straight path to the stopping point, and the state
        // velocity falls to zero at the end.
        const double stopDistance = speedT * speedT / (2.0 * dec);
        m.v = m.v - dir * dot(m.v, dir) + dir * (stopDistance / remaining);
        m.a -= at;
        sa_[i] = sa_[i] - sat - vt / remaining;
        return;
    }
    m.a -= dir * (pp.dynamicFriction * normalAccel);
    sa_[i] -= dir * (pp.dynamicFriction * normalAccel);
}

// Millington's resting-contact rule: closing slower than restingSpeed plus the speed the
// contact's acceleration builds in one step is resting. For a pair, that acceleration is
// at least what the forces on the two particles build (|a_i| + |a_j|) h: in a pile the
// contacts resolved before have taken the inward part of a particle's acceleration away,
// and the rest of the speed gravity gave it in this step must not count as a bounce.
double ParticleCollisions::restingLimit(std::size_t i, std::size_t j, double an,
                                        const CollisionDef& def, double h) const {
    return def.restingSpeed + std::max(std::max(-an, 0.0) * h, (accel0_[i] + accel0_[j]) * h);
}

ParticleCollisions::Resolution
ParticleCollisions::resolveStatic(const Candidate& c, ParticleSet& set, const StaticShapes& shapes,
                                  const MaterialTable& mats, const CollisionDef& def, double h,
                                  double tickTime) {
    const std::size_t i = c.a;
    const double r = set.radius[i];
    // The path may have changed since detection (an earlier contact in this pass); if it
    // has not, the time found then is the time (the same function of the same path).
    const auto toi = pathChanged_[i] != pass_
                         ? std::optional<double>(c.time)
                         : withShape(shapes, c.shape, [&](const auto& shape) {
                               return timeOfImpact(shape, r, path_[i], h, toi_);
                           });
    if (!toi) return Resolution::None;
    markChanged(i);
    rebase(i, *toi);
    PathMotion& m = path_[i];
    const SurfacePoint sp = shapes.closestPoint(c.shape, m.p);
    const Vec2 n = sp.normal;
    const double gap = sp.distance - r;
    if (gap < 0.0) m.p += n * (-gap); // started inside (spawned, pushed): project out

    const Vec2 v = sv_[i];
    const double vn = dot(v, n);
    // Inward acceleration: the larger of the path's and the state's (they differ only
    // for the Euler methods).
    const double an = std::min(dot(m.a, n), dot(sa_[i], n));
    const double w = set.invMass[i];
    const bool resting = -vn < def.restingSpeed + std::max(-an, 0.0) * h;
    const PairProperties& pp = mats.pair(set.material[i], shapes.material(c.shape));
    const double e = resting ? 0.0 : pp.restitution;
    const double remaining = h - *toi;
    const ContactImpulse ci = contactImpulse(v, n, w, 0.0, e, pp);
    Vec2 vNew = v + ci.impulse * w;
    m.v = vNew;
    sv_[i] = vNew;
    if (resting) support(i, n, vNew, pp, remaining, c.proxy);
    touched_[i] = 1;
    resting_[i] = resting_[i] || resting;
    set.flags[i] &= ~kSleeping;
    events_.push_back({static_cast<ParticleId>(i), kNoParticle, c.shape, tickTime + *toi, n, -vn,
                       ci.normal, resting, m.p, vNew});
    return resting ? Resolution::Resting : Resolution::Impact;
}

ParticleCollisions::Resolution ParticleCollisions::resolvePair(const Candidate& c, ParticleSet& set,
                                                               const MaterialTable& mats,
                                                               const CollisionDef& def, double h,
                                                               double tickTime, Vec2 up) {
    const std::size_t i = c.a, j = c.b;
    // A carried pair (later_passes.cpp) was left to the solver by the last pass, and no
    // contact has changed either path since: until one in this pass does, it meets the
    // same paths, velocities, masses and sleepers as then, and is left again. (A heap
    // whose last awake balls bounce through all eight passes carries hundreds a pass.)
    const bool unchanged = pathChanged_[i] != pass_ && pathChanged_[j] != pass_;
    if (c.carried && unchanged) return Resolution::Deferred;
    const double rj = set.radius[j], ri = set.radius[i];
    const auto toi = unchanged ? std::optional<double>(c.time)
                               : timeOfImpact(Circle{{0.0, 0.0}, rj}, ri,
                                              path_[i].relativeTo(path_[j]), h, toi_);
    if (!toi) return Resolution::None;
    // Sleeping particles count as immovable unless the impulse is big enough to wake them.
    double wi = moving(set, i) ? set.invMass[i] : 0.0;
    double wj = moving(set, j) ? set.invMass[j] : 0.0;
    {
        // Classify at the time of impact before changing anything: a resting contact
        // between two free particles (a pile) is left to the contact solver. So is a
        // sleeper lying on a free particle: that is weight the free one carries, not a
        // surface it rests on. Held up by it as by a ceiling, pushed down into what lies
        // under it (often another sleeper) and up again, the free one kept the passes busy
        // for all their number, every step, while part of a pile slept.
        const PathMotion pi = path_[i], pj = path_[j];
        const Vec2 d = pi.position(*toi) - pj.position(*toi);
        const double L = length(d);
        const Vec2 n = L > 0.0 ? d / L : Vec2{0.0, 1.0};
        const Vec2 vrel = (sv_[i] + sa_[i] * (*toi - pi.t0)) - (sv_[j] + sa_[j] * (*toi - pj.t0));
        const double an = std::min(dot(pi.a - pj.a, n), dot(sa_[i] - sa_[j], n));
        const double vn = dot(vrel, n);
        const bool bothFree = wi > 0.0 && wj > 0.0;
        const bool underSleeper =
            onSleeper(set, i, j, wi, wj) && dot(wi > 0.0 ? n : -n, up) < -kSupport;
        if (def.restingPairsToSolver && (bothFree || underSleeper) &&
            -vn < restingLimit(i, j, an, def, h)) {
            // Only its first deferral is reported (reportDeferred), and a carried pair
            // has one from a pass before.
            if (!c.carried)
                deferred_.push_back({(std::uint64_t{c.a} << 32) | c.b,
                                     static_cast<std::uint32_t>(deferred_.size()), tickTime + *toi,
                                     -vn, n, pi.position(*toi)});
            return Resolution::Deferred;
        }
    }
    markChanged(i);
    markChanged(j);
    rebase(i, *toi);
    rebase(j, *toi);
    PathMotion &mi = path_[i], &mj = path_[j];
    const Vec2 d = mi.p - mj.p;
    const double L = length(d);
    const Vec2 n = L > 0.0 ? d / L : Vec2{0.0, 1.0};
    const Vec2 vrel = sv_[i] - sv_[j];
    const double vn = dot(vrel, n);
    const double an = std::min(dot(mi.a - mj.a, n), dot(sa_[i] - sa_[j], n));
    const bool resting = -vn < restingLimit(i, j, an, def, h);
    const PairProperties& pp = mats.pair(set.material[i], set.material[j]);
    const double e = resting ? 0.0 : pp.restitution;
    ContactImpulse ci = contactImpulse(vrel, n, wi, wj, e, pp);
    // An impact wakes a sleeper it would move faster than sleepSpeed; resting on one
    // does not (it carries what rests on it, as a sleeping pile carries its top layer).
    for (const std::size_t k : {i, j}) {
        if (asleep(set, k) && !resting && ci.normal * set.invMass[k] > def.sleepSpeed) {
            set.flags[k] &= ~kSleeping;
            (k == i ? wi : wj) = set.invMass[k];
            ci = contactImpulse(vrel, n, wi, wj, e, pp);
        }
    }
    const double gap = L - ri - rj;
    if (gap < 0.0 && wi + wj > 0.0) { // overlapping at the start: separate by inverse mass
        mi.p += n * (-gap * wi / (wi + wj));
        mj.p -= n * (-gap * wj / (wi + wj));
    }
    sv_[i] += ci.impulse * wi;
    sv_[j] -= ci.impulse * wj;
    mi.v = sv_[i];
    mj.v = sv_[j];
    if (resting) {
        // Resting on something immovable (a fixed or sleeping particle): it carries the
        // other for the rest of the step as a static surface does, normal force and
        // Coulomb friction both (support). Without the friction a ball came to rest on a
        // sleeper slid off it however flat the contact.
        const double remaining = h - *toi;
        if (wj == 0.0) {
            support(i, n, sv_[i] - sv_[j], pp, remaining, static_cast<std::uint32_t>(j));
        } else if (wi == 0.0) {
            support(j, -n, sv_[j] - sv_[i], pp, remaining, static_cast<std::uint32_t>(i));
        } else {
            // Both free: they accelerate together along n (a plastic contact for the
            // rest of the step), sharing the momentum rate, weights m_i, m_j. What then
            // pushes one of them into a surface is resolved in the next pass.
            auto share = [&](Vec2& ai, Vec2& aj) {
                const double rel = dot(ai - aj, n);
                if (rel >= 0.0) return;
                ai -= n * (rel * wi / (wi + wj));
                aj += n * (rel * wj / (wi + wj));
            };
            share(mi.a, mj.a);
            share(sa_[i], sa_[j]);
        }
    }
    if (wi > 0.0) touched_[i] = 1, resting_[i] = resting_[i] || resting;
    if (wj > 0.0) touched_[j] = 1, resting_[j] = resting_[j] || resting;
    events_.push_back({static_cast<ParticleId>(i),
                       static_cast<ParticleId>(j),
                       {},
                       tickTime + *toi,
                       n,
                       -vn,
                       ci.normal,
                       resting,
                       mi.p,
                       sv_[i]});
    return resting ? Resolution::Resting : Resolution::Impact;
}

void ParticleCollisions::finish(ParticleSet& set, double h) {
    for (const std::uint32_t i : active_) {
        if (!touched_[i]) continue;
        const PathMotion& m = path_[i];
        const Vec2 p = m.position(h), v = sv_[i] + sa_[i] * (h - m.t0);
        set.px[i] = p.x, set.py[i] = p.y, set.vx[i] = v.x, set.vy[i] = v.y;
        set.flags[i] &= ~kHistory; // multi-step integrators restart from the bounced state
    }
}

void ParticleCollisions::impulsePhase(ParticleSet& set, const StaticShapes& shapes,
                                      const MaterialTable& mats, const CollisionDef& def, double h,
                                      double tickTime, Vec2 up) {
    toi_ = {def.continuous, def.bisectionHalvings, def.toiTolerance, def.maxAdvanceIterations};
    ++substep_;
    up_ = up;
    selectActive(set, def, !def.skipSettled);
    buildPaths(set, h);
    bool converged = false;
    deferred_.clear();
    for (int pass = 0; pass < def.maxPasses; ++pass) {
        if (pass == 0 || !def.redetectChangesOnly || !detectChanges(set, shapes, def, h))
            detect(set, shapes, def, h);
        changed_.clear(); // what this pass changes, for the next one
        leftToSolver_.assign(candidates_.size(), 0);
        ++stats_.passes;
        int resolved = 0;
        for (const TimeKey& key : order_) {
            const Candidate& c = candidates_[key.index];
            const Resolution r = c.b == kNoParticle
                                     ? resolveStatic(c, set, shapes, mats, def, h, tickTime)
                                     : resolvePair(c, set, mats, def, h, tickTime, up);
            resolved += r == Resolution::Resting || r == Resolution::Impact ? 1 : 0;
            leftToSolver_[key.index] = r == Resolution::Deferred ? 1 : 0;
        }
        stats_.impacts += resolved;
        converged = resolved == 0;
        if (converged) break;
    }
    finish(set, h);
    if (!converged || !deferred_.empty()) {
        relaxContacts(set, shapes, mats, def, h, up);
        reportDeferred(set);
    } else {
        warm_.clear(); // nothing to carry over to the next sub-step
        boxSettlingForSolver(set, def);
    }
    holdsOfWoken(set, def);
    wakeWhereHoldersMoved(set, def);
}

// The contacts left at the end of a sub-step that the passes did not settle (a pile, a
// stack, a particle wedged in a corner) are relaxed on the end state as contact
// constraints, by sequential impulses (Catto) with shock propagation:
//   velocity  sweeps of normal impulses remove every closing velocity (no bounce: what
//             still closes after the passes is resting), with Coulomb friction bounded by
//             mu_s times the contact's accumulated normal impulse;
//   position  sweeps push overlaps apart along the normal, split by inverse mass, at most
//             a fifth of a radius at a time and, in each band (below), the static
//             contacts last, so that a pile pressing on a wall never pushes a particle
//             through it. Velocities are left as the impulses made them, so the
//             projection adds no energy.
// Both steps sweep the contacts in one order, so one layout serves every sweep.
// After sweeps over all contacts, the contacts are swept again band by band from the
// ground up (a particle's level is how many particles down, holding each other up
// against gravity, it is from the ground: a static shape or an immovable particle), with
// the particle that holds the other up immovable once its band is done (shock
// propagation, Guendelman et al. 2003), so a stack is stopped and lifted from the
// bottom up instead of settling over many steps.
// Fixed and sleeping particles are immovable. A contact that needs nothing (not closing,
// not overlapping) changes nothing.
void ParticleCollisions::relaxContacts(ParticleSet& set, const StaticShapes& shapes,
                                       const MaterialTable& mats, const CollisionDef& def, double h,
                                       Vec2 up) {
    const auto t0 = clock_.now(); // profile only
    const std::size_t n = set.slots();
    // Boxes from where each particle started the step to where it ends: a shape whose
    // side it crossed in the step (the passes ran out) is found, and puts it back. (A
    // settled particle's path is this one too: at rest where it started.)
    for (const std::uint32_t i : active_) {
        const Vec2 start{x0_[i], y0_[i]};
        const Vec2 moved = set.position(static_cast<ParticleId>(i)) - start;
        path_[i] = {start, isPositiveZero(moved) ? Vec2{} : moved / h, {}, 0.0};
    }
    std::swap(boxes_, solverBoxes_);
    buildProxies(set, shapes, def, h, false, kSpeculative);
    findPairs(set, def, h);
    std::swap(boxes_, solverBoxes_);
    detectMicros_ += clock_.microsSince(t0);

    // The contacts: overlapping, touching, or nearly (speculative: a gap below
    // kSpeculative radii may close in one step, and the velocity sweeps allow it to close
    // no more than that), with something movable.
    const auto slots = static_cast<std::uint32_t>(n);
    contacts_.clear();
    // Every level is kUnsupported outside a solve (the solve puts its bodies' back).
    if (level_.size() < n) level_.resize(n, kUnsupported);
    growTo(bodyMark_, n), growTo(bodyIndex_, n);
    bodies_.clear();
    holds_.clear();
    nearPairs_.resize(pairs_.size());
    nearPairs_.resize(keepNear(pairs_, {set.px, set.py, set.radius}, def.toiTolerance, kSpeculative,
                               nearPairs_.data()));
    for (const NearPair& near : nearPairs_) {
        const std::uint32_t a = near.pair.first, b = near.pair.second;
        const bool isStatic = b >= slots;
        if (!isStatic && !def.particlePairs) continue;
        const double wa = moving(set, a) ? set.invMass[a] : 0.0;
        const double wb = !isStatic && moving(set, b) ? set.invMass[b] : 0.0;
        if (!(wa + wb > 0.0)) continue;
        // Built in place: a contact written field by field and then copied whole waits
        // for those writes to land (that copy was most of this loop's time).
        RelaxContact& c = contacts_.emplace_back();
        c.a = a;
        c.b = isStatic ? kNoParticle : b;
        c.proxy = b;
        c.normalImpulse = c.tangentImpulse = 0.0;
        if (isStatic) {
            c.shape = shapes.ref(b - slots);
            const SurfacePoint sp = shapes.closestPoint(c.shape, set.position(a));
            c.normal = sp.normal;
            c.depth = set.radius[a] - sp.distance;
            // A centre that crossed the shape in this step (a segment has two sides)
            // belongs on the side it started from: the contact pushes it back there.
            const SurfacePoint from = shapes.closestPoint(c.shape, {x0_[a], y0_[a]});
            if (dot(from.normal, sp.normal) < 0.0) {
                c.normal = from.normal;
                c.depth = set.radius[a] + sp.distance;
            }
            c.friction = mats.pair(set.material[a], shapes.material(c.shape)).staticFriction;
        } else { // near enough: keepNear tested the depth
            c.normal = near.normal;
            c.depth = near.depth;
            c.friction = mats.pair(set.material[a], set.material[b]).staticFriction;
        }
        const double reach = set.radius[a] + (isStatic ? 0.0 : set.radius[b]);
        if (isStatic && !nearEnough(c.depth, reach, def.toiTolerance, kSpeculative)) {
            contacts_.pop_back();
            continue;
        }
        if (c.depth < -def.toiTolerance) {
            // A gap: a constraint only if it closes as slowly as a resting contact would
            // (Millington's rule, restingLimit). One closing faster is an impact of the
            // next step, which the passes resolve at its time of impact with the pair's
            // e; held here to the speed the gap allows, it would lose its energy.
            const Vec2 vb = isStatic ? Vec2{} : set.velocity(b);
            const double approach = -dot(set.velocity(a) - vb, c.normal);
            const double accel = accel0_[a] + (isStatic ? 0.0 : accel0_[b]);
            if (approach > def.restingSpeed + accel * h) {
                contacts_.pop_back();
                continue;
            }
        }
        // The closing speed the gap allows; a gap within the slop counts as touching, so
        // that what projection left a hair apart does not keep closing on it for ever.
        c.closing = std::max(-c.depth - kSlop * reach, 0.0) / h;
        c.wa = wa, c.wb = wb;
        // Which side holds the other up against gravity, if either does (a wall or a
        // neighbour at the side holds nothing up).
        const double upward = dot(c.normal, up);
        c.support = upward > kSupport ? 1 : (!isStatic && upward < -kSupport ? -1 : 0);
        // Levels: immovable particles are ground (0), like the static shapes; what the
        // ground holds up is level 1 (the rest follows in orderContactsByLevel).
        if (wa == 0.0) level_[a] = 0;
        if (!isStatic && wb == 0.0) level_[b] = 0;
        if (c.support == 1 && wa > 0.0 && wb == 0.0) level_[a] = 1;
        if (c.support == -1 && wb > 0.0 && wa == 0.0) level_[b] = 1;
        addBody(a);
        if (!isStatic) addBody(b);
        // The particle below holds the one above up, when both can move.
        if (!isStatic && c.support != 0 && wa > 0.0 && wb > 0.0)
            holds_.push_back(c.support == 1 ? std::pair{b, a} : std::pair{a, b});
    }
    if (contacts_.empty()) {
        warm_.clear();
        return;
    }
    orderContactsByLevel();
    sweepContacts(set, shapes, def);

    // One pass over the contacts: their impulses, which start the next sub-step's sweeps;
    // whatever is in contact rests; the sleepers held up by a free particle (a contact
    // of two particles with one side immovable).
    warm_.clear();
    for (const RelaxContact& c : contacts_) {
        warm_.push_back({(std::uint64_t{c.a} << 32) | c.proxy, c.normalImpulse, c.tangentImpulse});
        resting_[c.a] = 1;
        if (c.b == kNoParticle) continue;
        resting_[c.b] = 1;
        if (c.wa == 0.0 || c.wb == 0.0) collectHold(set, c);
    }
    // Whatever moved restarts its multi-step integrator.
    for (const std::uint32_t i : bodies_) {
        if (touched_[i]) set.flags[i] &= ~kHistory;
        bodyMark_[i] = 0;
        level_[i] = kUnsupported;
    }
}

// The resting pairs the passes left to the solver are contacts of the tick too (a shell
// settling on a heap has touched it): one event per pair and sub-step, at the time the
// passes first found it, with the normal impulse the solver gave it.
void ParticleCollisions::reportDeferred(const ParticleSet& set) {
    if (deferred_.empty()) return;
    std::sort(deferred_.begin(), deferred_.end(), [](const Deferred& x, const Deferred& y) {
        return x.key < y.key || (x.key == y.key && x.order < y.order);
    });
    std::size_t k = 0;
    for (std::size_t d = 0; d < deferred_.size(); ++d) {
        const Deferred& e = deferred_[d];
        if (d > 0 && deferred_[d - 1].key == e.key) continue; // found again by a later pass
        const auto a = static_cast<ParticleId>(e.key >> 32), b = static_cast<ParticleId>(e.key);
        double impulse = 0.0;
        while (k < contacts_.size() &&
               ((std::uint64_t{contacts_[k].a} << 32) | contacts_[k].proxy) < e.key)
            ++k;
        if (k < contacts_.size() &&
            ((std::uint64_t{contacts_[k].a} << 32) | contacts_[k].proxy) == e.key)
            impulse = contacts_[k].normalImpulse;
        events_.push_back({a,
                           b,
                           {},
                           e.time,
                           e.normal,
                           e.closingSpeed,
                           impulse,
                           true,
                           e.position,
                           set.velocity(a)});
    }
}

// contactOrder_: the contacts by band (the level of their upper particle), those with
// something immovable last in each band, a counting sort, so the pair order, which is
// fixed, breaks ties. Levels spread from the particles the ground holds up (level 1) to
// the particles they hold up, breadth first; particles that nothing connects to the
// ground this way come last. A particle's level is its distance from the ground, whatever
// order the search takes them in. Only the contacts' particles (bodies_) are counted, by
// their places there.
void ParticleCollisions::orderContactsByLevel() {
    const std::size_t n = bodies_.size();
    // Who holds whom up, among the movable particles: offsets into a flat list.
    adjacencyStart_.assign(n + 1, 0u);
    for (const auto& [holder, held] : holds_)
        ++adjacencyStart_[bodyIndex_[holder] + 1];
    for (std::size_t i = 0; i < n; ++i)
        adjacencyStart_[i + 1] += adjacencyStart_[i];
    adjacency_.resize(adjacencyStart_[n]);
    fill_.assign(adjacencyStart_.begin(), adjacencyStart_.end() - 1);
    for (const auto& [holder, held] : holds_)
        adjacency_[fill_[bodyIndex_[holder]]++] = held;
    // Breadth first from the ground.
    frontier_.clear();
    for (const std::uint32_t i : bodies_)
        if (level_[i] == 1) frontier_.push_back(i);
    for (std::size_t head = 0; head < frontier_.size(); ++head) {
        const std::uint32_t p = frontier_[head], at = bodyIndex_[p];
        for (std::uint32_t k = adjacencyStart_[at]; k < adjacencyStart_[at + 1]; ++k) {
            const std::uint32_t q = adjacency_[k];
            if (level_[q] != kUnsupported) continue;
            level_[q] = level_[p] + 1;
            frontier_.push_back(q);
        }
    }
    // Bands: a contact belongs to the level of its upper particle (a static contact to its
    // particle's); band 0 is never used (the ground does not move), the last band holds
    // what no path of contacts connects to the ground. Within a band, the contacts with
    // something immovable (a shape, a fixed or sleeping particle) come after the others:
    // the projection then leaves nothing inside those, whatever else stays to do.
    std::uint32_t top = 1;
    for (const std::uint32_t i : bodies_)
        if (level_[i] != kUnsupported) top = std::max(top, level_[i]);
    const std::size_t unsupported = static_cast<std::size_t>(top) + 1;
    auto key = [&](const RelaxContact& c) -> std::size_t {
        const std::uint32_t l = bandOf(c);
        const bool immovableSide = c.b == kNoParticle || c.wa == 0.0 || c.wb == 0.0;
        return 2 * (l == kUnsupported ? unsupported : l) + (immovableSide ? 1 : 0);
    };
    // Each contact's key once, in a column the placing pass reads instead of the contacts.
    keyStart_.assign(2 * unsupported + 3, 0u);
    contactKey_.resize(contacts_.size());
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
        const auto bucket = static_cast<std::uint32_t>(key(contacts_[k]));
        contactKey_[k] = bucket;
        ++keyStart_[bucket + 1];
    }
    for (std::size_t k = 0; k + 1 < keyStart_.size(); ++k)
        keyStart_[k + 1] += keyStart_[k];
    bandStart_.resize(unsupported + 2);
    for (std::size_t b = 0; b < bandStart_.size(); ++b)
        bandStart_[b] = keyStart_[2 * b];
    contactOrder_.resize(contacts_.size());
    for (std::uint32_t k = 0; k < contacts_.size(); ++k)
        contactOrder_[keyStart_[contactKey_[k]]++] = k;
}

void ParticleCollisions::penaltyPhase(ParticleSet& set, const StaticShapes& shapes,
                                      const MaterialTable& mats, const CollisionDef& def, double h,
                                      double tickTime) {
    const auto t0 = clock_.now(); // profile only
    selectActive(set, def, true);
    buildPaths(set, h);
    buildProxies(set, shapes, def, h, true);
    findPairs(set, def, h);
    stats_.pairs += static_cast<int>(pairs_.size());
    ++stats_.passes;
    detectMicros_ += clock_.microsSince(t0);
    const auto n = static_cast<std::uint32_t>(set.slots());
    for (const ProxyPair& pair : pairs_) {
        const std::uint32_t a = pair.first, b = pair.second;
        const bool isStatic = b >= n;
        if (!isStatic && !def.particlePairs) continue;
        const Vec2 pa = set.position(a);
        SurfacePoint sp;
        double reach = set.radius[a];
        ShapeRef ref{};
        if (isStatic) {
            ref = shapes.ref(b - n);
            sp = shapes.closestPoint(ref, pa);
        } else {
            const Vec2 dv = pa - set.position(b);
            const double L = length(dv);
            sp = {L, L > 0.0 ? dv / L : Vec2{0.0, 1.0}};
            reach += set.radius[b];
        }
        const double depth = reach - sp.distance;
        if (!(depth > 0.0)) continue;
        const double wa = moving(set, a) ? set.invMass[a] : 0.0;
        const double wb = isStatic || !moving(set, b) ? 0.0 : set.invMass[b];
        const Vec2 vrel = set.velocity(a) - (isStatic ? Vec2{} : set.velocity(b));
        const PairProperties& pp =
            mats.pair(set.material[a], isStatic ? shapes.material(ref) : set.material[b]);
        const double vn = dot(vrel, sp.normal);
        const double jn = penaltyImpulse(depth, vn, wa, wb, pp.restitution, def.penaltyHertz, h);
        // Dynamic friction only (a spring contact has no sticking state), never reversing.
        const Vec2 vt = vrel - sp.normal * vn;
        const double speedT = length(vt);
        Vec2 J = sp.normal * jn;
        if (speedT > 0.0 && wa + wb > 0.0)
            J -= vt / speedT * std::min(pp.dynamicFriction * jn, speedT / (wa + wb));
        set.vx[a] += J.x * wa, set.vy[a] += J.y * wa;
        set.flags[a] &= ~(kHistory | kSleeping);
        if (!isStatic) {
            set.vx[b] -= J.x * wb, set.vy[b] -= J.y * wb;
            if (wb > 0.0) set.flags[b] &= ~(kHistory | kSleeping);
        }
        events_.push_back({a, isStatic ? kNoParticle : b, ref, tickTime + h, sp.normal, -vn, jn,
                           false, pa, set.velocity(a)});
        ++stats_.impacts;
    }
}

// A particle in resting contact is still when its velocity is below sleepSpeed, or when
// its motion is: it has strayed less than sleepSpeed * sleepTime from where its rest
// window started (restAnchor_), a mean velocity below sleepSpeed. Either alone misses a
// kind of rest. The velocity misses a particle wedged between sleepers, or a cluster the
// contact solver leaves with a residual velocity that the position projection undoes
// every step: they report centimetres per second and go nowhere. The motion misses a
// particle the projection nudges a fraction of a millimetre a step while it has no
// velocity at all. After sleepTime still, it sleeps. A steady slide at sleepSpeed or
// faster fails both; so does any tick without a resting contact.
void ParticleCollisions::updateSleep(ParticleSet& set, const CollisionDef& def, double dt,
                                     const std::vector<std::uint8_t>& tethered) {
    const std::size_t n = set.slots();
    growTo(sleepTimer_, n), growTo(resting_, n), growTo(restAnchor_, n);
    auto restartWindow = [&](std::size_t i) {
        sleepTimer_[i] = 0.0;
        restAnchor_[i] = set.position(i);
    };
    if (restTimersStale_) { // what updateSleep would have done in the ticks without contacts
        for (std::size_t i = 0; i < n; ++i)
            if (!(set.flags[i] & kSleeping)) restartWindow(i);
        restTimersStale_ = false;
    }
    const double stray = def.sleepSpeed * def.sleepTime; // m: the window's allowed drift
    int asleep = static_cast<int>(settledAsleep_);       // settled: asleep, and stays so
    const std::size_t holds = held_.size();
    for (const std::uint32_t i : active_) {
        if (set.flags[i] & kSleeping) {
            asleep += (set.flags[i] & kAlive) ? 1 : 0;
            continue;
        }
        const bool resting = def.sleep && resting_[i] &&
                             !(i < tethered.size() && tethered[i]) && moving(set, i);
        resting_[i] = 0;
        const bool slow = lengthSquared(set.velocity(i)) < def.sleepSpeed * def.sleepSpeed;
        const bool stayed = lengthSquared(set.position(i) - restAnchor_[i]) <= stray * stray;
        if (!resting || !(slow || stayed)) {
            restartWindow(i);
            continue;
        }
        if (!stayed) restAnchor_[i] = set.position(i); // slow but drifting: measure anew
        sleepTimer_[i] += dt;
        if (sleepTimer_[i] >= def.sleepTime) {
            set.flags[i] = (set.flags[i] | kSleeping) & ~kHistory;
            sleptAt_[i] = {set.px[i], set.py[i], set.radius[i]};
            holdsOfNewSleeper(set, def, i);
            set.vx[i] = set.vy[i] = 0.0;
            set.halfVx[i] = set.halfVy[i] = 0.0;
            restartWindow(i);
            ++asleep;
        }
    }
    if (held_.size() != holds) sortHolds(); // a new sleeper held up by awake particles
    wakeHeldSleepers(set, asleep);
    stats_.sleeping = asleep;
}

} // namespace phys
