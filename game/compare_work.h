// The work-precision of one shot: the compare's shot (the same aim, forces and landing
// surface) flown by every integrator at the tick, twice and four times it, and its
// halves and quarters (what a coarser or finer tick would give), each landing's
// error against the reference and what it cost in force evaluations, for a log-log
// work-precision chart beside the compared paths (Hairer, Norsett and Wanner, Solving
// Ordinary Differential Equations I, II.1: error against work; a method of order p falls
// on a line of slope -p against evaluations, p against the step).
//
// Reference: the closed form where it is exact (no drag, no water); else RK4 at the
// finest tick / referenceRefinement, whose own error is refinement^4 below RK4's finest
// point.
#pragma once

#include "game/compare.h"

#include <string>
#include <vector>

namespace game {

struct ShotWorkPoint {
    double tickSeconds = 0.0; ///< s
    double evaluations = 0.0; ///< force evaluations to the landing: per step x steps flown
    double error = INFINITY;  ///< m, |landing - reference landing|; infinity when not down
};

struct ShotWorkLine {
    phys::Integrator integrator = phys::Integrator::RK4;
    std::string name;                  ///< as phys::integrators() names it
    std::vector<ShotWorkPoint> points; ///< the tick falling
};

struct ShotWork {
    LandingReference reference = LandingReference::ClosedForm;
    double tickSeconds = 0.0;        ///< s, the tick compared (the match's unless given)
    std::vector<ShotWorkLine> lines; ///< one per integrator, in phys::integrators() order
};

struct ShotWorkDef {
    CompareDef compare;          ///< the tick (0: the match's), surface and longest flight
    int levels = 5;              ///< how many ticks, each half the one before; >= 1
    int coarser = 2;             ///< of them above the tick: the first is tick x 2^coarser
    int referenceRefinement = 4; ///< with drag or water: RK4 at the finest tick / this
};

/// Every integrator's landing error against cost for the compare's shot at (angleDeg,
/// speedMps) from the current cannon, at each tick of `def`.
ShotWork shotWorkPrecision(const Match& match, double angleDeg, double speedMps,
                           const ShotWorkDef& def = {});

/// The order a line shows: the least-squares slope of log(error) against log(tick) over
/// its points above `floor` (m); NaN with fewer than two.
double observedOrder(const ShotWorkLine& line, double floor = 1e-9);

} // namespace game
