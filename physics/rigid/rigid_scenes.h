// Rigid scenes shared by tests, benchmarks and (later) the sandbox, so the figures the
// benchmark prints are about the same scene the tests check.
#pragma once

#include "physics/rigid/rigid_world.h"

#include <vector>

namespace phys {

/// Columns of stacked boxes on flat terrain at y = 0, with defaults and units.
struct RigidTowerDef {
    int columns = 1;                           ///< side by side, >= 1
    int height = 10;                           ///< boxes per column, >= 1
    double boxSize = 0.5;                      ///< edge of each box, m
    double columnGap = 0.5;                    ///< free space between columns, m
    RigidMaterial material{600.0, 0.6, 0.603}; ///< wooden block: pine ~600 kg/m^3 x 1 m
                                               ///< depth, wooden COR preset 0.603
};

/// Builds the floor and the tower; returns the boxes, bottom to top, column by column.
/// Boxes start resting exactly on each other (their skins overlapping by b2_linearSlop),
/// so nothing falls and the tower settles in a few ticks.
std::vector<BodyId> buildTower(RigidWorld& world, const RigidTowerDef& def);

} // namespace phys
