// The sweeps of the end-of-step contact solver (ParticleCollisions::relaxContacts): warm
// start, velocity sweeps over all contacts and then band by band, position sweeps the
// same way. Each contact is visited some twenty times a sub-step, so the sweeps run on a
// layout made for the loop, built once:
//   rows        one row per contact, as columns (simd/contact_rows.h), holding what a visit
//               of either step reads (normal, closing speed, friction, reach, the
//               inverse and the effective masses, each side's share of a push); the
//               banded masses of shock propagation are worked out once per contact, not
//               once per visit;
//   wavefronts  where the processor has AVX2, the rows are laid out once in the
//               wavefronts of their order (wavefronts.h), which every sweep takes, four
//               at a time: the bits of the sweeps in that order, in about 650 steps of
//               four for 2,500 contacts;
//   copies      the velocities and positions as pairs, with two slots past the
//               particles: still, at rest, which a shape reads as its velocity, and sink,
//               which takes the push on an immovable side, so no visit branches on either;
//   masses      each row keeps its effective mass 1 / (wa + wb) and its shares, so a
//               visit multiplies where it divided; a pair of balls apart by their radii or more
//               needs no push, and costs no square root.
#include "physics/collision/particle_collisions.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace phys {

// The sweeps, as the solve's steps: copies in, warm start, velocity, position, copies out.
void ParticleCollisions::sweepContacts(ParticleSet& set, const StaticShapes& shapes,
                                       const CollisionDef& def) {
    lanes_ = def.contactLanes && contactLanesAvailable();
    copyForSweeps(set);
    warmStart();
    layOutRows(set);
    sweepImpulses(def);
    sweepProjections(shapes, def);
    copyAfterSweeps(set);
}

// The velocities and positions of the contacts' particles (the sweeps read and write no
// others) as pairs, still at rest, and "moved by the solver" cleared for them. When they
// are most of the particles, a pass over every slot is the quicker way to the same.
void ParticleCollisions::copyForSweeps(const ParticleSet& set) {
    const auto n = static_cast<std::uint32_t>(set.slots());
    sweepVelocity_.resize(n + 2);
    sweepPosition_.resize(n + 2);
    if (touched_.size() < n + 2) touched_.resize(n + 2);
    auto copy = [&](std::uint32_t i) {
        sweepVelocity_[i] = {set.vx[i], set.vy[i]};
        sweepPosition_[i] = {set.px[i], set.py[i]};
        touched_[i] = 0;
    };
    if (mostAreBodies(n))
        for (std::uint32_t i = 0; i < n; ++i)
            copy(i);
    else
        for (const std::uint32_t i : bodies_)
            copy(i);
    sweepVelocity_[n] = sweepVelocity_[n + 1] = {}; // still, sink
    sweepPosition_[n] = sweepPosition_[n + 1] = {};
    touched_[n] = touched_[n + 1] = 0;
}

void ParticleCollisions::copyAfterSweeps(ParticleSet& set) const {
    auto copy = [&](std::size_t i) {
        set.vx[i] = sweepVelocity_[i].x, set.vy[i] = sweepVelocity_[i].y;
        set.px[i] = sweepPosition_[i].x, set.py[i] = sweepPosition_[i].y;
    };
    if (mostAreBodies(set.slots()))
        for (std::size_t i = 0; i < set.slots(); ++i)
            copy(i);
    else
        for (const std::uint32_t i : bodies_)
            copy(i);
}

// A contact that was there at the end of the last sub-step starts from the impulses it
// ended with (both lists are in pair order, so one merge finds them). In a resting pile
// those are nearly the answer, and the sweeps only correct them.
void ParticleCollisions::warmStart() {
    Vec2* const v = sweepVelocity_.data();
    std::size_t w = 0;
    for (RelaxContact& c : contacts_) {
        const std::uint64_t key = (std::uint64_t{c.a} << 32) | c.proxy;
        while (w < warm_.size() && warm_[w].key < key)
            ++w;
        if (w == warm_.size() || warm_[w].key != key) continue;
        c.normalImpulse = warm_[w].normalImpulse;
        c.tangentImpulse = warm_[w].tangentImpulse;
        const Vec2 J = c.normal * c.normalImpulse + perp(c.normal) * c.tangentImpulse;
        v[c.a] += J * c.wa;
        touched_[c.a] = 1;
        if (c.b != kNoParticle) {
            v[c.b] -= J * c.wb;
            touched_[c.b] = 1;
        }
    }
}

