#include "physics/collision/contact_solver.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace phys {

namespace {

// The effective mass and the shares of a pair of inverse masses: three divisions, done
// once for each pair. A pile of like balls has a handful (1 and 1, 1 and 0, 0 and 1), each
// seen thousands of times, and a division keeps the loop waiting for several
// multiplications' time. The last four pairs are kept, by their bits (-0 is not 0).
class MassShares {
  public:
    MassShares() { known_.fill({~std::uint64_t{0}, ~std::uint64_t{0}, 0.0, 0.0, 0.0}); } // NaNs
    void set(ContactRows::Masses& m, std::size_t at, double wa, double wb, std::uint32_t b,
             std::uint32_t sink) {
        const auto ka = std::bit_cast<std::uint64_t>(wa), kb = std::bit_cast<std::uint64_t>(wb);
        std::size_t i = 0;
        while (i < known_.size() && (known_[i].wa != ka || known_[i].wb != kb))
            ++i;
        if (i == known_.size()) {
            const double sum = wa + wb;
            i = replace_++ % known_.size();
            known_[i] = sum > 0.0 ? Known{ka, kb, 1.0 / sum, wa / sum, wb / sum}
                                  : Known{ka, kb, 0.0, 0.0, 0.0};
        }
        m.wa[at] = wa, m.wb[at] = wb;
        m.mass[at] = known_[i].mass, m.fa[at] = known_[i].fa, m.fb[at] = known_[i].fb;
        m.pushB[at] = wb > 0.0 ? b : sink;
    }

  private:
    struct Known {
        std::uint64_t wa, wb;
        double mass, fa, fb;
    };
    std::array<Known, 4> known_;
    std::size_t replace_ = 0;
};

} // namespace

// ---- the contacts ----------------------------------------------------------------------

void ContactSolver::solve(const Substep& sub, const Stages& st) {
    findNearPairs(sub, st);
    buildContacts(sub, st.paths);
    if (contacts_.empty()) {
        warm_.clear();
        return;
    }
    order_.orderByLevel(contacts_, bodies_, bodyIndex_);
    sweepContacts(sub.set, sub.shapes, sub.def, sub.stats);
    finishContacts(sub, st);
}

// Boxes from where each particle started the step to where it ends: a shape whose side
// it crossed in the step (the passes ran out) is found, and puts it back. Then the pairs
// near enough to be contacts: overlapping, touching, or nearly (speculative: a gap below
// kSpeculative radii may close in one step, and the velocity sweeps allow it to close no
// more than that).
void ContactSolver::findNearPairs(const Substep& sub, const Stages& st) {
    const auto t0 = sub.detect.clock.now(); // profile only
    const ParticleSet& set = sub.set;
    st.paths.straightenToEnd(set, st.awake.active(), sub.h);
    st.proxies.swapForSolver();
    st.proxies.build(set, st.awake.active(), st.paths, sub.def, sub.h, false, kSpeculative);
    st.cache.findPairs(sub, st.awake.active(), st.proxies, st.paths);
    st.proxies.swapForSolver();
    sub.detect.micros += sub.detect.clock.microsSince(t0);
    const std::vector<ProxyPair>& pairs = st.cache.pairs();
    nearPairs_.resize(pairs.size());
    nearPairs_.resize(keepNear(pairs, {set.px, set.py, set.radius}, sub.def.toiTolerance,
                               kSpeculative, nearPairs_.data()));
}

// The contacts of the near pairs with something movable, and what the sweep order
// learns of each.
void ContactSolver::buildContacts(const Substep& sub, const SubstepPaths& paths) {
    const ParticleSet& set = sub.set;
    const std::size_t n = set.slots();
    const auto slots = static_cast<std::uint32_t>(n);
    contacts_.clear();
    order_.prepare(n);
    growTo(bodyMark_, n), growTo(bodyIndex_, n);
    bodies_.clear();
    for (const NearPair& near : nearPairs_) {
        const std::uint32_t a = near.pair.first, b = near.pair.second;
        const bool isStatic = b >= slots;
        if (!isStatic && !sub.def.particlePairs) continue;
        const double wa = movable(set, a) ? set.invMass[a] : 0.0;
        const double wb = !isStatic && movable(set, b) ? set.invMass[b] : 0.0;
        if (!(wa + wb > 0.0)) continue;
        if (addContact(near, wa, wb, sub, paths)) noteLevelsAndBodies(contacts_.back());
    }
}

