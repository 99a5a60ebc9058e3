// artillery trajectory: one particle, one integrator, compared with the closed form.
#include "game/cli/verbs.h"

#include "physics/ballistics.h"
#include "physics/world.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <ostream>

namespace game::cli {

namespace {
nlohmann::json pair(phys::Vec2 v) { return nlohmann::json::array({v.x, v.y}); }
} // namespace

int runTrajectory(const Args& args, std::ostream& out) {
    const phys::Vec2 from = args.vec2("from", {0.0, 0.0});
    const double speed = args.requiredNumber("speed", 0.0, 1e6, "m/s");
    const double angle = args.requiredNumber("angle", -360.0, 360.0, "degrees");
    const double time = args.requiredNumber("time", 0.0, 1e6, "s");
    const phys::Integrator method = integratorOption(args, phys::Integrator::VelocityVerlet);
    const double dt = args.number("dt", 0.01, 1e-7, 1.0, "s");
    const double g = gravityOption(args);
    const bool drag = args.has("diameter") || args.has("cd") || args.has("air-density") ||
                      args.has("wind");
    const double mass = args.number("mass", 1.0, 1e-9, 1e9, "kg");
    const double diameter = args.number("diameter", 0.1, 1e-6, 100.0, "m");
    const double cd = args.number("cd", 0.47, 0.0, 100.0, "");
    const double rho = args.number("air-density", phys::kAirDensitySeaLevel, 0.0, 1e4, "kg/m^3");
    const phys::Vec2 wind = args.vec2("wind", {0.0, 0.0});
    const bool json = args.flag("json");
    args.rejectUnknown();

    const double stepsExact = time / dt;
    if (stepsExact > 1e8) args.fail("--time / --dt asks for more than 1e8 steps");
    const long long steps = std::llround(stepsExact);
    const double simulated = static_cast<double>(steps) * dt;

    phys::WorldDef def;
    def.model = phys::ModelPolicy::Integrate; // the verb compares the integrator with the closed form
    def.tickSeconds = dt;
    def.integrator = method;
    def.forces.gravity = {0.0, -g};
    if (drag) {
        def.forces.drag = phys::DragModel::Quadratic;
        def.forces.airDensity = rho;
        def.forces.wind = wind;
    }
    phys::World world(def);
    const double rad = angle * std::numbers::pi / 180.0;
    const phys::Vec2 v0{speed * std::cos(rad), speed * std::sin(rad)};
    phys::ParticleDef pd;
    pd.position = from;
    pd.velocity = v0;
    pd.mass = mass;
    pd.radius = 0.5 * diameter;
    pd.dragCoefficient = cd;
    const auto id = world.particles.add(pd);
    for (long long i = 0; i < steps; ++i) world.step();

    const phys::Vec2 p = world.particles.position(id), v = world.particles.velocity(id);
    const bool exactKnown = !drag;
    const auto exact = phys::ballisticState(from, v0, def.forces.gravity, simulated);
    const double err = length(p - exact.position);

    if (json) {
        nlohmann::json j{{"integrator", phys::info(method).name},
                         {"position", pair(p)},
                         {"velocity", pair(v)},
                         {"steps", steps},
                         {"time_s", simulated}};
        j["closed_form"] = exactKnown ? nlohmann::json{{"position", pair(exact.position)},
                                                       {"velocity", pair(exact.velocity)}}
                                      : nlohmann::json(nullptr);
        j["position_error_m"] = exactKnown ? nlohmann::json(err) : nlohmann::json(nullptr);
        out << j.dump() << "\n";
        return kOk;
    }
    char line[200];
    std::snprintf(line, sizeof line, "%s, dt = %g s, %lld steps, t = %.10g s%s\n",
                  phys::info(method).name, dt, steps, simulated,
                  std::abs(simulated - time) > 1e-9 * std::max(1.0, time)
                      ? " (rounded to a whole number of steps)"
                      : "");
    out << line;
    std::snprintf(line, sizeof line, "  simulated    position (%.10g, %.10g) m   velocity (%.10g, %.10g) m/s\n",
                  p.x, p.y, v.x, v.y);
    out << line;
    if (exactKnown) {
        std::snprintf(line, sizeof line,
                      "  closed form  position (%.10g, %.10g) m   velocity (%.10g, %.10g) m/s\n",
                      exact.position.x, exact.position.y, exact.velocity.x, exact.velocity.y);
        out << line;
        std::snprintf(line, sizeof line, "  position error %.6g m\n", err);
        out << line;
    } else {
        out << "  (drag or wind acts: there is no closed form to compare with)\n";
    }
    return kOk;
}

} // namespace game::cli