// The rows, one per contact, in the order of contactOrder_ (band by band from the ground
// up; in each band, the contacts with something immovable after the others), laid out in
// the wavefronts of that order when the lanes run, with a barrier before each band: one
// layout, which every sweep takes, those over all contacts and those over a band (from
// rowStart_[band]). The band masses are those of shock propagation in the contact's band;
// the last band, which nothing connects to the ground, is never swept on its own.
void ParticleCollisions::layOutRows(const ParticleSet& set) {
    const auto count = static_cast<std::uint32_t>(contacts_.size());
    const std::uint32_t still = stillSlot(), sink = sinkSlot();
    // The contacts as the sweeps take them: contactOrder_ itself, or its wavefronts.
    const std::vector<std::uint32_t>* order = &contactOrder_;
    if (lanes_) {
        wavefronts_.begin(still); // still and sink order nothing
        wavefronts_.add(contactOrder_, bandStart_, [&](std::uint32_t index) {
            const RelaxContact& c = contacts_[index];
            const bool shape = c.b == kNoParticle;
            const std::uint32_t b = shape ? still : c.b;
            return std::array<std::uint32_t, 4>{shape ? 1u : 0u, c.a, b, b};
        });
        order = &wavefronts_.order(4);
        rowStart_ = wavefronts_.barrierStarts();
        order = &keepLanesWhereTheyFill(*order);
    } else {
        rowStart_ = bandStart_;
        bandLanes_.assign(bandStart_.size() - 1, 0);
    }
    // Three divisions a pair of inverse masses, done once for each pair: a pile of like
    // balls has a handful (1 and 1, 1 and 0, 0 and 1), each seen thousands of times, and
    // a division keeps the loop waiting for several multiplications' time. The last four
    // pairs are kept, by their bits (-0 is not 0).
    struct Known {
        std::uint64_t wa, wb;
        double mass, fa, fb;
    };
    std::array<Known, 4> known;
    known.fill({~std::uint64_t{0}, ~std::uint64_t{0}, 0.0, 0.0, 0.0}); // a NaN's bits
    std::size_t replace = 0;
    ContactRows& rows = rows_;
    auto setMasses = [&](ContactRows::Masses& m, std::size_t at, double wa, double wb,
                         std::uint32_t b) {
        const auto ka = std::bit_cast<std::uint64_t>(wa), kb = std::bit_cast<std::uint64_t>(wb);
        std::size_t i = 0;
        while (i < known.size() && (known[i].wa != ka || known[i].wb != kb))
            ++i;
        if (i == known.size()) {
            const double sum = wa + wb;
            i = replace++ % known.size();
            known[i] = sum > 0.0 ? Known{ka, kb, 1.0 / sum, wa / sum, wb / sum}
                                 : Known{ka, kb, 0.0, 0.0, 0.0};
        }
        m.wa[at] = wa, m.wb[at] = wb;
        m.mass[at] = known[i].mass, m.fa[at] = known[i].fa, m.fb[at] = known[i].fb;
        m.pushB[at] = wb > 0.0 ? b : sink;
    };
    joinBandsIntoRuns();
    rows.resize(order->size());
    stats_.solverContacts += static_cast<int>(count);
    stats_.solverRows += static_cast<int>(rows.size());
    for (std::size_t at = 0; at < order->size(); ++at) {
        const std::uint32_t index = (*order)[at];
        if (index >= count) { // padding: at the sink against still, no mass, no reach
            rows.a[at] = sink, rows.readB[at] = still, rows.contact[at] = index;
            rows.shape[at] = 0;
            rows.nx[at] = rows.ny[at] = rows.closing[at] = rows.friction[at] = 0.0;
            rows.reach[at] = rows.cap[at] = 0.0;
            rows.normalImpulse[at] = rows.tangentImpulse[at] = 0.0;
            setMasses(rows.all, at, 0.0, 0.0, sink);
            setMasses(rows.band, at, 0.0, 0.0, sink);
            continue;
        }
        const RelaxContact& c = contacts_[index];
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
        setMasses(rows.all, at, c.wa, c.wb, b);
        const std::uint32_t band = bandOf(c);
        const auto [wa, wb] = band == kUnsupported ? std::pair{c.wa, c.wb} : shockMasses(c, band);
        setMasses(rows.band, at, wa, wb, b);
    }
}

