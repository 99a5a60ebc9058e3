// The debug view's overlays (the "Draw" controls), checked through a recorder
// implementation of phys::DebugDraw: exactly what drawOverlays emits, where and in which
// colour. No GL is needed; the picture itself is checked by ui.cli.play_draw_toggles_png.
#include "physics/rigid/rigid_world.h"
#include "ui/render/world_view.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using phys::Color;
using phys::Vec2;
constexpr double kTick = 1.0 / 120.0;

/// Records every call, with its points, radius, colour and text.
class Recorder final : public phys::DebugDraw {
  public:
    enum class Kind { Segment, Circle, SolidCircle, Polygon, SolidPolygon, Point, Text };
    struct Call {
        Kind kind;
        std::vector<Vec2> points;
        double radius = 0.0;
        Color color;
        std::string text;
    };
    std::vector<Call> calls;

    void segment(Vec2 a, Vec2 b, Color c) override { calls.push_back({Kind::Segment, {a, b}, 0, c, {}}); }
    void circle(Vec2 p, double r, Color c) override { calls.push_back({Kind::Circle, {p}, r, c, {}}); }
    void solidCircle(Vec2 p, double r, Vec2, Color c) override {
        calls.push_back({Kind::SolidCircle, {p}, r, c, {}});
    }
    void polygon(std::span<const Vec2> v, Color c) override {
        calls.push_back({Kind::Polygon, {v.begin(), v.end()}, 0, c, {}});
    }
    void solidPolygon(std::span<const Vec2> v, Color c) override {
        calls.push_back({Kind::SolidPolygon, {v.begin(), v.end()}, 0, c, {}});
    }
    void point(Vec2 p, float size, Color c) override { calls.push_back({Kind::Point, {p}, size, c, {}}); }
    void text(Vec2 p, std::string_view t, Color c) override {
        calls.push_back({Kind::Text, {p}, 0, c, std::string(t)});
    }

    std::vector<Call> of(Kind kind, Color color) const {
        std::vector<Call> out;
        for (const Call& c : calls)
            if (c.kind == kind && c.color == color) out.push_back(c);
        return out;
    }
    bool allFinite() const {
        for (const Call& c : calls) {
            if (!std::isfinite(c.radius)) return false;
            for (const Vec2 p : c.points)
                if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
        }
        return true;
    }
};

using Kind = Recorder::Kind;

phys::ParticleId addBall(phys::World& w, Vec2 at, Vec2 v = {}, double mass = 1.0,
                         double radius = 0.1, std::uint32_t flags = 0) {
    phys::ParticleDef pd;
    pd.position = at;
    pd.velocity = v;
    pd.mass = mass;
    pd.radius = radius;
    pd.flags = flags;
    return w.particles.add(pd);
}

ui::WorldDrawOptions only(void (*pick)(ui::DebugOverlays&)) {
    ui::WorldDrawOptions o;
    pick(o.overlays);
    o.pixel = 0.01;
    return o;
}

/// What drawOverlays emits for `w` under `o`.
Recorder record(const phys::World& w, const ui::WorldDrawOptions& o) {
    Recorder rec;
    ui::drawOverlays(rec, w, o);
    return rec;
}

/// Flat static ground along y = 0, and the definition of a dynamic body at `at`.
phys::BodyDef onFlatGround(phys::RigidWorld& rigid, Vec2 at) {
    const std::array<Vec2, 2> ground{Vec2{-20.0, 0.0}, Vec2{20.0, 0.0}};
    rigid.createTerrain(ground, {});
    phys::BodyDef bd;
    bd.type = phys::BodyType::Dynamic;
    bd.position = at;
    return bd;
}

TEST(Overlays, NothingIsDrawnWhileEveryToggleIsOff) {
    phys::World w;
    addBall(w, {0.0, 1.0}, {3.0, 4.0});
    EXPECT_TRUE(record(w, {}).calls.empty());
    Recorder rec;
    ui::drawWorld(rec, w, {});
    ASSERT_EQ(rec.calls.size(), 1u) << "the particle's disc and nothing else";
    EXPECT_EQ(rec.calls[0].kind, Kind::SolidCircle);
}