// Contact a-b (or a and a shape), built in place: a contact written field by field and
// then copied whole waits for those writes to land. False, with nothing added, for a
// shape too far away or a gap that closes faster than a resting contact would.
// (Always inlined, as the next one is: each is the body of the build's loop, named, and
// a call per contact would pass the build's state back and forth thousands of times.)
[[gnu::always_inline]] inline bool ContactSolver::addContact(const NearPair& near, double wa,
                                                             double wb, const Substep& sub,
                                                             const SubstepPaths& paths) {
    const ParticleSet& set = sub.set;
    const StaticShapes& shapes = sub.shapes;
    const auto slots = static_cast<std::uint32_t>(set.slots());
    const std::uint32_t a = near.pair.first, b = near.pair.second;
    const bool isStatic = b >= slots;
    SolverContact& c = contacts_.emplace_back();
    c.a = a;
    c.b = isStatic ? kNoParticle : b;
    c.proxy = b;
    c.normalImpulse = c.tangentImpulse = 0.0;
    if (isStatic) {
        c.shape = shapes.ref(b - slots);
        const SurfacePoint sp = shapes.closestPoint(c.shape, set.position(a));
        c.normal = sp.normal;
        c.depth = set.radius[a] - sp.distance;
        // A centre that crossed the shape in this step (a segment has two sides) belongs
        // on the side it started from: the contact pushes it back there.
        const SurfacePoint from = shapes.closestPoint(c.shape, paths.start(a));
        if (dot(from.normal, sp.normal) < 0.0) {
            c.normal = from.normal;
            c.depth = set.radius[a] + sp.distance;
        }
        c.friction = sub.mats.pair(set.material[a], shapes.material(c.shape)).staticFriction;
    } else { // near enough: keepNear tested the depth
        c.normal = near.normal;
        c.depth = near.depth;
        c.friction = sub.mats.pair(set.material[a], set.material[b]).staticFriction;
    }
    const double reach = set.radius[a] + (isStatic ? 0.0 : set.radius[b]);
    if (isStatic && !nearEnough(c.depth, reach, sub.def.toiTolerance, kSpeculative)) {
        contacts_.pop_back();
        return false;
    }
    if (c.depth < -sub.def.toiTolerance) {
        // A gap: a constraint only if it closes as slowly as a resting contact would
        // (Millington's rule, ToiPasses::restingLimit). One closing faster is an impact of
        // the next step, which the passes resolve at its time of impact with the pair's
        // e; held here to the speed the gap allows, it would lose its energy.
        const Vec2 vb = isStatic ? Vec2{} : set.velocity(b);
        const double approach = -dot(set.velocity(a) - vb, c.normal);
        const double accel = paths.accel0(a) + (isStatic ? 0.0 : paths.accel0(b));
        if (approach > sub.def.restingSpeed + accel * sub.h) {
            contacts_.pop_back();
            return false;
        }
    }
    // The closing speed the gap allows; a gap within the slop counts as touching, so that
    // what projection left a hair apart does not keep closing on it for ever.
    c.closing = std::max(-c.depth - kSlop * reach, 0.0) / sub.h;
    c.wa = wa, c.wb = wb;
    // Which side holds the other up against gravity, if either does (a wall or a
    // neighbour at the side holds nothing up).
    const double upward = dot(c.normal, sub.up);
    c.support = upward > kSupport ? 1 : (!isStatic && upward < -kSupport ? -1 : 0);
    return true;
}

