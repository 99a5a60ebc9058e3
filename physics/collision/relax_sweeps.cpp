// The sweeps of the end-of-step contact solver (ParticleCollisions::relaxContacts): warm
// start, velocity sweeps over all contacts and then band by band, position sweeps the
// same way. Each contact is visited some twenty times a sub-step, so the sweeps run on a
// layout made for the loop, built once:
//   rows        one row per contact and sweep, as columns (contact_columns.h), holding
//               what the visit reads (normal, closing speed, friction, the inverse and
//               the effective masses, each side's share of a push); the banded masses of
//               shock propagation are worked out once per contact, not once per visit;
//   wavefronts  where the processor has AVX2, each sweep's rows are laid out in its
//               wavefronts (wavefronts.h) and swept four at a time: the bits of the sweep
//               in its own order, in about 650 steps of four for 2,500 contacts;
//   copies      the velocities and positions as pairs, with two slots past the
//               particles: still, at rest, which a shape reads as its velocity, and sink,
//               which takes the push on an immovable side, so no visit branches on either;
//   masses      each row keeps its effective mass 1 / (wa + wb), so a visit multiplies
//               where it divided twice; a pair of balls apart by their radii or more needs
//               no push, and costs no square root.
#include "physics/collision/particle_collisions.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace phys {

namespace {

// The mass the contact's impulse moves: 1 / (wa + wb), 0 when neither side moves.
inline double effectiveMass(double wa, double wb) {
    return wa + wb > 0.0 ? 1.0 / (wa + wb) : 0.0;
}

} // namespace

