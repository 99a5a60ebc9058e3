#include "physics/rigid/rigid_scenes.h"

#include <box2d/b2_common.h>

#include <array>

namespace phys {

std::vector<BodyId> buildTower(RigidWorld& world, const RigidTowerDef& def) {
    const double pitch = def.boxSize + def.columnGap;
    const double width = def.columns * pitch + 20.0;
    const std::array<Vec2, 2> floor{Vec2{-width, 0.0}, Vec2{width, 0.0}};
    RigidMaterial ground;
    ground.friction = def.material.friction;
    world.createTerrain(floor, ground);

    // A resting pair of Box2D shapes overlaps by b2_linearSlop inside their skins (each
    // polygon/edge carries b2_polygonRadius); spacing the boxes that way starts them at
    // rest instead of dropping them through the skin gap.
    const double skin = b2_polygonRadius;
    const double slop = b2_linearSlop;
    const double half = 0.5 * def.boxSize;
    std::vector<BodyId> boxes;
    for (int c = 0; c < def.columns; ++c) {
        double y = skin - slop + skin + half; // floor skin + box skin, minus the slop
        for (int k = 0; k < def.height; ++k) {
            BodyDef bd;
            bd.position = {c * pitch, y};
            boxes.push_back(world.createBox(bd, {half, half}, def.material));
            y += def.boxSize + 2.0 * skin - slop;
        }
    }
    return boxes;
}

} // namespace phys
