#include "game/compare_work.h"

#include "game/bench/work_precision.h"

#include <algorithm>
#include <cmath>

namespace game {

ShotWork shotWorkPrecision(const Match& match, double angleDeg, double speedMps,
                           const ShotWorkDef& def) {
    ShotWork out;
    out.tickSeconds =
        def.compare.tickSeconds > 0.0 ? def.compare.tickSeconds : match.world().def().tickSeconds;
    const int levels = std::max(1, def.levels);
    auto tickAt = [&](int k) { return std::ldexp(out.tickSeconds, def.coarser - k); };
    const double finest = tickAt(levels - 1);
    const phys::ParticleDef shell = compareShell(match, angleDeg, speedMps);
    CompareDef refDef = def.compare;
    refDef.referenceRefinement = def.referenceRefinement;
    // Its landing alone is used: the closed form's does not depend on the sampling.
    const IntegratorPath ref = referencePath(match, finest, shell, refDef);
    out.reference = ref.reference;
    for (const phys::IntegratorInfo& info : phys::integrators()) {
        ShotWorkLine line;
        line.integrator = info.id;
        line.name = info.name;
        for (int k = 0; k < levels; ++k) {
            const double tick = tickAt(k);
            const IntegratorPath p = flyPath(match, info.id, tick, shell, def.compare, false);
            ShotWorkPoint point;
            point.tickSeconds = tick;
            point.evaluations = static_cast<double>(info.evaluations) *
                                static_cast<double>(match.world().def().substeps) *
                                static_cast<double>(p.steps);
            if (p.landed && ref.landed) point.error = length(p.landing - ref.landing);
            line.points.push_back(point);
        }
        out.lines.push_back(std::move(line));
    }
    return out;
}

double observedOrder(const ShotWorkLine& line, double floor) {
    std::vector<double> tick, error;
    for (const ShotWorkPoint& p : line.points)
        tick.push_back(p.tickSeconds), error.push_back(p.error);
    return bench::logLogSlope(tick, error, floor);
}

} // namespace game
