// The targets still standing (or the enemy cannons in a duel): what a miss is measured
// to and what the camera frames with the shell. One list for the verdict and the view.
#pragma once

#include "physics/vec2.h"

#include <cstddef>
#include <vector>

namespace game {

class Match;

struct StandingTarget {
    std::size_t id = 0;   ///< discs, then blocks, then blobs (cannons in a duel), by index
    phys::Vec2 where;     ///< its centre, m
    double reach = 0.0;   ///< how far its outline reaches from the centre, m
    phys::Vec2 halfSize;  ///< a block's half sizes (zero for a disc, a blob or a cannon), m
    double angle = 0.0;   ///< a block's angle, rad

    /// The distance from `p` to its outline (a block's box, else its circle), 0 inside, m.
    double distanceFrom(phys::Vec2 p) const;
};

/// The targets `shooter` may still hit: in a duel the other cannons with hit points left,
/// else the discs not yet hit and the target blocks and blobs still in place.
std::vector<StandingTarget> standingTargets(const Match& match, int shooter);

} // namespace game
