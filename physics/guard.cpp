#include "physics/guard.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace phys {

namespace {

// The alive particles whose state is not finite or has run away, counted into r.
std::vector<ParticleId> offenders(const ParticleSet& s, const GuardDef& def, GuardReport& r) {
    std::vector<ParticleId> bad;
    for (std::size_t i = 0; i < s.slots(); ++i) {
        if (!(s.flags[i] & kAlive)) continue;
        const double v[4] = {s.px[i], s.py[i], s.vx[i], s.vy[i]};
        const bool finite = std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) &&
                            std::isfinite(v[3]);
        if (!finite) {
            ++r.nonFinite;
        } else if (v[2] * v[2] + v[3] * v[3] > def.maxSpeed * def.maxSpeed ||
                   std::abs(v[0]) > def.maxCoordinate || std::abs(v[1]) > def.maxCoordinate) {
            ++r.runaway;
        } else {
            continue;
        }
        bad.push_back(static_cast<ParticleId>(i));
    }
    return bad;
}

// The stiffest spring on an offender, in units of w dt (and its stiffness).
struct SpringAtStep {
    double omegaDt = 0.0, stiffness = 0.0;
};

SpringAtStep stiffestOnOffenders(const World& w, const std::vector<char>& isBad, double h) {
    std::vector<Spring> touching;
    for (const Spring& sp : w.springs)
        if (isBad[sp.a] || (sp.b != kNoParticle && isBad[sp.b])) touching.push_back(sp);
    const StiffestSpring worst = stiffestSpring(touching, w.particles);
    return {worst.omega * h, worst.stiffness};
}

// What caused the blow-up, and what to change, diagnosed before anything is cut.
std::string cause(const World& w, const SpringAtStep& worst, std::size_t bad, bool nonFinite,
                  double h) {
    const Integrator m = w.def().integrator;
    char buf[400];
    if (worst.stiffness > 0.0 && !(worst.omegaDt < stableOmegaDt(m))) {
        char limit[80];
        if (stableOmegaDt(m) > 0.0)
            std::snprintf(limit, sizeof limit, "it needs w dt < %.3g", stableOmegaDt(m));
        else
            std::snprintf(limit, sizeof limit, "it gains energy on springs at any dt");
        std::snprintf(buf, sizeof buf,
                      "%s with springs of %g N/m is unstable at dt = %.3g ms (w dt = %.3g; %s): "
                      "add sub-steps, lower the stiffness or use implicit-euler",
                      info(m).name, worst.stiffness, 1e3 * h, worst.omegaDt, limit);
    } else if (w.def().collision.model == ContactModel::Penalty) {
        std::snprintf(buf, sizeof buf,
                      "penalty contacts at %g Hz are too stiff for dt = %.3g ms with %s: lower "
                      "the contact frequency, add sub-steps or use impulse contacts",
                      w.def().collision.penaltyHertz, 1e3 * h, info(m).name);
    } else if (worst.stiffness > 0.0) {
        std::snprintf(buf, sizeof buf,
                      "springs of %g N/m blew up with %s at dt = %.3g ms (w dt = %.3g): add "
                      "sub-steps or use implicit-euler",
                      worst.stiffness, info(m).name, 1e3 * h, worst.omegaDt);
    } else {
        std::snprintf(buf, sizeof buf,
                      "%d particle(s) became %s with %s at dt = %.3g ms: lower the time step or "
                      "the forces acting on them",
                      static_cast<int>(bad), nonFinite ? "non-finite" : "too fast", info(m).name,
                      1e3 * h);
    }
    return buf;
}

} // namespace

GuardReport guardWorld(World& w, const GuardDef& def) {
    GuardReport r;
    ParticleSet& s = w.particles;
    const std::vector<ParticleId> bad = offenders(s, def, r);
    if (bad.empty()) return r;

    const double h = w.def().tickSeconds / w.def().substeps;
    std::vector<char> isBad(s.slots(), 0);
    for (ParticleId id : bad) isBad[id] = 1;
    r.cause = cause(w, stiffestOnOffenders(w, isBad, h), bad.size(), r.nonFinite != 0, h);

    // Cut what held the offenders, then remove them.
    const auto before = w.springs.size() + w.constraints.size();
    std::erase_if(w.springs, [&](const Spring& sp) {
        return isBad[sp.a] || (sp.b != kNoParticle && isBad[sp.b]);
    });
    std::erase_if(w.constraints, [&](const DistanceConstraint& c) {
        return isBad[c.a] || (c.b != kNoParticle && isBad[c.b]);
    });
    r.springsCut = static_cast<int>(before - w.springs.size() - w.constraints.size());
    for (ParticleId id : bad) s.remove(id);
    r.removed = static_cast<int>(bad.size());
    return r;
}

} // namespace phys
