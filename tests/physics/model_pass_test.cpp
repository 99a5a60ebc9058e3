// The fused model pass (model_pass.h) against the separate sweeps it replaces: model
// choice, closed-form launch, integrate(SymplecticEuler or VelocityVerlet) and the
// closed-form advance give
// the same bits, and the same counts, for every mix of flags, drag law and water.
#include "physics/model_pass.h"

#include "physics/ballistics.h"
#include "physics/integrators.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

using namespace phys;

namespace {

// A set with every kind of particle: drag-free, weightless, fixed, asleep, dead, already
// on the closed form (some off their parabola), attractors, some under water; an odd
// number of slots so the paired path has a tail; and a run of plain ones (alive, awake,
// massive, with drag and gravity), which the lane sweeps step without masks.
ParticleSet mixedSet(unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    ParticleSet s;
    for (int i = 0; i < 301; ++i) {
        ParticleDef d;
        d.position = {20.0 * u(rng), 5.0 + 5.0 * u(rng)};
        d.velocity = {10.0 * u(rng), 10.0 * u(rng)};
        d.mass = 0.5 + 0.4 * u(rng);
        d.radius = 0.05 + 0.04 * u(rng);
        d.dragCoefficient = 0.47 + 0.2 * u(rng);
        const bool plain = i >= 200 && i < 264;
        if (plain) {
            s.add(d);
            continue;
        }
        if (i % 7 == 0) d.flags |= kNoDrag;
        if (i % 11 == 0) d.flags |= kNoGravity;
        if (i % 13 == 0) d.mass = 0.0;
        if (i % 17 == 0) d.flags |= kSleeping;
        if (i % 19 == 0) d.flags |= kAttractor;
        s.add(d);
    }
    for (std::size_t i = 0; i < s.slots(); i += 5) { // on the closed form since t = 0.5 s
        if (s.invMass[i] <= 0.0 || (s.flags[i] & kSleeping) || (i >= 200 && i < 264)) continue;
        s.flags[i] |= kBallistic;
        s.launchX[i] = s.px[i], s.launchY[i] = s.py[i];
        s.launchVx[i] = s.vx[i], s.launchVy[i] = s.vy[i];
        s.launchT[i] = i % 10 == 0 ? 0.5 : NAN; // some not launched yet
    }
    // A run on the closed form in whole groups of lanes, free of drag (which would hand
    // them to the integrator), launched at t = 0.3 s: on their parabola at 0.5 s (where
    // ballisticState puts them), off it (pushed), or not launched yet.
    for (std::size_t i = 268; i < 300; ++i) {
        if (s.invMass[i] <= 0.0 || (s.flags[i] & kSleeping)) continue;
        s.flags[i] |= kBallistic | kNoDrag;
        s.launchX[i] = s.px[i], s.launchY[i] = s.py[i];
        s.launchVx[i] = s.vx[i], s.launchVy[i] = s.vy[i];
        s.launchT[i] = i % 3 == 2 ? NAN : 0.3;
        const BallisticState now =
            ballisticState(s.position(i), s.velocity(i), ForceDef{}.gravity, 0.2);
        s.px[i] = now.position.x + (i % 3 == 1 ? 1e-3 : 0.0), s.py[i] = now.position.y;
        s.vx[i] = now.velocity.x, s.vy[i] = now.velocity.y;
    }
    s.remove(4);
    s.remove(40);
    return s;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// One setting of the forces and the model rule the fused pass is compared under.
struct FlightCase {
    Integrator method;
    DragModel drag;
    bool water;     ///< buoyancy and water drag (one particle at a time)
    bool choose;    ///< the model is chosen in this sweep (the first sub-step)
    bool allowed;   ///< ModelPolicy::Auto
    bool onSprings; ///< some particles are tethered (springs or rods)
};

// The separate sweeps, as World::step makes them for the other integrators.
ModelCounts separateSweeps(ParticleSet& s, const FlightCase& c, const ForceDef& f,
                           const ModelRule& rule, double h, double start, double end) {
    ModelCounts counts;
    for (std::size_t i = 0; i < s.slots(); ++i)
        countModel(counts, c.choose ? chooseModel(s, i, rule) : s.flags[i], s.invMass[i]);
    for (std::size_t i = 0; i < s.slots(); ++i)
        if (s.flags[i] & kBallistic) launchBallistic(s, i, f.gravity, start);
    const std::vector<Spring> none;
    IntegratorScratch scratch;
    integrate(c.method, Dynamics(f, none, s), s, h, scratch);
    for (std::size_t i = 0; i < s.slots(); ++i)
        if (s.flags[i] & kBallistic) advanceBallistic(s, i, f.gravity, end);
    return counts;
}

void expectSameFlight(const FlightCase& c) {
    ForceDef f;
    f.drag = c.drag;
    f.linearDrag = 0.3;
    f.wind = {2.0, -0.5};
    f.water = c.water;
    f.waterLevel = 4.0;
    const double h = 1.0 / 120.0, start = 0.5, end = 0.5 + h;
    std::vector<std::uint8_t> tethered(301, 0);
    for (std::size_t i = 0; i < tethered.size(); i += 9)
        tethered[i] = 1;
    const ModelRule rule(f, c.allowed, h, c.onSprings ? tethered.data() : nullptr);
    ParticleSet ref = mixedSet(7);
    const ModelCounts want = separateSweeps(ref, c, f, rule, h, start, end);
    const FlightScheme scheme = c.method == Integrator::VelocityVerlet
                                    ? FlightScheme::VelocityVerlet
                                    : FlightScheme::SymplecticEuler;
    for (const int lanes : {1, 2, 4}) {
        ParticleSet fused = mixedSet(7);
        const ModelCounts got =
            flightPass(fused, f, c.choose ? &rule : nullptr, h, start, end, scheme, lanes);
        SCOPED_TRACE(::testing::Message()
                     << "integrator " << static_cast<int>(c.method) << " drag "
                     << static_cast<int>(c.drag) << " water " << c.water << " choose " << c.choose
                     << " auto " << c.allowed << " tethered " << c.onSprings << " lanes " << lanes);
        for (auto column : {&ParticleSet::px, &ParticleSet::py, &ParticleSet::vx, &ParticleSet::vy,
                            &ParticleSet::launchX, &ParticleSet::launchY, &ParticleSet::launchVx,
                            &ParticleSet::launchVy, &ParticleSet::launchT})
            EXPECT_TRUE(sameBits(fused.*column, ref.*column));
        EXPECT_EQ(fused.flags, ref.flags);
        EXPECT_EQ(got.closedForm, want.closedForm);
        EXPECT_EQ(got.integrated, want.integrated);
        EXPECT_EQ(got.sleeping, want.sleeping);
        EXPECT_EQ(got.fixed, want.fixed);
        EXPECT_EQ(got.asleep, want.asleep);
    }
}

} // namespace

TEST(ModelPass, FlightPassGivesTheSeparateSweepsBitForBit) {
    int compared = 0;
    for (const Integrator method : {Integrator::SymplecticEuler, Integrator::VelocityVerlet})
        for (const DragModel drag : {DragModel::None, DragModel::Linear, DragModel::Quadratic})
            for (const bool water : {false, true})
                for (const bool choose : {true, false})
                    for (const bool allowed : {true, false})
                        for (const bool onSprings : {true, false}) {
                            expectSameFlight({method, drag, water, choose, allowed, onSprings});
                            ++compared;
                        }
    EXPECT_EQ(compared, 96); // cases, each with one, two and four lanes
}

// Without collisions the world counts the models in the fused sweep; the profile says
// the same as a count of the flags after the tick.
TEST(ModelPass, WorldCountsWhatTheFlagsSay) {
    for (const Integrator method : {Integrator::SymplecticEuler, Integrator::RK4}) {
        WorldDef d;
        d.integrator = method;
        d.collision.model = ContactModel::None;
        d.forces.drag = DragModel::Quadratic;
        World w(d);
        w.particles = mixedSet(3);
        for (int t = 0; t < 3; ++t)
            w.step();
        int fixed = 0, asleep = 0, closed = 0, integrated = 0;
        for (std::size_t i = 0; i < w.particles.slots(); ++i) {
            const std::uint32_t f = w.particles.flags[i];
            if (!(f & kAlive)) continue;
            if (w.particles.invMass[i] <= 0.0)
                ++fixed;
            else if (f & kSleeping)
                ++asleep;
            else if (f & kBallistic)
                ++closed;
            else
                ++integrated;
        }
        EXPECT_EQ(w.profile().fixed, fixed) << info(method).name;
        EXPECT_EQ(w.profile().sleeping, asleep) << info(method).name;
        EXPECT_EQ(w.profile().closedForm, closed) << info(method).name;
        EXPECT_EQ(w.profile().integrated, integrated) << info(method).name;
        EXPECT_GT(closed, 0); // the drag-free ones
        EXPECT_GT(integrated, 0);
    }
}

// A tick without collisions restarts every awake particle's rest timer, as a sleep sweep
// over a tick without contacts would: a ball resting on the floor needs sleepTime of
// rest after collisions come back before it sleeps, however long it rested before.
TEST(ModelPass, ATickWithoutCollisionsRestartsTheRestTimer) {
    WorldDef d;
    World w(d);
    w.shapes.addSegment({-1.0, 0.0}, {1.0, 0.0}, material::kFloor);
    ParticleDef pd;
    pd.position = {0.0, 0.05};
    pd.radius = 0.05;
    const auto id = w.particles.add(pd);
    for (int i = 0; i < 50; ++i)
        w.step(); // 0.42 s of rest: almost asleep
    ASSERT_FALSE(w.particles.flags[id] & kSleeping);
    WorldDef off = d;
    off.collision.model = ContactModel::None;
    w.setDef(off);
    w.step();
    w.setDef(d);
    int ticks = 0;
    while (!(w.particles.flags[id] & kSleeping) && ticks < 1000) {
        w.step();
        ++ticks;
    }
    // 0.5 s at 1/120 s is 60 ticks of rest, counted from the tick collisions came back.
    EXPECT_GE(ticks, 60);
    EXPECT_LT(ticks, 240);
}
