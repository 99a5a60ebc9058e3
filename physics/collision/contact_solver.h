// The contact solver: at the end of a sub-step, the contacts the passes did not settle (a
// pile, a stack, a particle wedged in a corner) are relaxed on the end state as contact
// constraints, by sequential impulses (Catto, box2d-lite) with shock propagation:
//   velocity  sweeps of normal impulses remove every closing velocity (no bounce: what
//             still closes after the passes is resting), with Coulomb friction bounded by
//             mu_s times the contact's accumulated normal impulse;
//   position  sweeps push overlaps apart along the normal, split by inverse mass, at most
//             a fifth of a radius at a time and, in each band, the static contacts last,
//             so that a pile pressing on a wall never pushes a particle through it.
//             Velocities are left as the impulses made them, so the projection adds no
//             energy.
// Both steps sweep the contacts in one order (sweep_order.h), first all of them, then
// band by band from the ground up, so one layout of rows (simd/contact_rows.h) serves
// every sweep. Each contact is visited some twenty times a sub-step, so the rows hold
// what a visit reads, worked out once: the effective mass 1 / (wa + wb) and each side's
// share of a push (a visit multiplies where it divided), and the banded masses of shock
// propagation. The sweeps run on copies of the velocities and positions as pairs, with
// two slots past the particles: still, at rest, which a shape reads as its velocity, and
// sink, which takes the push on an immovable side, so no visit branches on either.
// Fixed and sleeping particles are immovable. A contact that needs nothing (not closing,
// not overlapping) changes nothing.
//
// A contact that was there at the end of the last sub-step starts from the impulses it
// ended with (warm start): in a resting pile those are nearly the answer.
#pragma once

#include "physics/collision/awake_set.h"
#include "physics/collision/held_sleepers.h"
#include "physics/collision/pair_cache.h"
#include "physics/collision/paths.h"
#include "physics/collision/proxies.h"
#include "physics/collision/simd/contact_rows.h"
#include "physics/collision/simd/pair_filter.h"
#include "physics/collision/sleep.h"
#include "physics/collision/solver_contact.h"
#include "physics/collision/substep.h"
#include "physics/collision/sweep_order.h"
#include "physics/collision/toi_passes.h"

#include <cstdint>
#include <vector>

namespace phys {

class ContactSolver {
  public:
    using Stages = SubstepStages;
    /// Settles the contacts of the sub-step's end state.
    void solve(const Substep& sub, const Stages& st);
    /// No solve this sub-step: nothing to warm the next one with.
    void forgetWarmStart() { warm_.clear(); }
    /// The resting pairs the passes left to the solver are contacts of the tick too (a
    /// shell settling on a heap has touched it): one event per pair and sub-step, at the
    /// time the passes first found it, with the normal impulse the solver gave it.
    void reportDeferred(std::vector<DeferredPair>& deferred, const ParticleSet& set,
                        std::vector<ContactEvent>& events) const;

  private:
    void findNearPairs(const Substep& sub, const Stages& st);
    void buildContacts(const Substep& sub, const SubstepPaths& paths);
    bool addContact(const NearPair& near, double wa, double wb, const Substep& sub,
                    const SubstepPaths& paths);
    void noteLevelsAndBodies(const SolverContact& c);
    void finishContacts(const Substep& sub, const Stages& st);
    void addBody(std::uint32_t i) {
        if (bodyMark_[i]) return;
        bodyMark_[i] = 1;
        bodyIndex_[i] = static_cast<std::uint32_t>(bodies_.size());
        bodies_.push_back(i);
    }
    bool mostAreBodies(std::size_t slots) const { return 2 * bodies_.size() > slots; }
    // The sweeps: copies in, warm start, rows, velocity, position, copies out.
    void sweepContacts(ParticleSet& set, const StaticShapes& shapes, const CollisionDef& def,
                       CollisionStats& stats);
    void copyForSweeps(const ParticleSet& set);
    void copyAfterSweeps(ParticleSet& set) const;
    void warmStart();
    void fillRows(const ParticleSet& set, const std::vector<std::uint32_t>& order,
                  CollisionStats& stats);
    void sweepImpulses(const CollisionDef& def);
    void sweepProjections(const StaticShapes& shapes, const CollisionDef& def);
    /// The slots of the sweeps' copies past the particles: still, at rest, and sink,
    /// which takes the push on an immovable side.
    std::uint32_t stillSlot() const { return static_cast<std::uint32_t>(velocity_.size() - 2); }
    std::uint32_t sinkSlot() const { return stillSlot() + 1; }
    /// Sweeps over each band, from the ground up, with the bands below immovable.
    static constexpr int kShockSweeps = 4;
    /// The position sweeps over all contacts go on (up to relaxPositionSweeps) only while
    /// one pushed a pair apart by more than this share of its cap: a tenth of the smaller
    /// radius. One sweep leaves a resting pile's overlaps (about a hundredth of a radius)
    /// to the bands; more would only move its balls about.
    static constexpr double kDeepPush = 0.5;
    /// Gaps below this, in radii, count as touching (no closing allowed).
    static constexpr double kSlop = 1e-3;

    std::vector<NearPair> nearPairs_; ///< the pairs near enough to be contacts
    std::vector<SolverContact> contacts_;
    struct WarmStart {
        std::uint64_t key; ///< a << 32 | proxy
        double normalImpulse, tangentImpulse;
    };
    std::vector<WarmStart> warm_; ///< the contacts at the end of the last sub-step
    // The particles of the contacts (bodies_, marked in bodyMark_): all that the levels
    // and the sweeps read or write; bodyIndex_[i]: i's place in bodies_.
    std::vector<std::uint32_t> bodies_, bodyIndex_;
    std::vector<std::uint8_t> bodyMark_;
    SweepOrder order_;
    ContactRows rows_;
    bool lanes_ = false;                    ///< this solve's sweeps run in wavefronts of four lanes
    std::vector<Vec2> velocity_, position_; ///< the particles', then still, sink
    std::vector<std::uint8_t> moved_;       ///< by the sweeps, per slot of the copies
};

} // namespace phys
