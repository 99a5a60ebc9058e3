#include "physics/stability.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace phys {

double stableOmegaDt(Integrator m) {
    switch (m) {
    case Integrator::ExplicitEuler:
    case Integrator::Midpoint: return 0.0;
    case Integrator::SymplecticEuler:
    case Integrator::Verlet:
    case Integrator::VelocityVerlet:
    case Integrator::Leapfrog: return 2.0;
    case Integrator::RK4: return 2.0 * std::sqrt(2.0);
    case Integrator::ImplicitEuler: return std::numeric_limits<double>::infinity();
    }
    return 0.0;
}

double springOmega(double stiffness, double mass) { return std::sqrt(stiffness / mass); }

double largestStableStep(Integrator m, double stiffness, double mass) {
    return stableOmegaDt(m) / springOmega(stiffness, mass);
}

double explicitEulerEnergyGrowth(double omegaDt) { return 1.0 + omegaDt * omegaDt; }

StiffestSpring stiffestSpring(const std::vector<Spring>& springs, const ParticleSet& s) {
    StiffestSpring worst;
    for (const Spring& sp : springs) {
        if (sp.broken || sp.stiffness <= 0.0) continue;
        const double im = s.invMass[sp.a] + (sp.b != kNoParticle ? s.invMass[sp.b] : 0.0);
        if (!(im > 0.0)) continue; // both ends fixed: nothing moves
        const double omega = std::sqrt(sp.stiffness * im);
        if (omega > worst.omega) worst = {sp.stiffness, 1.0 / im, omega};
    }
    return worst;
}

std::string stiffnessWarning(Integrator method, double stiffness, double mass, double dt) {
    if (!(stiffness > 0.0) || !(mass > 0.0)) return "";
    const double limit = largestStableStep(method, stiffness, mass);
    const char* name = info(method).name;
    char out[200];
    if (limit == 0.0) {
        const double wdt = springOmega(stiffness, mass) * dt;
        if (method == Integrator::ExplicitEuler)
            std::snprintf(out, sizeof out,
                          "k = %g N/m with %.3g kg gains energy at any dt with %s (x%.3g a step)",
                          stiffness, mass, name, explicitEulerEnergyGrowth(wdt));
        else
            std::snprintf(out, sizeof out, "k = %g N/m with %.3g kg gains energy at any dt with %s",
                          stiffness, mass, name);
        return out;
    }
    if (dt < limit) return "";
    std::snprintf(out, sizeof out, "k = %g N/m with %.3g kg needs dt < %.2g s with %s (now %.2g s)",
                  stiffness, mass, limit, name, dt);
    return out;
}

} // namespace phys
