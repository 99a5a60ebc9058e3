// The work-precision sweep: measured slopes match each method's order of accuracy
// within 0.3, and the cheapest-within-tolerance pick is right.
#include "game/bench/work_precision.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace game::bench;
using phys::Integrator;

namespace {
struct SlopeCase {
    AccuracyScene scene;
    double largestDt;
    int halvings;
};
} // namespace

TEST(WorkPrecision, SlopesMatchTheOrderOfEachMethod) {
    for (const SlopeCase c : {SlopeCase{AccuracyScene::Spring, 0.002, 4},
                              SlopeCase{AccuracyScene::ProjectileDrag, 0.02, 4},
                              SlopeCase{AccuracyScene::Orbit, 0.02, 4}}) {
        WorkPrecisionDef def;
        def.scene = c.scene;
        def.largestDt = c.largestDt;
        def.halvings = c.halvings;
        def.repeats = 1;
        const auto points = runWorkPrecision(def);
        for (const auto& m : phys::integrators()) {
            const double slope = convergenceSlope(points, m.id);
            EXPECT_NEAR(slope, m.order, 0.3) << info(c.scene).name << " " << m.name;
        }
    }
}

TEST(WorkPrecision, CheapestWithinToleranceIsAccurateAndCheapest) {
    std::vector<WorkPrecisionPoint> pts = {
        {AccuracyScene::Spring, Integrator::RK4, 0.1, 20, 1e-6, 4.0, 0},
        {AccuracyScene::Spring, Integrator::SymplecticEuler, 0.001, 2000, 5e-4, 2.0, 0},
        {AccuracyScene::Spring, Integrator::ExplicitEuler, 0.1, 20, 0.5, 0.5, 0},
        {AccuracyScene::Spring, Integrator::Leapfrog, 0.01, 200, INFINITY, 0.1, 0},
    };
    EXPECT_EQ(cheapestWithin(pts, 1e-3)->integrator, Integrator::SymplecticEuler);
    EXPECT_EQ(cheapestWithin(pts, 1e-5)->integrator, Integrator::RK4);
    EXPECT_EQ(cheapestWithin(pts, 1.0)->integrator, Integrator::ExplicitEuler);
    EXPECT_EQ(cheapestWithin(pts, 1e-9), nullptr);
}