// The ghost of an explicit-Euler shell sits at ballisticState(launch, t) and the line to
// the shell is explicit Euler's error, |g| h^2 k / 2 after k steps.
TEST(Overlays, TheGhostOfAnExplicitEulerShellShowsTheIntegratorsError) {
    phys::WorldDef def;
    def.model = phys::ModelPolicy::Integrate;
    def.integrator = phys::Integrator::ExplicitEuler;
    def.tickSeconds = kTick;
    phys::World w(def);
    const phys::ParticleId shell = addBall(w, {0.0, 2.0}, {30.0, 40.0}, 4.0, 0.11);
    phys::ClosedFormGhosts ghosts;
    w.step();
    ghosts.observe(w);
    const auto launch = *ghosts.launch(shell);
    const int k = 180;
    for (int i = 0; i < k; ++i) {
        w.step();
        ghosts.observe(w);
    }
    ui::WorldDrawOptions o = only([](ui::DebugOverlays& d) { d.ghosts = true; });
    o.ghosts = &ghosts;
    const Recorder rec = record(w, o);

    const auto ghost = rec.of(Kind::Circle, ui::kOverlayGhost);
    ASSERT_EQ(ghost.size(), 1u);
    const phys::BallisticState exact = phys::ballisticState(launch.position, launch.velocity,
                                                            {0.0, -9.81}, w.time() - launch.time);
    EXPECT_NEAR(ghost[0].points[0].x, exact.position.x, 1e-12);
    EXPECT_NEAR(ghost[0].points[0].y, exact.position.y, 1e-12);
    EXPECT_EQ(ghost[0].radius, 0.11);
    EXPECT_EQ(rec.of(Kind::SolidCircle, ui::kOverlayGhostPath).size(), 1u) << "its faint disc";

    const auto error = rec.of(Kind::Segment, ui::kOverlayGhostError);
    ASSERT_EQ(error.size(), 1u);
    EXPECT_EQ(error[0].points[0], ghost[0].points[0]);
    EXPECT_EQ(error[0].points[1], w.particles.position(shell));
    const double expected = 9.81 * kTick * kTick * k / 2.0; // 0.0613 m
    EXPECT_NEAR(phys::length(error[0].points[1] - error[0].points[0]), expected, 1e-9);
    const auto label = rec.of(Kind::Text, ui::kOverlayGhost);
    ASSERT_EQ(label.size(), 1u);
    EXPECT_EQ(label[0].text, "0.0613 m");

    // The exact parabola from the launch to the ghost.
    const auto path = rec.of(Kind::Segment, ui::kOverlayGhostPath);
    ASSERT_EQ(path.size(), 40u);
    EXPECT_EQ(path.front().points[0], launch.position);
    EXPECT_NEAR(path.back().points[1].x, exact.position.x, 1e-9);
    EXPECT_NEAR(path.back().points[1].y, exact.position.y, 1e-9);
}

TEST(Overlays, TheForceOnAParticleAtRestIsItsWeight) {
    phys::World w;
    const phys::ParticleId heavy = addBall(w, {0.0, 5.0}, {}, 3.0);
    const phys::ParticleId light = addBall(w, {2.0, 5.0}, {}, 0.05);
    std::vector<Vec2> f;
    phys::netForces(w, f);
    EXPECT_EQ(f[heavy], (Vec2{0.0, -3.0 * 9.81}));
    EXPECT_EQ(f[light], (Vec2{0.0, -0.05 * 9.81}));
    const Recorder rec = record(w, only([](ui::DebugOverlays& d) { d.forces = true; }));
    const auto arrows = rec.of(Kind::Segment, ui::kOverlayForce);
    ASSERT_EQ(arrows.size(), 6u) << "a shaft and two barbs each";
    // Drawn in weights: m g is weightArrowPixels (30 px of 1 cm) straight down, whatever
    // the mass.
    EXPECT_EQ(arrows[0].points[0], w.particles.position(heavy));
    EXPECT_NEAR(arrows[0].points[1].x, 0.0, 1e-12);
    EXPECT_NEAR(arrows[0].points[1].y, 5.0 - 0.3, 1e-12);
    EXPECT_EQ(arrows[3].points[0], w.particles.position(light));
    EXPECT_NEAR(arrows[3].points[1].y, 5.0 - 0.3, 1e-12);
    EXPECT_TRUE(rec.of(Kind::Segment, ui::kOverlayVelocity).empty()) << "a distinct colour";
}

