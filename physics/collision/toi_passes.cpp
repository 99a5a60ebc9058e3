#include "physics/collision/toi_passes.h"

#include "physics/collision/contact_impulse.h"

#include <algorithm>
#include <cmath>

namespace phys {

bool ToiPasses::run(const Substep& sub, const Stages& st) {
    growTo(pathChanged_, sub.set.slots());
    deferred_.clear();
    for (int pass = 0; pass < sub.def.maxPasses; ++pass) {
        if (pass == 0 || !sub.def.redetectChangesOnly || !detectChanges(sub, st)) detect(sub, st);
        changed_.clear(); // what this pass changes, for the next one
        ++sub.stats.passes;
        const int resolved = resolveInTimeOrder(sub, st);
        sub.stats.impacts += resolved;
        if (resolved == 0) return true;
    }
    return false;
}

// A detection over every active particle: proxies, pairs, candidates, their order.
void ToiPasses::detect(const Substep& sub, const Stages& st) {
    const auto t0 = sub.detect.clock.now(); // profile only
    st.proxies.build(sub.set, st.awake.active(), st.paths, sub.def, sub.h, false);
    st.cache.findPairs(sub, st.awake.active(), st.proxies, st.paths);
    sub.stats.pairs += static_cast<int>(st.cache.pairs().size());
    st.narrow.findCandidates(sub, st.cache.pairs(), st.paths);
    st.narrow.orderByTime();
    ++pass_; // paths are as detected until a contact of this pass changes them
    sub.detect.micros += sub.detect.clock.microsSince(t0);
}

// The detection of a pass after the first from what the last pass changed; false when a
// changed particle left what the kept pairs cover (detect runs instead).
bool ToiPasses::detectChanges(const Substep& sub, const Stages& st) {
    const auto t0 = sub.detect.clock.now(); // profile only
    if (!st.cache.covers(st.proxies, sub.set.slots())) return false;
    carryLeftPairs(st.narrow.candidates());
    if (!st.cache.changedPairs(sub, changed_, st.proxies, st.paths)) return false;
    sub.stats.pairs += static_cast<int>(st.cache.pairs().size());
    st.narrow.findCandidates(sub, st.cache.pairs(), st.paths);
    st.narrow.mergeCarried(carried_);
    st.narrow.orderByTime();
    ++pass_;
    ++sub.stats.changesOnly;
    sub.detect.micros += sub.detect.clock.microsSince(t0);
    return true;
}

// Carried: the resting pairs left to the solver that no contact changed since, in the
// pair order of the last pass's candidates.
void ToiPasses::carryLeftPairs(const std::vector<Candidate>& candidates) {
    carried_.clear();
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        const Candidate& c = candidates[k];
        if (leftToSolver_[k] && pathChanged_[c.a] != pass_ && pathChanged_[c.b] != pass_) {
            carried_.push_back(c);
            carried_.back().carried = true;
        }
    }
}

int ToiPasses::resolveInTimeOrder(const Substep& sub, const Stages& st) {
    const std::vector<Candidate>& candidates = st.narrow.candidates();
    leftToSolver_.assign(candidates.size(), 0);
    int resolved = 0;
    for (const TimeKey& key : st.narrow.order()) {
        const Candidate& c = candidates[key.index];
        const Resolution r =
            c.b == kNoParticle ? resolveStatic(c, sub, st) : resolvePair(c, sub, st);
        resolved += r == Resolution::Resting || r == Resolution::Impact ? 1 : 0;
        leftToSolver_[key.index] = r == Resolution::Deferred ? 1 : 0;
    }
    return resolved;
}

void ToiPasses::markChanged(std::size_t i, const Substep& sub, const Stages& st) {
    if (pathChanged_[i] != pass_) changed_.push_back(static_cast<std::uint32_t>(i));
    pathChanged_[i] = pass_;
    if (st.awake.workOn(i)) { // settled until now: as SubstepPaths::build would have left it
        st.paths.untouch(i);
        ++sub.stats.active;
    }
}

// Millington's resting-contact rule: closing slower than restingSpeed plus the speed the
// contact's acceleration builds in one step is resting. For a pair, that acceleration is
// at least what the forces on the two particles build (|a_i| + |a_j|) h: in a pile the
// contacts resolved before have taken the inward part of a particle's acceleration away,
// and the rest of the speed gravity gave it in this step must not count as a bounce.
double ToiPasses::restingLimit(std::size_t i, std::size_t j, double an, const Substep& sub,
                               const SubstepPaths& paths) const {
    return sub.def.restingSpeed +
           std::max(std::max(-an, 0.0) * sub.h, (paths.accel0(i) + paths.accel0(j)) * sub.h);
}