// Levels: immovable particles are ground (0), like the static shapes; what the ground
// holds up is level 1 (the rest follows in SweepOrder::orderByLevel). The particle below
// holds the one above up, when both can move.
[[gnu::always_inline]] inline void ContactSolver::noteLevelsAndBodies(const SolverContact& c) {
    const bool isStatic = c.b == kNoParticle;
    const double wa = c.wa, wb = c.wb;
    if (wa == 0.0) order_.ground(c.a);
    if (!isStatic && wb == 0.0) order_.ground(c.b);
    if (c.support == 1 && wa > 0.0 && wb == 0.0) order_.onGround(c.a);
    if (c.support == -1 && wb > 0.0 && wa == 0.0) order_.onGround(c.b);
    addBody(c.a);
    if (!isStatic) addBody(c.b);
    if (!isStatic && c.support != 0 && wa > 0.0 && wb > 0.0)
        c.support == 1 ? order_.hold(c.b, c.a) : order_.hold(c.a, c.b);
}

// One pass over the contacts: their impulses, which start the next sub-step's sweeps;
// whatever is in contact rests; the sleepers held up by a free particle (a contact of two
// particles with one side immovable). Whatever moved restarts its multi-step integrator.
void ContactSolver::finishContacts(const Substep& sub, const Stages& st) {
    ParticleSet& set = sub.set;
    warm_.clear();
    for (const SolverContact& c : contacts_) {
        warm_.push_back({c.key(), c.normalImpulse, c.tangentImpulse});
        st.sleep.noteContact(c.a, true);
        if (c.b == kNoParticle) continue;
        st.sleep.noteContact(c.b, true);
        if (c.wa == 0.0 || c.wb == 0.0) st.held.noteSolverContact(set, c, st.paths);
    }
    for (const std::uint32_t i : bodies_) {
        if (moved_[i]) set.flags[i] &= ~kHistory;
        bodyMark_[i] = 0;
        order_.forget(i);
    }
}