TEST(Overlays, AForceOfManyWeightsIsClippedAndDoubleHeaded) {
    phys::WorldDef def;
    def.forces.gravity = {};
    phys::World w(def);
    const phys::ParticleId link = addBall(w, {0.0, 0.0}, {}, 0.1);
    phys::Spring s; // 10 N/m stretched by 1 m: 10 N on 0.1 kg, 10.2 "weights" of 9.81
    s.a = link;
    s.anchor = {2.0, 0.0};
    s.restLength = 1.0;
    s.stiffness = 10.0;
    w.springs.push_back(s);
    const Recorder rec = record(w, only([](ui::DebugOverlays& d) { d.forces = true; }));
    const auto arrows = rec.of(Kind::Segment, ui::kOverlayForce);
    ASSERT_EQ(arrows.size(), 5u) << "a shaft and two heads";
    EXPECT_NEAR(arrows[0].points[1].x, ui::DebugOverlays::kMaxWeights * 30.0 * 0.01, 1e-12);
    EXPECT_NEAR(arrows[0].points[1].y, 0.0, 1e-12);
}

TEST(Overlays, SleepingParticlesAndBodiesAreMarked) {
    phys::World w;
    w.shapes.addSegment({-10.0, 0.0}, {10.0, 0.0});
    const phys::ParticleId sleeper = addBall(w, {0.0, 0.1});
    phys::RigidWorld rigid;
    rigid.createBox(onFlatGround(rigid, {5.0, 0.5}), {0.5, 0.5}, {});
    for (int i = 0; i < 240; ++i) {
        w.step();
        rigid.step(kTick);
    }
    ASSERT_TRUE(w.particles.flags[sleeper] & phys::kSleeping);
    ASSERT_EQ(rigid.profile().sleepingBodies, 1);
    const phys::ParticleId flying = addBall(w, {0.0, 8.0}, {1.0, 1.0});
    ui::WorldDrawOptions o = only([](ui::DebugOverlays& d) { d.sleeping = true; });
    o.rigid = &rigid;
    const Recorder rec = record(w, o);
    const auto shade = rec.of(Kind::SolidCircle, ui::kOverlaySleepShade);
    ASSERT_EQ(shade.size(), 1u) << "the sleeper, not the ball in flight";
    EXPECT_EQ(shade[0].points[0], w.particles.position(sleeper));
    EXPECT_EQ(rec.of(Kind::SolidPolygon, ui::kOverlaySleepShade).size(), 1u) << "the box";
    EXPECT_EQ(rec.of(Kind::Segment, ui::kOverlaySleep).size(), 6u) << "a z on each";
    (void)flying;
}

