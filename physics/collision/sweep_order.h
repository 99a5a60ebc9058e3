// The contact solver's sweep order (contact_solver.h): which contact each sweep takes
// when, so that a stack is stopped and lifted from the bottom up.
//
// Levels: a particle's level is how many particles down, holding each other up against
// gravity, it is from the ground (a static shape or an immovable particle: level 0); what
// the ground holds up is level 1, what that holds up level 2, breadth first. Bands: a
// contact belongs to the level of its upper particle; within a band the contacts with
// something immovable come after the others. The solver sweeps all contacts, then band by
// band from the ground up with what holds a band up immovable (shock propagation,
// Guendelman, Bridson and Fedkiw, "Nonconvex rigid bodies with stacking", 2003).
//
// Where the sweeps take four rows at a time (simd/contact_rows.h), the order is laid out
// in wavefronts (wavefronts.h), with a barrier before each band; a band whose wavefronts
// would be mostly padding is swept one row at a time in its own order instead. Either
// way the sweeps give the bits of the one-row sweep in the order.
#pragma once

#include "physics/collision/solver_contact.h"
#include "physics/collision/wavefronts.h"
#include "physics/particles.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace phys {

class SweepOrder {
  public:
    static constexpr std::uint32_t kUnsupported = 0xffffffffu;
    /// Starts a solve over n particles: no holds, and every level unknown.
    void prepare(std::size_t n);
    /// What the build learns of each contact: i is immovable (ground), i stands on the
    /// ground, holder holds held up (both movable).
    void ground(std::uint32_t i) { level_[i] = 0; }
    void onGround(std::uint32_t i) { level_[i] = 1; }
    void hold(std::uint32_t holder, std::uint32_t held) { holds_.push_back({holder, held}); }
    /// order(): the contacts by band, from the ground up. `bodies`: the contacts'
    /// particles, bodyIndex[i] the place of i among them.
    void orderByLevel(const std::vector<SolverContact>& contacts,
                      const std::vector<std::uint32_t>& bodies,
                      const std::vector<std::uint32_t>& bodyIndex);
    /// The rows of the sweeps, in order (with kPadding rows where the lanes run), and
    /// from where each band's rows start (rowStart); `still`: the slot that orders nothing.
    const std::vector<std::uint32_t>& layOut(bool lanes, const std::vector<SolverContact>& contacts,
                                             std::uint32_t still);
    /// Back to unknown for each of the solve's particles (every level is unknown outside a
    /// solve).
    void forget(std::uint32_t i) { level_[i] = kUnsupported; }

    /// The level of the contact's upper particle (kUnsupported if it has none).
    std::uint32_t bandOf(const SolverContact& c) const {
        return c.b == kNoParticle ? level_[c.a] : std::max(level_[c.a], level_[c.b]);
    }
    /// The inverse masses of contact c under shock propagation in its band: the particle
    /// that holds the other up, if it is settled already (a lower level), is immovable.
    std::pair<double, double> shockMasses(const SolverContact& c, std::uint32_t band) const {
        double wa = c.wa, wb = c.wb;
        if (c.support == 1 && c.b != kNoParticle && level_[c.b] < band) wb = 0.0;
        if (c.support == -1 && level_[c.a] < band) wa = 0.0;
        return {wa, wb};
    }
    /// Bands: 0 (never used: the ground does not move) up to the last, which holds what no
    /// path of contacts connects to the ground.
    std::size_t bands() const { return bandStart_.size() - 1; }
    std::uint32_t rowStart(std::size_t band) const { return rowStart_[band]; }
    std::uint32_t rowEnd(std::size_t band) const { return rowStart_[band + 1]; }
    bool bandInLanes(std::size_t band) const { return bandLanes_[band] != 0; }
    /// The sweeps over all contacts as runs of bands swept the same way.
    struct Run {
        std::uint32_t from, to;
        bool lanes;
    };
    const std::vector<Run>& runs() const { return runs_; }

  private:
    void findLevels(const std::vector<std::uint32_t>& bodies,
                    const std::vector<std::uint32_t>& bodyIndex);
    void sortIntoBands(const std::vector<SolverContact>& contacts,
                       const std::vector<std::uint32_t>& bodies);
    const std::vector<std::uint32_t>&
    keepLanesWhereTheyFill(const std::vector<std::uint32_t>& wavefronts);
    void joinBandsIntoRuns();
    /// A band whose wavefronts take more rows than this a contact is swept one row at a
    /// time (on a staggered heap, 1.5 was slower and 3 no faster).
    static constexpr double kMostRowsPerContact = 2.0;
    std::vector<std::uint32_t> level_; ///< by particle
    /// Who holds whom up among the movable particles, one entry per such contact, in the
    /// contacts' order (the build lists them; the levels read these, not the contacts).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> holds_;              ///< holder, held
    std::vector<std::uint32_t> adjacencyStart_, adjacency_, fill_, frontier_; ///< the search
    std::vector<std::uint32_t> keyStart_, contactKey_;                        ///< the sort
    std::vector<std::uint32_t> order_, bandStart_; ///< the contacts by band
    Wavefronts wavefronts_;
    std::vector<std::uint32_t> rowStart_, mixedOrder_; ///< the rows as laid out
    std::vector<std::uint8_t> bandLanes_; ///< per band: swept in lanes (else one row at a time)
    std::vector<Run> runs_;
};

} // namespace phys
