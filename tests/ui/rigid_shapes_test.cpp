// RigidWorld::forEachShape, the accessor MatchView draws Box2D blocks with: every
// fixture in world coordinates (it lives in physics/, tested here beside its one user).
#include "physics/rigid/rigid_world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

using phys::RigidShapeView;
using phys::Vec2;

TEST(RigidShapes, BoxesCirclesAndTerrainComeOutInWorldCoordinates) {
    phys::RigidWorld world;
    phys::BodyDef box;
    box.position = {1.0, 2.0};
    box.angle = std::numbers::pi / 2; // a quarter turn: half extents swap on screen
    const phys::BodyId boxId = world.createBox(box, {0.5, 0.25}, {});
    phys::BodyDef ball;
    ball.position = {-3.0, 4.0};
    world.createCircle(ball, 0.7, {});
    const Vec2 ground[] = {{-10.0, 0.0}, {0.0, -1.0}, {10.0, 0.0}};
    world.createTerrain(ground, {});

    std::vector<RigidShapeView::Kind> kinds;
    world.forEachShape([&](const RigidShapeView& s) {
        kinds.push_back(s.kind);
        if (s.kind == RigidShapeView::Kind::Polygon) {
            EXPECT_EQ(s.body, boxId);
            EXPECT_EQ(s.type, phys::BodyType::Dynamic);
            ASSERT_EQ(s.vertices.size(), 4u);
            for (const Vec2 v : s.vertices) {
                // Turned by 90 degrees: 0.25 m either side in x, 0.5 m in y.
                EXPECT_NEAR(std::abs(v.x - 1.0), 0.25, 1e-6);
                EXPECT_NEAR(std::abs(v.y - 2.0), 0.5, 1e-6);
            }
        } else if (s.kind == RigidShapeView::Kind::Circle) {
            EXPECT_NEAR(s.center.x, -3.0, 1e-6);
            EXPECT_NEAR(s.center.y, 4.0, 1e-6);
            EXPECT_NEAR(s.radius, 0.7, 1e-6);
        } else {
            EXPECT_EQ(s.type, phys::BodyType::Static);
            ASSERT_EQ(s.vertices.size(), 3u);
            EXPECT_FALSE(s.loop);
            EXPECT_NEAR(s.vertices[1].y, -1.0, 1e-6);
        }
    });
    ASSERT_EQ(kinds.size(), 3u);
    EXPECT_EQ(kinds[0], RigidShapeView::Kind::Polygon);
    EXPECT_EQ(kinds[1], RigidShapeView::Kind::Circle);
    EXPECT_EQ(kinds[2], RigidShapeView::Kind::Chain);
}

TEST(RigidShapes, DestroyedBodiesAreNotReported) {
    phys::RigidWorld world;
    const phys::BodyId a = world.createBox({}, {0.5, 0.5}, {});
    world.destroyBody(a);
    int n = 0;
    world.forEachShape([&](const RigidShapeView&) { ++n; });
    EXPECT_EQ(n, 0);
}

} // namespace