void ContactSolver::reportDeferred(std::vector<DeferredPair>& deferred, const ParticleSet& set,
                                   std::vector<ContactEvent>& events) const {
    if (deferred.empty()) return;
    std::sort(deferred.begin(), deferred.end(), [](const DeferredPair& x, const DeferredPair& y) {
        return x.key < y.key || (x.key == y.key && x.order < y.order);
    });
    std::size_t k = 0;
    for (std::size_t d = 0; d < deferred.size(); ++d) {
        const DeferredPair& e = deferred[d];
        if (d > 0 && deferred[d - 1].key == e.key) continue; // found again by a later pass
        const auto a = static_cast<ParticleId>(e.key >> 32), b = static_cast<ParticleId>(e.key);
        double impulse = 0.0;
        while (k < contacts_.size() && contacts_[k].key() < e.key)
            ++k;
        if (k < contacts_.size() && contacts_[k].key() == e.key)
            impulse = contacts_[k].normalImpulse;
        events.push_back({a,
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

// ---- the sweeps ------------------------------------------------------------------------

// The sweeps, as the solve's steps: copies in, warm start, rows, velocity, position,
// copies out.
void ContactSolver::sweepContacts(ParticleSet& set, const StaticShapes& shapes,
                                  const CollisionDef& def, CollisionStats& stats) {
    lanes_ = def.contactLanes && contactLanesAvailable();
    copyForSweeps(set);
    warmStart();
    fillRows(set, order_.layOut(lanes_, contacts_, stillSlot()), stats);
    sweepImpulses(def);
    sweepProjections(shapes, def);
    copyAfterSweeps(set);
}

// The velocities and positions of the contacts' particles (the sweeps read and write no
// others) as pairs, still at rest, and "moved by the solver" cleared for them. When they
// are most of the particles, a pass over every slot is the quicker way to the same.
void ContactSolver::copyForSweeps(const ParticleSet& set) {
    const auto n = static_cast<std::uint32_t>(set.slots());
    velocity_.resize(n + 2);
    position_.resize(n + 2);
    if (moved_.size() < n + 2) moved_.resize(n + 2);
    auto copy = [&](std::uint32_t i) {
        velocity_[i] = {set.vx[i], set.vy[i]};
        position_[i] = {set.px[i], set.py[i]};
        moved_[i] = 0;
    };
    if (mostAreBodies(n))
        for (std::uint32_t i = 0; i < n; ++i)
            copy(i);
    else
        for (const std::uint32_t i : bodies_)
            copy(i);
    velocity_[n] = velocity_[n + 1] = {}; // still, sink
    position_[n] = position_[n + 1] = {};
    moved_[n] = moved_[n + 1] = 0;
}

void ContactSolver::copyAfterSweeps(ParticleSet& set) const {
    auto copy = [&](std::size_t i) {
        set.vx[i] = velocity_[i].x, set.vy[i] = velocity_[i].y;
        set.px[i] = position_[i].x, set.py[i] = position_[i].y;
    };
    if (mostAreBodies(set.slots()))
        for (std::size_t i = 0; i < set.slots(); ++i)
            copy(i);
    else
        for (const std::uint32_t i : bodies_)
            copy(i);
}

// A contact that was there at the end of the last sub-step starts from the impulses it
// ended with (both lists are in pair order, so one merge finds them).
void ContactSolver::warmStart() {
    Vec2* const v = velocity_.data();
    std::size_t w = 0;
    for (SolverContact& c : contacts_) {
        const std::uint64_t key = c.key();
        while (w < warm_.size() && warm_[w].key < key)
            ++w;
        if (w == warm_.size() || warm_[w].key != key) continue;
        c.normalImpulse = warm_[w].normalImpulse;
        c.tangentImpulse = warm_[w].tangentImpulse;
        const Vec2 J = c.normal * c.normalImpulse + perp(c.normal) * c.tangentImpulse;
        v[c.a] += J * c.wa;
        moved_[c.a] = 1;
        if (c.b != kNoParticle) {
            v[c.b] -= J * c.wb;
            moved_[c.b] = 1;
        }
    }
}

// The rows, one per place of `order`: a contact's, with its masses for the sweeps over
// all contacts and those of shock propagation in its band (the last band, which nothing
// connects to the ground, is never swept on its own), or padding (at the sink against
// still, no mass, no reach: it does nothing).
void ContactSolver::fillRows(const ParticleSet& set, const std::vector<std::uint32_t>& order,
                             CollisionStats& stats) {
    const auto count = static_cast<std::uint32_t>(contacts_.size());
    const std::uint32_t still = stillSlot(), sink = sinkSlot();
    MassShares shares;
    ContactRows& rows = rows_;
    rows.resize(order.size());
    stats.solverContacts += static_cast<int>(count);
    stats.solverRows += static_cast<int>(rows.size());
    for (std::size_t at = 0; at < order.size(); ++at) {
        const std::uint32_t index = order[at];
        if (index >= count) { // padding
            rows.a[at] = sink, rows.readB[at] = still, rows.contact[at] = index;
            rows.shape[at] = 0;
            rows.nx[at] = rows.ny[at] = rows.closing[at] = rows.friction[at] = 0.0;
            rows.reach[at] = rows.cap[at] = 0.0;
            rows.normalImpulse[at] = rows.tangentImpulse[at] = 0.0;
            shares.set(rows.all, at, 0.0, 0.0, sink, sink);
            shares.set(rows.band, at, 0.0, 0.0, sink, sink);
            continue;
        }
        const SolverContact& c = contacts_[index];
        const bool shape = c.b == kNoParticle;
        const std::uint32_t b = shape ? still : c.b;
        rows.a[at] = c.a, rows.readB[at] = b, rows.contact[at] = index;
        rows.shape[at] = shape ? 1 : 0;
        rows.nx[at] = c.normal.x, rows.ny[at] = c.normal.y;
        rows.closing[at] = c.closing, rows.friction[at] = c.friction;
        const double ra = set.radius[c.a];
        rows.reach[at] = shape ? ra : ra + set.radius[c.b];
        rows.cap[at] = 0.2 * (shape ? ra : std::min(ra, set.radius[c.b]));
        rows.normalImpulse[at] = c.normalImpulse, rows.tangentImpulse[at] = c.tangentImpulse;
        shares.set(rows.all, at, c.wa, c.wb, b, sink);
        const std::uint32_t band = order_.bandOf(c);
        const auto [wa, wb] =
            band == SweepOrder::kUnsupported ? std::pair{c.wa, c.wb} : order_.shockMasses(c, band);
        shares.set(rows.band, at, wa, wb, b, sink);
    }
}

// Velocity: sweeps over all contacts, then band by band from the ground up, on the same
// accumulated impulses; those they end with go back to the contacts (the warm start and
// the events read them there).
void ContactSolver::sweepImpulses(const CollisionDef& def) {
    Vec2* const v = velocity_.data();
    std::uint8_t* const moved = moved_.data();
    ContactRows& rows = rows_;
    for (int sweep = 0; sweep < def.relaxVelocitySweeps; ++sweep)
        for (const SweepOrder::Run& run : order_.runs())
            sweepImpulseRows(rows, rows.all, run.from, run.to, v, moved, run.lanes);
    for (std::size_t band = 1; band + 1 < order_.bands(); ++band)
        for (int sweep = 0; sweep < kShockSweeps; ++sweep)
            sweepImpulseRows(rows, rows.band, order_.rowStart(band), order_.rowEnd(band), v, moved,
                             order_.bandInLanes(band));
    const auto count = static_cast<std::uint32_t>(contacts_.size());
    for (std::size_t at = 0; at < rows.size(); ++at) {
        const std::uint32_t index = rows.contact[at];
        if (index >= count) continue; // padding
        contacts_[index].normalImpulse = rows.normalImpulse[at];
        contacts_[index].tangentImpulse = rows.tangentImpulse[at];
    }
}

// Position: sweeps over all contacts (a second and later ones only while the one before
// pushed deep: a resting pile needs one, and each more moves its balls about), then band
// by band from the ground up, on the rows of the velocity sweeps; in each band the
// contacts against what never moves (a shape, a fixed or sleeping particle) come after
// the others, so that nothing is left inside those, whatever else stays to do. A row
// whose sides are both immovable in its band does nothing.
void ContactSolver::sweepProjections(const StaticShapes& shapes, const CollisionDef& def) {
    Vec2* const p = position_.data();
    std::uint8_t* const moved = moved_.data();
    ContactRows& rows = rows_;
    // A contact with a shape: push the centre out along the shape's normal, at most a
    // fifth of the radius at a time; how far it pushed tells whether the push was deep.
    auto shapeStep = [&](const ContactRows::Masses& m) {
        return [&, p, moved](std::size_t k) {
            const std::uint32_t a = rows.a[k];
            const SolverContact& c = contacts_[rows.contact[k]];
            SurfacePoint sp = shapes.closestPoint(c.shape, p[a]);
            // Keep the side the contact was found on: a segment has two, and a centre
            // that the other contacts pushed across it must come back across, at once,
            // not be pushed out of the far side (and fall out of the level).
            const bool crossed = dot(sp.normal, c.normal) < 0.0;
            if (crossed) sp = {-sp.distance, c.normal};
            const double reach = rows.reach[k];
            const double depth =
                crossed ? reach - sp.distance : std::min(reach - sp.distance, rows.cap[k]);
            if (!(depth > 0.0)) return 0.0;
            const Vec2 move = sp.normal * depth;
            const std::uint32_t pushB = m.pushB[k];
            p[a] += move * m.fa[k];
            p[pushB] -= move * m.fb[k];
            moved[a] = 1;
            moved[pushB] = 1;
            return depth;
        };
    };
    for (int sweep = 0; sweep < def.relaxPositionSweeps; ++sweep) {
        bool deep = false;
        for (const SweepOrder::Run& run : order_.runs())
            deep = sweepProjectRows(rows, rows.all, run.from, run.to, p, moved, run.lanes,
                                    kDeepPush, shapeStep(rows.all)) ||
                   deep;
        if (!deep) break;
    }
    for (std::size_t band = 1; band + 1 < order_.bands(); ++band)
        for (int sweep = 0; sweep < kShockSweeps; ++sweep)
            sweepProjectRows(rows, rows.band, order_.rowStart(band), order_.rowEnd(band), p, moved,
                             order_.bandInLanes(band), kDeepPush, shapeStep(rows.band));
    if (lanes_) markTouched(rows, moved, rows.all.pushB, rows.band.pushB);
}

} // namespace phys
