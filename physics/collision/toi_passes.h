// The passes of a sub-step: detect, then resolve each contact at its time of impact, in
// time order, up to maxPasses times; a pass that resolves nothing ends them.
//
// A pass resolves its candidates (narrowphase.h) in time order: it moves the two
// particles to that time, applies the impulse (Claypool's equation 4 with the pair's
// restitution, and Coulomb friction, contact_impulse.h), and replaces the rest of their
// paths by the ones leaving the contact with the new velocities (paths.h). With the
// integrators exact under constant acceleration, this makes a bounce exact: an apex
// depends on e and H only, not on where the impact fell within the step.
//
// Resting contact (Millington, Game Physics Engine Development): a contact closing slower
// than restingSpeed + |a.n| dt is resting. It does not bounce. On a static shape or an
// immovable particle the surface then supports the particle for the rest of the step
// (SubstepPaths::support): a particle resting on a surface stays exactly where it is,
// with no jitter and no creep; one resting on two (a notch, a corner) is held by both at
// once. A resting pair of free particles (a stack, a pile) is left to the contact solver
// (contact_solver.h), which settles a pile in one step where passes would settle it one
// layer per pass, as is a sleeper lying on a free particle (weight that particle carries,
// not a surface it rests on).
//
// A pass after the first detects again only what the pass before it changed
// (detectChanges): the pass changed nothing but the paths of the particles it bounced,
// stopped or put to rest, so the next pass's candidates are
//   changed    pairs with a particle whose path changed: tested again, from the kept
//              pairs of each such particle filtered by its new box (PairCache::changedPairs);
//   carried    pairs of two unchanged particles: their paths, boxes and time of impact
//              are those of the last pass, so such a pair is a candidate again exactly
//              when it was one then and its resolution changed neither path. That is a
//              resting pair the pass left to the contact solver: a static contact, an
//              impact or a resting contact always changes a path, and a candidate that
//              came to nothing did so because a path had changed.
// These are the candidates a detection over every particle finds, at the same times;
// listed in pair order they keep its tie order too, so the passes resolve the same
// contacts in the same order, to the bit. A pass then costs what the pass before it
// changed, not the world.
#pragma once

#include "physics/collision/awake_set.h"
#include "physics/collision/narrowphase.h"
#include "physics/collision/pair_cache.h"
#include "physics/collision/paths.h"
#include "physics/collision/proxies.h"
#include "physics/collision/sleep.h"
#include "physics/collision/substep.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace phys {

/// A resting pair left to the contact solver in this sub-step, for its contact event.
struct DeferredPair {
    std::uint64_t key;   ///< a << 32 | b
    std::uint32_t order; ///< when it was first left, for a stable report
    double time, closingSpeed;
    Vec2 normal, position;
};

class ToiPasses {
  public:
    using Stages = SubstepStages;
    /// Up to def.maxPasses passes over the active particles' paths; whether the last one
    /// resolved nothing (converged).
    bool run(const Substep& sub, const Stages& st);
    /// The resting pairs of free particles left to the contact solver in this sub-step.
    std::vector<DeferredPair>& deferred() { return deferred_; }

  private:
    void detect(const Substep& sub, const Stages& st);
    bool detectChanges(const Substep& sub, const Stages& st);
    void carryLeftPairs(const std::vector<Candidate>& candidates);
    /// Resolves the candidates of this pass in time order; how many it resolved.
    int resolveInTimeOrder(const Substep& sub, const Stages& st);
    /// What resolving a candidate did: nothing (no contact any more), a resting contact,
    /// an impact, or nothing yet (a resting pair, left to the contact solver).
    enum class Resolution { None, Resting, Impact, Deferred };
    Resolution resolveStatic(const Candidate& c, const Substep& sub, const Stages& st);
    Resolution resolvePair(const Candidate& c, const Substep& sub, const Stages& st);
    /// The pair's time of impact now: the one found at detection while neither path has
    /// changed since.
    std::optional<double> pairTime(const Candidate& c, bool unchanged, const Substep& sub,
                                   const Stages& st) const;
    /// A resting pair of free particles, or a sleeper lying on a free one, at `toi`: left
    /// to the contact solver (true).
    bool leaveToSolver(const Candidate& c, double toi, double wi, double wj, const Substep& sub,
                       const Stages& st);
    /// The impulse of a pair of particles at `toi` and what follows from it.
    Resolution bounce(const Candidate& c, double toi, double wi, double wj, const Substep& sub,
                      const Stages& st);
    /// A resting pair after its impulse, for the rest of the step.
    static void carryResting(std::size_t i, std::size_t j, Vec2 n, double wi, double wj,
                             const PairProperties& pp, double remaining, SubstepPaths& paths);
    double restingLimit(std::size_t i, std::size_t j, double an, const Substep& sub,
                        const SubstepPaths& paths) const;
    /// A path changed by a contact of this pass: the particle is worked on, and not
    /// settled in the next sub-step.
    void markChanged(std::size_t i, const Substep& sub, const Stages& st);

    std::uint32_t pass_ = 0;                 ///< counts passes over the world's life
    std::vector<std::uint32_t> pathChanged_; ///< pass_ when a contact last changed the path
    std::vector<std::uint32_t> changed_;     ///< the particles whose paths this pass changed
    std::vector<std::uint8_t> leftToSolver_; ///< per candidate: a resting pair deferred
    std::vector<Candidate> carried_;         ///< detectChanges' carried candidates
    std::vector<DeferredPair> deferred_;
};

} // namespace phys