ToiPasses::Resolution ToiPasses::resolveStatic(const Candidate& c, const Substep& sub,
                                               const Stages& st) {
    ParticleSet& set = sub.set;
    SubstepPaths& paths = st.paths;
    const std::size_t i = c.a;
    const double r = set.radius[i];
    // The path may have changed since detection (an earlier contact in this pass); if it
    // has not, the time found then is the time (the same function of the same path).
    const auto toi =
        pathChanged_[i] != pass_
            ? std::optional<double>(c.time)
            : withShape(sub.shapes, c.shape, [&](const auto& shape) {
                  return timeOfImpact(shape, r, paths.path(i), sub.h, st.narrow.settings());
              });
    if (!toi) return Resolution::None;
    markChanged(i, sub, st);
    paths.rebase(i, *toi);
    PathMotion& m = paths.path(i);
    const SurfacePoint sp = sub.shapes.closestPoint(c.shape, m.p);
    const Vec2 n = sp.normal;
    const double gap = sp.distance - r;
    if (gap < 0.0) m.p += n * (-gap); // started inside (spawned, pushed): project out

    const Vec2 v = paths.velocity(i);
    const double vn = dot(v, n);
    // Inward acceleration: the larger of the path's and the state's (they differ only
    // for the Euler methods).
    const double an = std::min(dot(m.a, n), dot(paths.rate(i), n));
    const double w = set.invMass[i];
    const bool resting = -vn < sub.def.restingSpeed + std::max(-an, 0.0) * sub.h;
    const PairProperties& pp = sub.mats.pair(set.material[i], sub.shapes.material(c.shape));
    const double e = resting ? 0.0 : pp.restitution;
    const double remaining = sub.h - *toi;
    const ContactImpulse ci = contactImpulse(v, n, w, 0.0, e, pp);
    Vec2 vNew = v + ci.impulse * w;
    m.v = vNew;
    paths.velocity(i) = vNew;
    if (resting) paths.support(i, n, vNew, pp, remaining, c.proxy);
    paths.touch(i);
    st.sleep.noteContact(i, resting);
    set.flags[i] &= ~kSleeping;
    sub.events.push_back({static_cast<ParticleId>(i), kNoParticle, c.shape, sub.tickTime + *toi, n,
                          -vn, ci.normal, resting, m.p, vNew});
    return resting ? Resolution::Resting : Resolution::Impact;
}

ToiPasses::Resolution ToiPasses::resolvePair(const Candidate& c, const Substep& sub,
                                             const Stages& st) {
    const std::size_t i = c.a, j = c.b;
    // A carried pair was left to the solver by the last pass, and no contact has changed
    // either path since: until one in this pass does, it meets the same paths,
    // velocities, masses and sleepers as then, and is left again. (A heap whose last
    // awake balls bounce through all eight passes carries hundreds a pass.)
    const bool unchanged = pathChanged_[i] != pass_ && pathChanged_[j] != pass_;
    if (c.carried && unchanged) return Resolution::Deferred;
    const auto toi = pairTime(c, unchanged, sub, st);
    if (!toi) return Resolution::None;
    // Sleeping particles count as immovable unless the impulse is big enough to wake them.
    const ParticleSet& set = sub.set;
    const double wi = movable(set, i) ? set.invMass[i] : 0.0;
    const double wj = movable(set, j) ? set.invMass[j] : 0.0;
    if (leaveToSolver(c, *toi, wi, wj, sub, st)) return Resolution::Deferred;
    return bounce(c, *toi, wi, wj, sub, st);
}

std::optional<double> ToiPasses::pairTime(const Candidate& c, bool unchanged, const Substep& sub,
                                          const Stages& st) const {
    if (unchanged) return c.time;
    const SubstepPaths& paths = st.paths;
    return timeOfImpact(Circle{{0.0, 0.0}, sub.set.radius[c.b]}, sub.set.radius[c.a],
                        paths.path(c.a).relativeTo(paths.path(c.b)), sub.h, st.narrow.settings());
}

// Classified at the time of impact before anything changes: a resting contact between two
// free particles (a pile) is left to the contact solver. So is a sleeper lying on a free
// particle: that is weight the free one carries, not a surface it rests on. Held up by it
// as by a ceiling, pushed down into what lies under it (often another sleeper) and up
// again, the free one kept the passes busy for all their number, every step, while part of
// a pile slept.
bool ToiPasses::leaveToSolver(const Candidate& c, double toi, double wi, double wj,
                              const Substep& sub, const Stages& st) {
    if (!sub.def.restingPairsToSolver) return false;
    const ParticleSet& set = sub.set;
    SubstepPaths& paths = st.paths;
    const std::size_t i = c.a, j = c.b;
    const PathMotion pi = paths.path(i), pj = paths.path(j);
    const Vec2 d = pi.position(toi) - pj.position(toi);
    const double L = length(d);
    const Vec2 n = L > 0.0 ? d / L : Vec2{0.0, 1.0};
    const Vec2 vrel = (paths.velocity(i) + paths.rate(i) * (toi - pi.t0)) -
                      (paths.velocity(j) + paths.rate(j) * (toi - pj.t0));
    const double an = std::min(dot(pi.a - pj.a, n), dot(paths.rate(i) - paths.rate(j), n));
    const double vn = dot(vrel, n);
    const bool bothFree = wi > 0.0 && wj > 0.0;
    // One of the pair is free and the other a sleeper above it.
    const bool onSleeper =
        (wi > 0.0 && wakeableSleeper(set, j)) || (wj > 0.0 && wakeableSleeper(set, i));
    const bool underSleeper = onSleeper && dot(wi > 0.0 ? n : -n, sub.up) < -kSupport;
    if (!((bothFree || underSleeper) && -vn < restingLimit(i, j, an, sub, paths))) return false;
    // Only its first deferral is reported (ContactSolver::reportDeferred), and a carried
    // pair has one from a pass before.
    if (!c.carried)
        deferred_.push_back({(std::uint64_t{c.a} << 32) | c.b,
                             static_cast<std::uint32_t>(deferred_.size()), sub.tickTime + toi, -vn,
                             n, pi.position(toi)});
    return true;
}

