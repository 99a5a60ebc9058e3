#include "physics/collision/particle_collisions.h"

#include "physics/collision/contact_resolver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace phys {

namespace {

constexpr std::uint32_t kHistory = kVerletPrimed | kLeapfrogPrimed;
// m/s: slower sliding than this is rounding residue of a stop, not motion.
constexpr double kRestSlide = 1e-9;
// Sweeps over the particle pairs when projecting overlaps apart (after one over the
// static contacts); each sweep shrinks what the previous one left.
constexpr int kProjectionSweeps = 4;

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

template <class T> void growTo(std::vector<T>& v, std::size_t n) {
    if (v.size() < n) v.resize(n);
}

} // namespace

void ParticleCollisions::beginSubstep(const ParticleSet& set) {
    const std::size_t n = set.slots();
    growTo(x0_, n), growTo(y0_, n), growTo(vx0_, n), growTo(vy0_, n);
    std::copy(set.px.begin(), set.px.end(), x0_.begin());
    std::copy(set.py.begin(), set.py.end(), y0_.begin());
    std::copy(set.vx.begin(), set.vx.end(), vx0_.begin());
    std::copy(set.vy.begin(), set.vy.end(), vy0_.begin());
}

// The parabola through the start and the end of the integrator's step (narrowphase.h).
void ParticleCollisions::buildPaths(const ParticleSet& set, double h) {
    const std::size_t n = set.slots();
    growTo(path_, n), growTo(sv_, n), growTo(sa_, n), growTo(touched_, n), growTo(resting_, n);
    const double k = 2.0 / (h * h);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 p0{x0_[i], y0_[i]}, v0{vx0_[i], vy0_[i]};
        const Vec2 p1{set.px[i], set.py[i]}, v1{set.vx[i], set.vy[i]};
        path_[i] = {p0, v0, (p1 - p0 - v0 * h) * k, 0.0};
        sv_[i] = v0;
        sa_[i] = (v1 - v0) / h;
        touched_[i] = 0;
    }
}

void ParticleCollisions::buildProxies(const ParticleSet& set, const StaticShapes& shapes,
                                      const CollisionDef& def, double h, bool atEndOnly) {
    const std::size_t n = set.slots();
    boxes_.resize(n);
    kinds_.resize(n);
    staticIndex_.update(shapes);
    staticHits_.reserve(shapes.count()); // the most a query can return: no growth later
    for (std::size_t i = 0; i < n; ++i) {
        if ((set.flags[i] & (kAlive | kNoCollide)) != kAlive) {
            kinds_[i] = ProxyKind::None;
            continue;
        }
        kinds_[i] = moving(set, i) ? ProxyKind::Moving : ProxyKind::Resting;
        const PathMotion& m = path_[i];
        const Vec2 end = m.position(h);
        // A quadratic path lies in the triangle of its Bezier control points:
        // start, start + v T/2, end.
        const Vec2 mid = m.p + m.v * (0.5 * (h - m.t0));
        Vec2 lo = end, hi = end;
        if (!atEndOnly)
            for (const Vec2 q : {m.p, mid}) {
                lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
                hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
            }
        const double r = set.radius[i] + def.toiTolerance;
        boxes_[i] = {lo - Vec2{r, r}, hi + Vec2{r, r}};
    }
}

void ParticleCollisions::findPairs(const CollisionDef& def) {
    // Particle against particle: the chosen broad phase over the particles' boxes.
    switch (def.broadPhase) {
    case BroadPhase::Grid:
        grid_.findPairs(boxes_, kinds_, pairs_, def.gridCellSize);
        break;
    case BroadPhase::SortAndSweep:
        sweep_.findPairs(boxes_, kinds_, pairs_);
        break;
    case BroadPhase::AllPairs:
        allPairs(boxes_, kinds_, pairs_);
        break;
    }
    // Particle against static shape: moving particles look up the static index. A shape's
    // proxy number is slots + its index, as the narrow phase expects.
    const auto n = static_cast<std::uint32_t>(boxes_.size());
    for (std::uint32_t i = 0; i < n; ++i) {
        if (kinds_[i] != ProxyKind::Moving) continue;
        staticIndex_.query(boxes_[i], staticHits_);
        for (const std::uint32_t s : staticHits_) pairs_.push_back({i, n + s});
    }
    std::sort(pairs_.begin(), pairs_.end());
}

