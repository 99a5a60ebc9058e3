#include "physics/particles.h"

#include <gtest/gtest.h>

using namespace phys;

TEST(ParticleSet, RemovedSlotsAreReusedAndIdsStayStable) {
    ParticleSet s;
    s.reserve(4);
    ParticleDef pd;
    const auto a = s.add(pd), b = s.add(pd), c = s.add(pd);
    const double* before = s.px.data();
    s.remove(b);
    EXPECT_FALSE(s.alive(b));
    EXPECT_EQ(s.count(), 2u);
    EXPECT_EQ(s.invMass[b], 0.0) << "a dead slot is inert in every kernel";
    pd.position = {5, 6};
    const auto d = s.add(pd);
    EXPECT_EQ(d, b) << "the free slot is reused";
    EXPECT_EQ(s.position(d), (Vec2{5, 6}));
    EXPECT_TRUE(s.alive(a) && s.alive(c) && s.alive(d));
    EXPECT_EQ(s.px.data(), before) << "no reallocation within the reserved capacity";
}

TEST(ParticleSet, MassZeroOrInfiniteIsFixed) {
    ParticleSet s;
    ParticleDef pd;
    pd.mass = 0.0;
    EXPECT_EQ(s.invMass[s.add(pd)], 0.0);
    pd.mass = INFINITY;
    EXPECT_EQ(s.invMass[s.add(pd)], 0.0);
    pd.mass = 4.0;
    EXPECT_EQ(s.invMass[s.add(pd)], 0.25);
}

TEST(ParticleSet, VelocityChangesForgetIntegratorHistory) {
    ParticleSet s;
    const auto a = s.add({});
    s.flags[a] |= kVerletPrimed | kLeapfrogPrimed;
    s.setVelocity(a, {1, 2});
    EXPECT_EQ(s.flags[a] & (kVerletPrimed | kLeapfrogPrimed), 0u);
}