ToiPasses::Resolution ToiPasses::bounce(const Candidate& c, double toi, double wi, double wj,
                                        const Substep& sub, const Stages& st) {
    ParticleSet& set = sub.set;
    SubstepPaths& paths = st.paths;
    const std::size_t i = c.a, j = c.b;
    markChanged(i, sub, st);
    markChanged(j, sub, st);
    paths.rebase(i, toi);
    paths.rebase(j, toi);
    PathMotion &mi = paths.path(i), &mj = paths.path(j);
    const Vec2 d = mi.p - mj.p;
    const double L = length(d);
    const Vec2 n = L > 0.0 ? d / L : Vec2{0.0, 1.0};
    const Vec2 vrel = paths.velocity(i) - paths.velocity(j);
    const double vn = dot(vrel, n);
    const double an = std::min(dot(mi.a - mj.a, n), dot(paths.rate(i) - paths.rate(j), n));
    const bool resting = -vn < restingLimit(i, j, an, sub, paths);
    const PairProperties& pp = sub.mats.pair(set.material[i], set.material[j]);
    const double e = resting ? 0.0 : pp.restitution;
    ContactImpulse ci = contactImpulse(vrel, n, wi, wj, e, pp);
    // An impact wakes a sleeper it would move faster than sleepSpeed; resting on one
    // does not (it carries what rests on it, as a sleeping pile carries its top layer).
    for (const std::size_t k : {i, j}) {
        if (wakeableSleeper(set, k) && !resting &&
            ci.normal * set.invMass[k] > sub.def.sleepSpeed) {
            set.flags[k] &= ~kSleeping;
            (k == i ? wi : wj) = set.invMass[k];
            ci = contactImpulse(vrel, n, wi, wj, e, pp);
        }
    }
    const double gap = L - set.radius[i] - set.radius[j];
    if (gap < 0.0 && wi + wj > 0.0) { // overlapping at the start: separate by inverse mass
        mi.p += n * (-gap * wi / (wi + wj));
        mj.p -= n * (-gap * wj / (wi + wj));
    }
    paths.velocity(i) += ci.impulse * wi;
    paths.velocity(j) -= ci.impulse * wj;
    mi.v = paths.velocity(i);
    mj.v = paths.velocity(j);
    if (resting) carryResting(i, j, n, wi, wj, pp, sub.h - toi, paths);
    if (wi > 0.0) paths.touch(i), st.sleep.noteContact(i, resting);
    if (wj > 0.0) paths.touch(j), st.sleep.noteContact(j, resting);
    sub.events.push_back({static_cast<ParticleId>(i),
                          static_cast<ParticleId>(j),
                          {},
                          sub.tickTime + toi,
                          n,
                          -vn,
                          ci.normal,
                          resting,
                          mi.p,
                          paths.velocity(i)});
    return resting ? Resolution::Resting : Resolution::Impact;
}

// Resting on something immovable (a fixed or sleeping particle): it carries the other for
// the rest of the step as a static surface does, normal force and Coulomb friction both
// (SubstepPaths::support). Without the friction a ball come to rest on a sleeper slid off
// it however flat the contact. Both free: they accelerate together along n (a plastic
// contact for the rest of the step), sharing the momentum rate, weights m_i, m_j. What
// then pushes one of them into a surface is resolved in the next pass.
void ToiPasses::carryResting(std::size_t i, std::size_t j, Vec2 n, double wi, double wj,
                             const PairProperties& pp, double remaining, SubstepPaths& paths) {
    if (wj == 0.0) {
        paths.support(i, n, paths.velocity(i) - paths.velocity(j), pp, remaining,
                      static_cast<std::uint32_t>(j));
    } else if (wi == 0.0) {
        paths.support(j, -n, paths.velocity(j) - paths.velocity(i), pp, remaining,
                      static_cast<std::uint32_t>(i));
    } else {
        auto share = [&](Vec2& ai, Vec2& aj) {
            const double rel = dot(ai - aj, n);
            if (rel >= 0.0) return;
            ai -= n * (rel * wi / (wi + wj));
            aj += n * (rel * wj / (wi + wj));
        };
        share(paths.path(i).a, paths.path(j).a);
        share(paths.rate(i), paths.rate(j));
    }
}

} // namespace phys
