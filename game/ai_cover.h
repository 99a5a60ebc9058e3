// What stands in a trial shot's way. The match's preview flies the shell alone (bodies
// are left out of it), but a shell does not fly through a wall of blocks: the computer
// cuts each trial path at the first block it enters, so it aims over or around its own
// castle and the other's instead of into them, and where no path is clear, its closest
// one ends on the wall nearest its target (a breach).
#pragma once

#include "game/match.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace game {

class BlockCover {
  public:
    /// Nothing in the way.
    BlockCover() = default;
    /// The blocks standing in `match` now, each grown by `margin` m (the shell's radius),
    /// but any that holds `target`: a target block is what the shot is for.
    BlockCover(const Match& match, phys::Vec2 target, double margin);
    /// The index of the first point of `path` inside a block, or path.size() if none is.
    std::size_t firstBlocked(const std::vector<phys::Vec2>& path) const;
    bool empty() const { return boxes_.empty(); }

  private:
    struct Box {
        phys::Vec2 centre, half; ///< m, in the block's frame
        double cos = 1.0, sin = 0.0;
        bool contains(phys::Vec2 p) const;
    };
    /// Columns of kColumn m along x, each listing the boxes that reach into it, so a
    /// point is tested against the few boxes near it.
    long column(double x) const;
    std::vector<Box> boxes_;
    std::vector<std::pair<long, std::uint32_t>> columns_; ///< (column, box), sorted
};

} // namespace game