void ParticleCollisions::detect(const ParticleSet& set, const StaticShapes& shapes,
                                const CollisionDef& def, double h) {
    const auto t0 = std::chrono::steady_clock::now(); // profile only
    buildProxies(set, shapes, def, h, false);
    findPairs(def);
    stats_.pairs += static_cast<int>(pairs_.size());
    candidates_.clear();
    const auto n = static_cast<std::uint32_t>(set.slots());
    for (const ProxyPair& pair : pairs_) {
        const std::uint32_t a = pair.first, b = pair.second; // (clang 14 cannot capture a structured binding)
        if (b >= n) {
            if (!moving(set, a)) continue;
            const ShapeRef ref = shapes.ref(b - n);
            const auto t = withShape(shapes, ref, [&](const auto& shape) {
                return timeOfImpact(shape, set.radius[a], path_[a], h, toi_);
            });
            if (t) candidates_.push_back({a, kNoParticle, ref, *t});
        } else if (def.particlePairs) {
            const PathMotion rel = path_[a].relativeTo(path_[b]);
            const auto t =
                timeOfImpact(Circle{{0.0, 0.0}, set.radius[b]}, set.radius[a], rel, h, toi_);
            if (t) candidates_.push_back({a, b, {}, *t});
        }
    }
    // Time order; ties in a fixed order so the result never depends on the sort.
    std::sort(candidates_.begin(), candidates_.end(), [](const Candidate& x, const Candidate& y) {
        if (x.time != y.time) return x.time < y.time;
        if (x.a != y.a) return x.a < y.a;
        if (x.b != y.b) return x.b < y.b;
        if (x.shape.kind != y.shape.kind) return x.shape.kind < y.shape.kind;
        return x.shape.index < y.shape.index;
    });
    detectMicros_ +=
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
}

// Moves particle i's path start to time t (state velocity carried with its own rate).
void ParticleCollisions::rebase(std::size_t i, double t) {
    const PathMotion m = path_[i];
    sv_[i] = sv_[i] + sa_[i] * (t - m.t0);
    path_[i] = {m.position(t), m.velocity(t), m.a, t};
}

