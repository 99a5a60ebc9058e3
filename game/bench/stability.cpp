#include "game/bench/stability.h"

#include "physics/guard.h"

#include "physics/world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

namespace game::bench {

using namespace phys;

double energyGrowth(Integrator m, double omegaDt, int minSteps) {
    // Cover at least 20 periods (2 pi / (w dt) steps each), so that each half of the run
    // holds whole oscillations of the energy and their peaks compare like with like.
    const int steps = static_cast<int>(
        std::min(400000.0, std::max<double>(minSteps, 40.0 * 3.141592653589793 / omegaDt)));
    // The unit oscillator (k = m = 1, so w = 1 and dt = w dt), released from x = 1.
    WorldDef d;
    d.integrator = m;
    d.tickSeconds = omegaDt;
    d.forces.gravity = {0.0, 0.0};
    d.collision.model = ContactModel::None;
    World w(d);
    ParticleDef pd;
    pd.position = {1.0, 0.0};
    const auto id = w.particles.add(pd);
    Spring s;
    s.a = id;
    s.restLength = 0.0;
    s.stiffness = 1.0;
    w.springs.push_back(s);
    // Mean energy of each half. Means, not peaks: a stable method's energy oscillates,
    // and near a resonance between the step and the period the sampled peaks drift
    // slowly, while the mean over many steps settles (the oscillating part sums to a
    // bounded amount).
    double first = 0.0, second = 0.0;
    for (int i = 0; i < steps; ++i) {
        w.step();
        const double x = w.particles.px[id], v = w.particles.vx[id];
        const double e = 0.5 * (x * x + v * v);
        if (!std::isfinite(e)) return std::numeric_limits<double>::infinity();
        (i < steps / 2 ? first : second) += e;
    }
    first /= steps / 2;
    second /= steps - steps / 2;
    return first > 0.0 ? second / first : 1.0;
}

double maxStableOmegaDt(Integrator m) {
    auto stable = [&](double wdt) { return energyGrowth(m, wdt) <= kGrowthTolerance; };
    if (!stable(kMinOmegaDt)) return 0.0;
    if (stable(kMaxOmegaDt)) return std::numeric_limits<double>::infinity();
    // Bracket the edge on a log scale, then bisect. Stability need not be monotone for
    // every method, so the bracket is found walking up from the bottom.
    double lo = kMinOmegaDt, hi = kMinOmegaDt;
    while (hi < kMaxOmegaDt && stable(hi)) {
        lo = hi;
        hi *= 1.25;
    }
    while (hi / lo > 1.0 + 1e-4) {
        const double mid = std::sqrt(lo * hi);
        (stable(mid) ? lo : hi) = mid;
    }
    return lo;
}

bool ropeSurvives(Integrator m, double stiffness, const RopeDef& def) {
    WorldDef d;
    d.integrator = m;
    d.tickSeconds = def.tickSeconds;
    d.collision.model = ContactModel::None;
    World w(d);
    ParticleId prev = kNoParticle;
    for (int i = 0; i < def.particles; ++i) {
        ParticleDef pd;
        pd.position = {def.linkLength * (i + 1), 0.0};
        pd.mass = def.particleMass;
        pd.radius = 0.2 * def.linkLength;
        const auto id = w.particles.add(pd);
        Spring s;
        s.a = id;
        s.b = prev;
        s.restLength = def.linkLength;
        s.stiffness = stiffness;
        w.springs.push_back(s);
        prev = id;
    }
    const long steps = std::lround(def.seconds / def.tickSeconds);
    for (long t = 0; t < steps; ++t) {
        w.step();
        for (std::size_t i = 0; i < w.particles.slots(); ++i) {
            const double v2 = w.particles.vx[i] * w.particles.vx[i] + w.particles.vy[i] * w.particles.vy[i];
            if (!(v2 < 100.0 * 100.0)) return false; // also catches NaN
        }
    }
    return true;
}

double stiffestRopeSpring(Integrator m, const RopeDef& def) {
    double lo = 1.0, hi = 1e12;
    if (!ropeSurvives(m, lo, def)) return 0.0;
    if (ropeSurvives(m, hi, def)) return std::numeric_limits<double>::infinity();
    while (hi / lo > 1.01) {
        const double mid = std::sqrt(lo * hi);
        (ropeSurvives(m, mid, def) ? lo : hi) = mid;
    }
    return lo;
}

double theoreticalOmegaDt(Integrator m) { return phys::stableOmegaDt(m); } // one table: the guard's

std::vector<StabilityRow> runStability(const std::function<void(int, int)>& progress,
                                       const RopeDef& rope) {
    std::vector<StabilityRow> rows;
    const int n = static_cast<int>(integrators().size());
    for (const auto& i : integrators()) {
        rows.push_back({i.id, maxStableOmegaDt(i.id), theoreticalOmegaDt(i.id),
                        stiffestRopeSpring(i.id, rope)});
        if (progress) progress(static_cast<int>(rows.size()), n);
    }
    return rows;
}

std::string toCsv(const std::vector<StabilityRow>& rows) {
    std::string out = "integrator,max_omega_dt,theory_omega_dt,rope_max_stiffness_n_per_m\n";
    char line[200];
    for (const auto& r : rows) {
        std::snprintf(line, sizeof line, "%s,%.6g,%.6g,%.6g\n", info(r.integrator).name,
                      r.maxOmegaDt, r.theoryOmegaDt, r.ropeStiffness);
        out += line;
    }
    return out;
}

std::vector<GrowthCurve> energyGrowthCurves(double lo, double hi, int samples,
                                            const std::function<void(int, int)>& progress) {
    std::vector<GrowthCurve> out;
    const int n = std::max(2, samples);
    const int total = static_cast<int>(phys::integrators().size());
    int done = 0;
    for (const auto& m : phys::integrators()) {
        GrowthCurve c{m.id, {}, {}};
        for (int k = 0; k < n; ++k) {
            const double wdt = lo * std::pow(hi / lo, static_cast<double>(k) / (n - 1));
            // Fewer steps than the limit search: the chart needs the trend, not 1e-4.
            c.omegaDt.push_back(wdt);
            c.growth.push_back(energyGrowth(m.id, wdt, 1000));
        }
        out.push_back(std::move(c));
        if (progress) progress(++done, total);
    }
    return out;
}

} // namespace game::bench