// The sweeps, as the solve's steps: copies in, warm start, velocity, position, copies out.
void ParticleCollisions::sweepContacts(ParticleSet& set, const StaticShapes& shapes,
                                       const CollisionDef& def) {
    lanes_ = def.contactLanes && contactLanesAvailable();
    copyForSweeps(set);
    warmStart();
    buildSweepRows(set);
    buildImpulseRows();
    sweepImpulses(def);
    buildProjectRows();
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

template <class Slots>
const std::vector<std::uint32_t>&
ParticleCollisions::sweepOrder(const std::vector<std::uint32_t>& parts,
                               std::vector<std::uint32_t>& partsOut, Slots&& slots) {
    if (!lanes_) {
        partsOut = parts;
        return sequence_;
    }
    wavefronts_.begin(stillSlot()); // still and sink order nothing
    wavefronts_.add(sequence_, parts, slots);
    const auto& order = wavefronts_.order(4);
    partsOut = wavefronts_.barrierStarts();
    return order;
}

// What every sweep's row of a contact reads, by its place in contactOrder_, with the
// masses of the sweeps over all contacts and of those of its band (bands 1 to bands - 2
// are swept on their own; band 0 is never used, and the last holds the contacts that
// nothing connects to the ground); and the padding row after them.
void ParticleCollisions::buildSweepRows(const ParticleSet& set) {
    const std::uint32_t still = stillSlot(), sink = sinkSlot();
    const std::size_t count = contacts_.size(), bands = bandStart_.size() - 1;
    // Three divisions a pair of inverse masses, done once for each pair: a pile of like
    // balls has a handful (1 and 1, 1 and 0, 0 and 1), each seen thousands of times, and
    // a division keeps the loop waiting for several multiplications' time. The last four
    // pairs are kept, by their bits (-0 is not 0). Each field is set on its own: a row
    // copied whole after one of its fields was written waits for that write to land.
    struct Known {
        std::uint64_t wa, wb;
        double mass, fa, fb;
    };
    std::array<Known, 4> known;
    known.fill({~std::uint64_t{0}, ~std::uint64_t{0}, 0.0, 0.0, 0.0}); // a NaN's bits
    std::size_t replace = 0;
    auto setMasses = [&](SweepRow::Masses& m, const SweepRow& r, double wa, double wb) {
        const auto a = std::bit_cast<std::uint64_t>(wa), b = std::bit_cast<std::uint64_t>(wb);
        std::size_t at = 0;
        while (at < known.size() && (known[at].wa != a || known[at].wb != b))
            ++at;
        if (at == known.size()) {
            const double sum = wa + wb;
            at = replace++ % known.size();
            known[at] = {a, b, effectiveMass(wa, wb), wa / sum, wb / sum};
        }
        m.wa = wa, m.wb = wb;
        m.mass = known[at].mass, m.fa = known[at].fa, m.fb = known[at].fb;
        m.pushB = !r.shape && wb > 0.0 ? r.readB : sink;
    };
    sweepRows_.resize(count + 1);
    for (std::uint32_t k = 0; k < count; ++k) {
        const RelaxContact& c = contacts_[contactOrder_[k]];
        SweepRow& r = sweepRows_[k];
        const bool shape = c.b == kNoParticle;
        r.a = c.a, r.contact = contactOrder_[k];
        r.readB = shape ? still : c.b;
        r.shape = shape;
        r.immovableSide = shape || c.wa == 0.0 || c.wb == 0.0;
        r.nx = c.normal.x, r.ny = c.normal.y;
        r.closing = c.closing, r.friction = c.friction;
        r.normalImpulse = c.normalImpulse, r.tangentImpulse = c.tangentImpulse;
        const double ra = set.radius[c.a];
        r.reach = shape ? ra : ra + set.radius[c.b];
        r.cap = 0.2 * (shape ? ra : std::min(ra, set.radius[c.b]));
        setMasses(r.all, r, c.wa, c.wb);
        setMasses(r.band, r, c.wa, c.wb);
    }
    for (std::uint32_t band = 1; band + 1 < bands; ++band)
        for (std::uint32_t k = bandStart_[band]; k < bandStart_[band + 1]; ++k) {
            SweepRow& r = sweepRows_[k];
            const auto [wa, wb] = shockMasses(contacts_[r.contact], band);
            setMasses(r.band, r, wa, wb);
        }
    SweepRow& padding = sweepRows_[count];
    padding = {};
    padding.a = padding.all.pushB = padding.band.pushB = sink;
    padding.readB = still;
}

// The velocity rows, one per contact, band by band (each band's from impulseStart_[band]),
// each band's in its wavefronts when the lanes run: the sweeps over all contacts take the
// bands one after the other, in their order, and those over a band take its rows alone.
void ParticleCollisions::buildImpulseRows() {
    const auto count = static_cast<std::uint32_t>(contacts_.size());
    sequence_.resize(count);
    for (std::uint32_t k = 0; k < count; ++k)
        sequence_[k] = k;
    const auto& order = sweepOrder(bandStart_, impulseStart_, [&](std::uint32_t k) {
        const SweepRow& r = sweepRows_[k];
        return std::array<std::uint32_t, 4>{0u, r.a, r.readB, r.all.pushB};
    });
    ImpulseColumns& rows = impulses_;
    rows.resize(order.size());
    impulseRow_.resize(count + 1); // and the padding row's, never read
    const auto padding = static_cast<std::uint32_t>(sweepRows_.size() - 1);
    for (std::size_t at = 0; at < order.size(); ++at) {
        const std::uint32_t k = std::min(order[at], padding); // kPadding: the padding row
        const SweepRow& r = sweepRows_[k];
        rows.a[at] = r.a, rows.readB[at] = r.readB;
        rows.nx[at] = r.nx, rows.ny[at] = r.ny, rows.closing[at] = r.closing;
        rows.friction[at] = r.friction;
        for (auto [to, from] : {std::pair{&rows.all, &r.all}, std::pair{&rows.band, &r.band}}) {
            to->wa[at] = from->wa, to->wb[at] = from->wb, to->mass[at] = from->mass;
            to->pushB[at] = from->pushB;
        }
        rows.normalImpulse[at] = r.normalImpulse, rows.tangentImpulse[at] = r.tangentImpulse;
        impulseRow_[k] = static_cast<std::uint32_t>(at);
    }
}

// Velocity: sweeps over all contacts, then band by band from the ground up, on the same
// accumulated impulses; those they end with go back to the contacts (the warm start and
// the events read them there).
void ParticleCollisions::sweepImpulses(const CollisionDef& def) {
    Vec2* const v = sweepVelocity_.data();
    std::uint8_t* const touched = touched_.data();
    ImpulseColumns& rows = impulses_;
    for (int sweep = 0; sweep < def.relaxVelocitySweeps; ++sweep)
        sweepImpulseColumns(rows, rows.all, 0, rows.size(), v, touched, lanes_);
    const std::size_t bands = bandStart_.size() - 1;
    for (std::size_t band = 1; band + 1 < bands; ++band)
        for (int sweep = 0; sweep < kShockSweeps; ++sweep)
            sweepImpulseColumns(rows, rows.band, impulseStart_[band], impulseStart_[band + 1], v,
                                touched, lanes_);
    if (lanes_) markTouched(rows, touched, rows.all.pushB, rows.band.pushB);
    for (std::uint32_t k = 0; k < contacts_.size(); ++k) {
        RelaxContact& c = contacts_[contactOrder_[k]];
        c.normalImpulse = rows.normalImpulse[impulseRow_[k]];
        c.tangentImpulse = rows.tangentImpulse[impulseRow_[k]];
    }
}

// The position rows: contactOrder_ with the contacts against what never moves (a shape, a
// fixed or sleeping particle) after the others, in the whole list and within each band,
// so that nothing is left inside those, whatever else stays to do. A row whose sides are
// both immovable in its band is left out: its visit would do nothing.
void ParticleCollisions::buildProjectRows() {
    const std::size_t count = contacts_.size(), bands = bandStart_.size() - 1;
    // Appends the places from..to to sequence_, movable first, each with something to move
    // (banded: in its band).
    auto movableFirst = [&](std::uint32_t from, std::uint32_t to, bool banded) {
        for (const bool statics : {false, true})
            for (std::uint32_t k = from; k < to; ++k) {
                const SweepRow& r = sweepRows_[k];
                const SweepRow::Masses& m = banded ? r.band : r.all;
                if (r.immovableSide == statics && m.wa + m.wb > 0.0) sequence_.push_back(k);
            }
    };
    const auto padding = static_cast<std::uint32_t>(sweepRows_.size() - 1);
    auto layOut = [&](ProjectColumns& rows, const std::vector<std::uint32_t>& parts,
                      std::vector<std::uint32_t>& partsOut, bool banded) {
        const auto& order = sweepOrder(parts, partsOut, [&](std::uint32_t k) {
            const SweepRow& r = sweepRows_[k];
            return std::array<std::uint32_t, 4>{r.shape ? 1u : 0u, r.a, r.readB,
                                                (banded ? r.band : r.all).pushB};
        });
        rows.resize(order.size());
        for (std::size_t at = 0; at < order.size(); ++at) {
            const SweepRow& r = sweepRows_[std::min(order[at], padding)];
            const SweepRow::Masses& m = banded ? r.band : r.all;
            rows.a[at] = r.a, rows.b[at] = r.shape ? ProjectColumns::kShapeRow : r.readB;
            rows.pushB[at] = m.pushB, rows.contact[at] = r.contact;
            rows.reach[at] = r.reach, rows.cap[at] = r.cap;
            rows.fa[at] = m.fa, rows.fb[at] = m.fb;
        }
    };
    sequence_.clear();
    movableFirst(0, static_cast<std::uint32_t>(count), false);
    parts_.clear();
    layOut(projections_, parts_, partsOut_, false);
    // Bands 1 to bands - 2, each a part of the sequence; shockProjectStart_[band] is where
    // band's rows start (bands 0 and the last have none).
    sequence_.clear();
    parts_.assign(2, 0u);
    for (std::uint32_t band = 1; band + 1 < bands; ++band) {
        movableFirst(bandStart_[band], bandStart_[band + 1], true);
        parts_.push_back(static_cast<std::uint32_t>(sequence_.size()));
    }
    layOut(shockProjections_, parts_, shockProjectStart_, true);
}

// Position: sweeps over all contacts, then band by band from the ground up. Velocities are
// left as the impulses made them, so the projection adds no energy.
void ParticleCollisions::sweepProjections(const StaticShapes& shapes, const CollisionDef& def) {
    Vec2* const p = sweepPosition_.data();
    std::uint8_t* const touched = touched_.data();
    // A contact with a shape: push the centre out along the shape's normal, at most a
    // fifth of the radius at a time.
    auto shapeStep = [&](const ProjectColumns& rows) {
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
            if (!(depth > 0.0)) return;
            const Vec2 move = sp.normal * depth;
            const std::uint32_t pushB = rows.pushB[k];
            p[a] += move * rows.fa[k];
            p[pushB] -= move * rows.fb[k];
            touched[a] = 1;
            touched[pushB] = 1;
        };
    };
    for (int sweep = 0; sweep < def.relaxPositionSweeps; ++sweep)
        sweepProjectColumns(projections_, 0, projections_.size(), p, touched, lanes_,
                            shapeStep(projections_));
    const std::size_t bands = bandStart_.size() - 1;
    for (std::size_t band = 1; band + 1 < bands; ++band)
        for (int sweep = 0; sweep < kShockSweeps; ++sweep)
            sweepProjectColumns(shockProjections_, shockProjectStart_[band],
                                shockProjectStart_[band + 1], p, touched, lanes_,
                                shapeStep(shockProjections_));
    if (lanes_)
        markTouched(projections_, touched, projections_.pushB),
            markTouched(shockProjections_, touched, shockProjections_.pushB);
}

} // namespace phys
