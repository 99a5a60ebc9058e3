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

/// What `trajectory` was asked for.
struct TrajectoryRequest {
    phys::Vec2 from, wind;
    double speed = 0, angle = 0, time = 0, dt = 0, g = 0, mass = 0, diameter = 0, cd = 0, rho = 0;
    phys::Integrator method = phys::Integrator::VelocityVerlet;
    bool drag = false, json = false;
};

TrajectoryRequest readTrajectoryOptions(const Args& args) {
    TrajectoryRequest q;
    q.from = args.vec2("from", {0.0, 0.0});
    q.speed = args.requiredNumber("speed", 0.0, 1e6, "m/s");
    q.angle = args.requiredNumber("angle", -360.0, 360.0, "degrees");
    q.time = args.requiredNumber("time", 0.0, 1e6, "s");
    q.method = integratorOption(args, phys::Integrator::VelocityVerlet);
    q.dt = args.number("dt", 0.01, 1e-7, 1.0, "s");
    q.g = gravityOption(args);
    q.drag = args.has("diameter") || args.has("cd") || args.has("air-density") || args.has("wind");
    q.mass = args.number("mass", 1.0, 1e-9, 1e9, "kg");
    q.diameter = args.number("diameter", 0.1, 1e-6, 100.0, "m");
    q.cd = args.number("cd", 0.47, 0.0, 100.0, "");
    q.rho = args.number("air-density", phys::kAirDensitySeaLevel, 0.0, 1e4, "kg/m^3");
    q.wind = args.vec2("wind", {0.0, 0.0});
    q.json = args.flag("json");
    args.rejectUnknown();
    return q;
}

/// The particle after `steps` steps: position and velocity.
std::pair<phys::Vec2, phys::Vec2> simulateShot(const TrajectoryRequest& q, const phys::WorldDef& def,
                                                phys::Vec2 v0, long long steps) {
    phys::World world(def);
    phys::ParticleDef pd;
    pd.position = q.from;
    pd.velocity = v0;
    pd.mass = q.mass;
    pd.radius = 0.5 * q.diameter;
    pd.dragCoefficient = q.cd;
    const auto id = world.particles.add(pd);
    for (long long i = 0; i < steps; ++i) world.step();
    return {world.particles.position(id), world.particles.velocity(id)};
}

void printTrajectoryText(const TrajectoryRequest& q, long long steps, double simulated,
                         phys::Vec2 p, phys::Vec2 v, const phys::BallisticState& exact, double err,
                         std::ostream& out) {
    char line[200];
    std::snprintf(line, sizeof line, "%s, dt = %g s, %lld steps, t = %.10g s%s\n",
                  phys::info(q.method).name, q.dt, steps, simulated,
                  std::abs(simulated - q.time) > 1e-9 * std::max(1.0, q.time)
                      ? " (rounded to a whole number of steps)"
                      : "");
    out << line;
    std::snprintf(line, sizeof line, "  simulated    position (%.10g, %.10g) m   velocity (%.10g, %.10g) m/s\n",
                  p.x, p.y, v.x, v.y);
    out << line;
    if (!q.drag) {
        std::snprintf(line, sizeof line,
                      "  closed form  position (%.10g, %.10g) m   velocity (%.10g, %.10g) m/s\n",
                      exact.position.x, exact.position.y, exact.velocity.x, exact.velocity.y);
        out << line;
        std::snprintf(line, sizeof line, "  position error %.6g m\n", err);
        out << line;
    } else {
        out << "  (drag or wind acts: there is no closed form to compare with)\n";
    }
}

} // namespace

int runTrajectory(const Args& args, std::ostream& out) {
    const TrajectoryRequest q = readTrajectoryOptions(args);
    const double stepsExact = q.time / q.dt;
    if (stepsExact > 1e8) args.fail("--time / --dt asks for more than 1e8 steps");
    const long long steps = std::llround(stepsExact);
    const double simulated = static_cast<double>(steps) * q.dt;

    phys::WorldDef def;
    def.model = phys::ModelPolicy::Integrate; // the verb compares the integrator with the closed form
    def.tickSeconds = q.dt;
    def.integrator = q.method;
    def.forces.gravity = {0.0, -q.g};
    if (q.drag) {
        def.forces.drag = phys::DragModel::Quadratic;
        def.forces.airDensity = q.rho;
        def.forces.wind = q.wind;
    }
    const double rad = q.angle * std::numbers::pi / 180.0;
    const phys::Vec2 v0{q.speed * std::cos(rad), q.speed * std::sin(rad)};
    const auto [p, v] = simulateShot(q, def, v0, steps);
    const bool exactKnown = !q.drag;
    const auto exact = phys::ballisticState(q.from, v0, def.forces.gravity, simulated);
    const double err = length(p - exact.position);

    if (q.json) {
        nlohmann::json j{{"integrator", phys::info(q.method).name},
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
    printTrajectoryText(q, steps, simulated, p, v, exact, err, out);
    return kOk;
}

} // namespace game::cli