TEST(Overlays, ModelsAreColouredByWhatMovesThem) {
    phys::WorldDef def;
    def.forces.drag = phys::DragModel::Quadratic;
    phys::World w(def);
    const phys::ParticleId closed = addBall(w, {0.0, 50.0}, {5.0, 5.0}, 1.0, 0.1, phys::kNoDrag);
    const phys::ParticleId integrated = addBall(w, {5.0, 50.0}, {5.0, 5.0});
    const phys::ParticleId fixed = addBall(w, {9.0, 9.0}, {}, 0.0);
    w.step();
    phys::RigidWorld rigid;
    phys::BodyDef bd;
    bd.type = phys::BodyType::Dynamic;
    bd.position = {20.0, 30.0};
    rigid.createBox(bd, {0.5, 0.5}, {});
    rigid.step(kTick);
    ui::WorldDrawOptions o = only([](ui::DebugOverlays& d) { d.models = true; });
    o.rigid = &rigid;
    const Recorder rec = record(w, o);
    auto ringAt = [&](phys::ParticleModel m) {
        const auto rings = rec.of(Kind::Circle, ui::modelColor(m));
        return rings.size() == 1 ? rings[0].points[0] : Vec2{NAN, NAN};
    };
    EXPECT_EQ(ringAt(phys::ParticleModel::ClosedForm), w.particles.position(closed));
    EXPECT_EQ(ringAt(phys::ParticleModel::Integrated), w.particles.position(integrated));
    EXPECT_EQ(ringAt(phys::ParticleModel::Fixed), w.particles.position(fixed));
    EXPECT_EQ(rec.of(Kind::Polygon, ui::kOverlayRigidAwake).size(), 1u) << "the falling box";
}

TEST(Overlays, OccupiedCellsAreDrawnAsTheirSquares) {
    phys::WorldDef def;
    def.collision.gridCellSize = 2.0;
    phys::World w(def);
    addBall(w, {0.5, 0.5});
    addBall(w, {-1.0, 3.0});
    const Recorder rec = record(w, only([](ui::DebugOverlays& d) { d.cells = true; }));
    const auto cells = rec.of(Kind::Polygon, ui::kOverlayCell);
    ASSERT_EQ(cells.size(), 2u);
    EXPECT_EQ(cells[0].points, (std::vector<Vec2>{{-2, 2}, {0, 2}, {0, 4}, {-2, 4}}));
    EXPECT_EQ(cells[1].points, (std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
}

TEST(Overlays, ContactNormalsOfABallOnTheGroundPointUp) {
    phys::World w;
    phys::RigidWorld rigid;
    rigid.createCircle(onFlatGround(rigid, {0.0, 0.5}), 0.5, {});
    for (int i = 0; i < 60; ++i) rigid.step(kTick);
    ui::WorldDrawOptions o = only([](ui::DebugOverlays& d) { d.contacts = true; });
    o.rigid = &rigid;
    const Recorder rec = record(w, o);
    const auto points = rec.of(Kind::Point, ui::kOverlayContact);
    ASSERT_EQ(points.size(), 1u);
    EXPECT_NEAR(points[0].points[0].x, 0.0, 1e-4);
    EXPECT_NEAR(points[0].points[0].y, 0.0, 0.02);
    const auto normal = rec.of(Kind::Segment, ui::kOverlayContact);
    ASSERT_EQ(normal.size(), 3u);
    const Vec2 d = normal[0].points[1] - normal[0].points[0];
    EXPECT_NEAR(d.x, 0.0, 1e-6);
    EXPECT_NEAR(d.y, 12.0 * o.pixel, 1e-6) << "0.3 m, but at most 12 px, up";
}

TEST(Overlays, NeverEmitANonFiniteCoordinate) {
    phys::WorldDef def;
    def.model = phys::ModelPolicy::Integrate;
    phys::World w(def);
    w.shapes.addSegment({-10.0, 0.0}, {10.0, 0.0});
    const phys::ParticleId bad = addBall(w, {0.0, 3.0}, {1.0, 0.0});
    addBall(w, {2.0, 0.1});
    phys::ClosedFormGhosts ghosts;
    for (int i = 0; i < 5; ++i) {
        w.step();
        ghosts.observe(w);
    }
    // What a blow-up leaves before the guard removes it.
    w.particles.px[bad] = std::numeric_limits<double>::quiet_NaN();
    w.particles.vy[bad] = std::numeric_limits<double>::infinity();
    ui::WorldDrawOptions o;
    o.overlays = {true, true, true, true, true, true, true};
    o.ghosts = &ghosts;
    Recorder rec;
    ui::drawWorld(rec, w, o);
    EXPECT_FALSE(rec.calls.empty());
    EXPECT_TRUE(rec.allFinite());
}

} // namespace