// Resting contact: the surface (normal n) carries particle i for the `remaining` time of
// the step. The inward part of its acceleration is removed (the normal force), and
// Coulomb friction acts through the acceleration, bounded by mu |a.n|:
// - not sliding and |a_t| <= mu_s |a.n|: static friction holds, no tangential motion;
// - sliding: dynamic friction decelerates at mu_d |a.n| against the slide; if that stops
//   the slide within the step (and static friction then holds), the particle ends the
//   step at the stopping point, v^2 / (2 a), at rest, rather than sliding back.
void ParticleCollisions::support(std::size_t i, Vec2 n, Vec2 vNew, const PairProperties& pp,
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

bool ParticleCollisions::resolveStatic(const Candidate& c, ParticleSet& set,
                                       const StaticShapes& shapes, const MaterialTable& mats,
                                       const CollisionDef& def, double h, double tickTime) {
    const std::size_t i = c.a;
    const double r = set.radius[i];
    // The path may have changed since detection (an earlier contact in this pass).
    const auto toi = withShape(shapes, c.shape, [&](const auto& shape) {
        return timeOfImpact(shape, r, path_[i], h, toi_);
    });
    if (!toi) return false;
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
    if (resting) support(i, n, vNew, pp, remaining);
    touched_[i] = 1;
    resting_[i] = resting_[i] || resting;
    set.flags[i] &= ~kSleeping;
    events_.push_back({static_cast<ParticleId>(i), kNoParticle, c.shape, tickTime + *toi, n, -vn,
                       ci.normal, resting, m.p, vNew});
    return true;
}

bool ParticleCollisions::resolvePair(const Candidate& c, ParticleSet& set,
                                     const MaterialTable& mats, const CollisionDef& def, double h,
                                     double tickTime) {
    const std::size_t i = c.a, j = c.b;
    const double ri = set.radius[i], rj = set.radius[j];
    const auto toi =
        timeOfImpact(Circle{{0.0, 0.0}, rj}, ri, path_[i].relativeTo(path_[j]), h, toi_);
    if (!toi) return false;
    rebase(i, *toi);
    rebase(j, *toi);
    PathMotion &mi = path_[i], &mj = path_[j];
    const Vec2 d = mi.p - mj.p;
    const double L = length(d);
    const Vec2 n = L > 0.0 ? d / L : Vec2{0.0, 1.0};
    // Sleeping particles count as immovable unless the impulse is big enough to wake them.
    double wi = moving(set, i) ? set.invMass[i] : 0.0;
    double wj = moving(set, j) ? set.invMass[j] : 0.0;
    const Vec2 vrel = sv_[i] - sv_[j];
    const double vn = dot(vrel, n);
    const double an = std::min(dot(mi.a - mj.a, n), dot(sa_[i] - sa_[j], n));
    const bool resting = -vn < def.restingSpeed + std::max(-an, 0.0) * h;
    const PairProperties& pp = mats.pair(set.material[i], set.material[j]);
    const double e = resting ? 0.0 : pp.restitution;
    ContactImpulse ci = contactImpulse(vrel, n, wi, wj, e, pp);
    for (const std::size_t k : {i, j}) {
        const bool asleep = (set.flags[k] & kSleeping) && set.invMass[k] > 0.0;
        if (asleep && ci.normal * set.invMass[k] > def.sleepSpeed) {
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
    if (resting) {
        if (wj == 0.0) { // resting on something immovable: it carries i for the rest of the step
            mi.a = withoutInward(mi.a, n), sa_[i] = withoutInward(sa_[i], n);
        } else if (wi == 0.0) {
            mj.a = withoutInward(mj.a, -n), sa_[j] = withoutInward(sa_[j], -n);
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
    mi.v = sv_[i];
    mj.v = sv_[j];
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
    return true;
}

void ParticleCollisions::finish(ParticleSet& set, double h) {
    for (std::size_t i = 0; i < set.slots(); ++i) {
        if (!touched_[i]) continue;
        const PathMotion& m = path_[i];
        const Vec2 p = m.position(h), v = sv_[i] + sa_[i] * (h - m.t0);
        set.px[i] = p.x, set.py[i] = p.y, set.vx[i] = v.x, set.vy[i] = v.y;
        set.flags[i] &= ~kHistory; // multi-step integrators restart from the bounced state
    }
}

void ParticleCollisions::impulsePhase(ParticleSet& set, const StaticShapes& shapes,
                                      const MaterialTable& mats, const CollisionDef& def, double h,
                                      double tickTime) {
    toi_ = {def.continuous, def.bisectionHalvings, def.toiTolerance, def.maxAdvanceIterations};
    buildPaths(set, h);
    bool converged = false;
    for (int pass = 0; pass < def.maxPasses; ++pass) {
        detect(set, shapes, def, h);
        ++stats_.passes;
        int resolved = 0;
        for (const Candidate& c : candidates_) {
            const bool done = c.b == kNoParticle
                                  ? resolveStatic(c, set, shapes, mats, def, h, tickTime)
                                  : resolvePair(c, set, mats, def, h, tickTime);
            resolved += done ? 1 : 0;
        }
        stats_.impacts += resolved;
        converged = resolved == 0;
        if (converged) break;
    }
    finish(set, h);
    if (!converged) projectOverlaps(set, shapes, def, h);
}

// The passes ran out with contacts still being resolved (a stack settling, a particle
// wedged in a corner): whatever still overlaps at the end of the step is pushed apart
// along the normal (split by inverse mass) and loses its closing velocity, so nothing
// is left inside anything, and nothing falls asleep inside anything.
void ParticleCollisions::projectOverlaps(ParticleSet& set, const StaticShapes& shapes,
                                         const CollisionDef& def, double h) {
    const auto t0 = std::chrono::steady_clock::now(); // profile only
    for (std::size_t i = 0; i < set.slots(); ++i)
        path_[i] = {set.position(static_cast<ParticleId>(i)), {}, {}, h};
    buildProxies(set, shapes, def, h, true);
    findPairs(def);
    detectMicros_ +=
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
    // Shock propagation (Guendelman et al. 2003): contacts with static shapes first; a
    // particle pushed out of one counts as immovable for the particle pairs after it,
    // and so does one pushed off a particle that was, so a stack is lifted from the
    // bottom up in one sweep instead of settling over many.
    const auto n = static_cast<std::uint32_t>(set.slots());
    std::fill(touched_.begin(), touched_.end(), 0); // reused as "supported"
    for (int sweep = 0; sweep < 1 + kProjectionSweeps; ++sweep)
        for (const ProxyPair& pair : pairs_) {
            const std::uint32_t a = pair.first, b = pair.second;
            const bool isStatic = b >= n;
            if (isStatic != (sweep == 0) || (!isStatic && !def.particlePairs)) continue;
            double wa = moving(set, a) && !touched_[a] ? set.invMass[a] : 0.0;
            double wb = isStatic || !moving(set, b) || touched_[b] ? 0.0 : set.invMass[b];
            if (!(wa + wb > 0.0)) continue;
            SurfacePoint sp;
            double reach = set.radius[a];
            if (isStatic) {
                sp = shapes.closestPoint(shapes.ref(b - n), set.position(a));
            } else {
                const Vec2 d = set.position(a) - set.position(b);
                const double L = length(d);
                sp = {L, L > 0.0 ? d / L : Vec2{0.0, 1.0}};
                reach += set.radius[b];
            }
            const double depth = reach - sp.distance;
            if (!(depth > 0.0)) {
                if (depth > -def.toiTolerance && (isStatic || wb == 0.0))
                    touched_[a] = 1; // touching
                continue;
            }
            const Vec2 nrm = sp.normal;
            const double vn = dot(set.velocity(a) - (isStatic ? Vec2{} : set.velocity(b)), nrm);
            const double fa = wa / (wa + wb), fb = wb / (wa + wb);
            set.px[a] += nrm.x * depth * fa, set.py[a] += nrm.y * depth * fa;
            if (vn < 0.0) set.vx[a] -= nrm.x * vn * fa, set.vy[a] -= nrm.y * vn * fa;
            if (wa > 0.0) set.flags[a] &= ~kHistory;
            if (!isStatic && wb > 0.0) {
                set.px[b] -= nrm.x * depth * fb, set.py[b] -= nrm.y * depth * fb;
                if (vn < 0.0) set.vx[b] += nrm.x * vn * fb, set.vy[b] += nrm.y * vn * fb;
                set.flags[b] &= ~kHistory;
            }
            if (isStatic || wb == 0.0)
                touched_[a] = 1;
            else if (wa == 0.0)
                touched_[b] = 1;
        }
}

void ParticleCollisions::penaltyPhase(ParticleSet& set, const StaticShapes& shapes,
                                      const MaterialTable& mats, const CollisionDef& def, double h,
                                      double tickTime) {
    const auto t0 = std::chrono::steady_clock::now(); // profile only
    buildPaths(set, h);
    buildProxies(set, shapes, def, h, true);
    findPairs(def);
    stats_.pairs += static_cast<int>(pairs_.size());
    ++stats_.passes;
    detectMicros_ +=
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
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

void ParticleCollisions::updateSleep(ParticleSet& set, const CollisionDef& def, double dt,
                                     const std::vector<std::uint8_t>& tethered) {
    const std::size_t n = set.slots();
    growTo(sleepTimer_, n), growTo(resting_, n);
    int asleep = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (set.flags[i] & kSleeping) {
            asleep += (set.flags[i] & kAlive) ? 1 : 0;
            continue;
        }
        const bool still = def.sleep && resting_[i] && !(i < tethered.size() && tethered[i]) &&
                           moving(set, i) &&
                           lengthSquared(set.velocity(i)) < def.sleepSpeed * def.sleepSpeed;
        sleepTimer_[i] = still ? sleepTimer_[i] + dt : 0.0;
        if (still && sleepTimer_[i] >= def.sleepTime) {
            set.flags[i] = (set.flags[i] | kSleeping) & ~kHistory;
            set.vx[i] = set.vy[i] = 0.0;
            set.halfVx[i] = set.halfVy[i] = 0.0;
            sleepTimer_[i] = 0.0;
            ++asleep;
        }
        resting_[i] = 0;
    }
    stats_.sleeping = asleep;
}

} // namespace phys
