// artillery spring: a mass on a spring, integrator against the analytic solution.
#include "game/cli/verbs.h"

#include "physics/oscillator.h"
#include "physics/world.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <ostream>

namespace game::cli {

int runSpring(const Args& args, std::ostream& out) {
    const double k = args.requiredNumber("k", 1e-12, 1e12, "N/m");
    const double mass = args.requiredNumber("mass", 1e-12, 1e12, "kg");
    const double x0 = args.requiredNumber("x0", -1e6, 1e6, "m");
    const double time = args.requiredNumber("time", 0.0, 1e6, "s");
    const phys::Integrator method = integratorOption(args, phys::Integrator::VelocityVerlet);
    const double dt = args.number("dt", 0.01, 1e-7, 1.0, "s");
    const double c = args.number("damping", 0.0, 0.0, 1e12, "N s/m");
    const bool json = args.flag("json");
    args.rejectUnknown();
    if (time / dt > 1e8) args.fail("--time / --dt asks for more than 1e8 steps");
    const long long steps = std::llround(time / dt);
    const double simulated = static_cast<double>(steps) * dt;

    // The mass hangs on a zero-rest-length spring to an anchor at the origin, with no
    // gravity: F = -k x - c v, the textbook linear oscillator.
    phys::WorldDef def;
    def.tickSeconds = dt;
    def.integrator = method;
    def.forces.gravity = {0.0, 0.0};
    phys::World world(def);
    phys::ParticleDef pd;
    pd.position = {x0, 0.0};
    pd.mass = mass;
    const auto id = world.particles.add(pd);
    phys::Spring s;
    s.a = id;
    s.anchor = {0.0, 0.0};
    s.restLength = 0.0;
    s.stiffness = k;
    s.damping = c;
    world.springs.push_back(s);

    const double e0 = phys::energy(world.particles, world.springs, def.forces).total();
    for (long long i = 0; i < steps; ++i) world.step();
    const double x = world.particles.px[id], v = world.particles.vx[id];
    const double e = phys::energy(world.particles, world.springs, def.forces).total();
    const auto exact = phys::dampedOscillator(x0, 0.0, k, mass, c, simulated);
    const double err = std::abs(x - exact.position);
    const double wdt = std::sqrt(k / mass) * dt;

    if (json) {
        nlohmann::json j{{"integrator", phys::info(method).name},
                         {"position", x},
                         {"velocity", v},
                         {"energy_j", e},
                         {"initial_energy_j", e0},
                         {"analytic_position", exact.position},
                         {"analytic_velocity", exact.velocity},
                         {"position_error_m", err},
                         {"steps", steps},
                         {"time_s", simulated},
                         {"omega_dt", wdt}};
        out << j.dump() << "\n";
        return kOk;
    }
    char line[200];
    std::snprintf(line, sizeof line, "%s, dt = %g s, %lld steps, t = %.10g s, w dt = %.4g\n",
                  phys::info(method).name, dt, steps, simulated, wdt);
    out << line;
    std::snprintf(line, sizeof line, "  simulated  x = %.10g m   v = %.10g m/s\n", x, v);
    out << line;
    std::snprintf(line, sizeof line, "  analytic   x = %.10g m   v = %.10g m/s\n", exact.position,
                  exact.velocity);
    out << line;
    std::snprintf(line, sizeof line, "  position error %.6g m\n", err);
    out << line;
    std::snprintf(line, sizeof line, "  energy %.10g J (initial %.10g J, ratio %.6g)\n", e, e0,
                  e0 != 0.0 ? e / e0 : 1.0);
    out << line;
    return kOk;
}

} // namespace game::cli