// The bands whose wavefronts are too narrow for the lanes are swept one row at a time
// instead, in their own order: the same bits (a band's wavefronts give the bits of its
// order), for less work where a padded lane would do one contact's work for four. A row
// of balls touching side by side, listed pair by pair, is a chain that takes one
// wavefront a contact: in a heap poured in staggered rows its bands take about three
// rows a contact in lanes. Returns the layout: `wavefronts` itself when every band
// keeps its lanes, else the bands' rows, each band's in the way it is swept.
const std::vector<std::uint32_t>&
ParticleCollisions::keepLanesWhereTheyFill(const std::vector<std::uint32_t>& wavefronts) {
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
            mixedOrder_.insert(mixedOrder_.end(), contactOrder_.begin() + bandStart_[b],
                               contactOrder_.begin() + bandStart_[b + 1]);
        rowStart_[b] = from;
    }
    rowStart_[bands] = static_cast<std::uint32_t>(mixedOrder_.size());
    return mixedOrder_;
}

// The sweeps over all contacts as runs of bands swept the same way: one run, [0, rows),
// unless some band is swept one row at a time.
void ParticleCollisions::joinBandsIntoRuns() {
    sweepRuns_.clear();
    for (std::size_t b = 0; b + 1 < rowStart_.size(); ++b) {
        const bool lanes = bandLanes_[b] != 0;
        if (!sweepRuns_.empty() && sweepRuns_.back().lanes == lanes)
            sweepRuns_.back().to = rowStart_[b + 1];
        else
            sweepRuns_.push_back({rowStart_[b], rowStart_[b + 1], lanes});
    }
}

// Velocity: sweeps over all contacts, then band by band from the ground up, on the same
// accumulated impulses; those they end with go back to the contacts (the warm start and
// the events read them there).
void ParticleCollisions::sweepImpulses(const CollisionDef& def) {
    Vec2* const v = sweepVelocity_.data();
    std::uint8_t* const touched = touched_.data();
    ContactRows& rows = rows_;
    const std::size_t bands = bandStart_.size() - 1;
    for (int sweep = 0; sweep < def.relaxVelocitySweeps; ++sweep)
        for (const SweepRun& run : sweepRuns_)
            sweepImpulseRows(rows, rows.all, run.from, run.to, v, touched, run.lanes);
    for (std::size_t band = 1; band + 1 < bands; ++band)
        for (int sweep = 0; sweep < kShockSweeps; ++sweep)
            sweepImpulseRows(rows, rows.band, rowStart_[band], rowStart_[band + 1], v, touched,
                                bandLanes_[band] != 0);
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
// whose sides are both immovable in its band does nothing. Velocities are left as the
// impulses made them, so the projection adds no energy.
void ParticleCollisions::sweepProjections(const StaticShapes& shapes, const CollisionDef& def) {
    Vec2* const p = sweepPosition_.data();
    std::uint8_t* const touched = touched_.data();
    ContactRows& rows = rows_;
    // A contact with a shape: push the centre out along the shape's normal, at most a
    // fifth of the radius at a time; how far it pushed tells whether the push was deep.
    auto shapeStep = [&](const ContactRows::Masses& m) {
        return [&, p, touched](std::size_t k) {
            const std::uint32_t a = rows.a[k];
            const RelaxContact& c = contacts_[rows.contact[k]];
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
            touched[a] = 1;
            touched[pushB] = 1;
            return depth;
        };
    };
    const std::size_t bands = bandStart_.size() - 1;
    for (int sweep = 0; sweep < def.relaxPositionSweeps; ++sweep) {
        bool deep = false;
        for (const SweepRun& run : sweepRuns_)
            deep = sweepProjectRows(rows, rows.all, run.from, run.to, p, touched, run.lanes,
                                       kDeepPush, shapeStep(rows.all)) ||
                   deep;
        if (!deep) break;
    }
    for (std::size_t band = 1; band + 1 < bands; ++band)
        for (int sweep = 0; sweep < kShockSweeps; ++sweep)
            sweepProjectRows(rows, rows.band, rowStart_[band], rowStart_[band + 1], p, touched,
                                bandLanes_[band] != 0, kDeepPush, shapeStep(rows.band));
    if (lanes_) markTouched(rows, touched, rows.all.pushB, rows.band.pushB);
}

} // namespace phys
