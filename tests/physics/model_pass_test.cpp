// The fused model pass (model_pass.h) against the separate sweeps it replaces: model
// choice, closed-form launch, integrate(SymplecticEuler or VelocityVerlet) and the
// closed-form advance give
// the same bits, and the same counts, for every mix of flags, drag law and water.
#include "physics/model_pass.h"

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
    s.remove(4);
    s.remove(40);
    return s;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

} // namespace

TEST(ModelPass, FlightPassGivesTheSeparateSweepsBitForBit) {
    int compared = 0;
    for (const Integrator method : {Integrator::SymplecticEuler, Integrator::VelocityVerlet}) {
        const FlightScheme scheme = method == Integrator::VelocityVerlet
                                        ? FlightScheme::VelocityVerlet
                                        : FlightScheme::SymplecticEuler;

        for (const DragModel drag : {DragModel::None, DragModel::Linear, DragModel::Quadratic})
            for (const bool water : {false, true})
                for (const bool choose : {true, false})
                    for (const bool allowed : {true, false}) {
                        ForceDef f;
                        f.drag = drag;
                        f.linearDrag = 0.3;
                        f.wind = {2.0, -0.5};
                        f.water = water;
                        f.waterLevel = 4.0;
                        const double h = 1.0 / 120.0, start = 0.5, end = 0.5 + h;
                        std::vector<std::uint8_t> tethered(301, 0);
                        for (std::size_t i = 0; i < tethered.size(); i += 9)
                            tethered[i] = 1;
                        const ModelRule rule(f, allowed, h, tethered.data());

                        // The separate sweeps, as World::step makes them for other integrators.
                        ParticleSet ref = mixedSet(7);
                        ModelCounts want;
                        for (std::size_t i = 0; i < ref.slots(); ++i) {
                            const std::uint32_t fl =
                                choose ? chooseModel(ref, i, rule) : ref.flags[i];
                            countModel(want, fl, ref.invMass[i]);
                        }
                        for (std::size_t i = 0; i < ref.slots(); ++i)
                            if (ref.flags[i] & kBallistic)
                                launchBallistic(ref, i, f.gravity, start);
                        const std::vector<Spring> none;
                        IntegratorScratch scratch;
                        integrate(method, Dynamics(f, none, ref), ref, h, scratch);
                        for (std::size_t i = 0; i < ref.slots(); ++i)
                            if (ref.flags[i] & kBallistic) advanceBallistic(ref, i, f.gravity, end);

                        for (const int lanes : {1, 2, 4}) {
                            ParticleSet fused = mixedSet(7);
                            const ModelCounts got = flightPass(fused, f, choose ? &rule : nullptr,
                                                               h, start, end, scheme, lanes);

                            SCOPED_TRACE(::testing::Message()
                                         << "integrator " << static_cast<int>(method) << " drag "
                                         << static_cast<int>(drag) << " water " << water
                                         << " choose " << choose << " auto " << allowed << " lanes "
                                         << lanes);
                            EXPECT_TRUE(sameBits(fused.px, ref.px));
                            EXPECT_TRUE(sameBits(fused.py, ref.py));
                            EXPECT_TRUE(sameBits(fused.vx, ref.vx));
                            EXPECT_TRUE(sameBits(fused.vy, ref.vy));
                            EXPECT_TRUE(sameBits(fused.launchX, ref.launchX));
                            EXPECT_TRUE(sameBits(fused.launchT, ref.launchT));
                            EXPECT_EQ(fused.flags, ref.flags);
                            EXPECT_EQ(got.closedForm, want.closedForm);
                            EXPECT_EQ(got.integrated, want.integrated);
                            EXPECT_EQ(got.sleeping, want.sleeping);
                            EXPECT_EQ(got.fixed, want.fixed);
                            EXPECT_EQ(got.asleep, want.asleep);
                            ++compared;
                        }
                    }
    }
    EXPECT_EQ(compared, 144);
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
