// artillery drop: the drop experiment of Claypool, Game Physics (ch. 10): bounce apexes
// against e^(2k) H.
#include "game/cli/verbs.h"

#include "physics/experiments/drop.h"
#include "physics/materials.h"
#include "physics/rigid/rigid_drop.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <ostream>

namespace game::cli {

namespace {

/// What `drop` was asked for: the drop, and how to model and report it.
struct DropRequest {
    phys::DropDef def;
    bool hasCor = false;
    std::string contact, model;
    bool json = false;
};

DropRequest readDropOptions(const Args& args, const phys::MaterialTable& table) {
    DropRequest q;
    phys::DropDef& def = q.def;
    def.height = args.requiredNumber("height", 1e-6, 1e5, "m");
    q.hasCor = args.has("cor");
    if (q.hasCor == args.has("material")) args.fail("give exactly one of --cor E or --material NAME");
    if (q.hasCor) {
        def.material = phys::material::kDefault;
        def.restitution = args.number("cor", 0.5, 0.0, 1.0, "");
    } else {
        const std::string name = *args.text("material");
        const auto id = table.find(name);
        if (!id)
            args.fail("--material expects one of " + table.nameList() + ", got '" + name + "'");
        def.material = *id;
    }
    def.bounces = static_cast<int>(args.integer("bounces", 3, 1, 100));
    def.integrator = integratorOption(args, phys::Integrator::VelocityVerlet);
    def.dt = args.number("dt", 1.0 / 120.0, 1e-6, 0.1, "s");
    def.gravity = gravityOption(args);
    if (!(def.gravity > 0.0)) args.fail("--gravity must be > 0 m/s^2 for a drop");
    def.collision.continuous = !args.flag("discrete");
    q.contact = args.text("contact", "impulse");
    if (q.contact == "penalty")
        def.collision.model = phys::ContactModel::Penalty;
    else if (q.contact != "impulse")
        args.fail("--contact expects impulse or penalty, got '" + q.contact + "'");
    def.collision.penaltyHertz =
        args.number("stiffness", def.collision.penaltyHertz, 1e-3, 1e6, "Hz");
    q.model = args.text("model", "particle");
    q.json = args.flag("json");
    args.rejectUnknown();
    if (q.model != "particle" && q.model != "rigid")
        args.fail("--model expects particle or rigid, got '" + q.model + "'");
    return q;
}

/// The same drop as a Box2D circle on a static floor: how close Box2D gets (it reverses
/// the speed at the end of a step, after that step's gravity, and rests bodies inside a
/// contact skin; see physics/rigid/rigid_world.h).
int rigidDrop(const DropRequest& q, const phys::MaterialTable& table, std::ostream& out) {
    const phys::DropDef& def = q.def;
    const double e = q.hasCor ? *def.restitution : table[def.material].restitution;
    phys::RigidDropDef rd;
    rd.height = def.height;
    rd.restitution = e;
    rd.bounces = def.bounces;
    rd.tickSeconds = def.dt;
    rd.gravity = def.gravity;
    const auto apexes = phys::rigidDropApexes(rd);
    nlohmann::json bounces = nlohmann::json::array();
    char line[200];
    if (!q.json) {
        std::snprintf(line, sizeof line, "drop from %g m as a Box2D circle, e = %g, dt = %g s\n",
                      def.height, e, def.dt);
        out << line << "  bounce   apex (m)        expected e^2k H (m)   error\n";
    }
    for (std::size_t k = 0; k < apexes.size(); ++k) {
        const double expected = std::pow(e, 2.0 * static_cast<double>(k + 1)) * def.height;
        const double err = expected > 0.0 ? (apexes[k] - expected) / expected : apexes[k];
        bounces.push_back({{"apex_m", apexes[k]}, {"expected_apex_m", expected}, {"relative_error", err}});
        if (!q.json) {
            std::snprintf(line, sizeof line, "  %-6zu   %-14.9g  %-20.9g  %+.4g %%\n", k + 1,
                          apexes[k], expected, 100.0 * err);
            out << line;
        }
    }
    if (q.json)
        out << nlohmann::json{{"model", "rigid"}, {"height_m", def.height}, {"restitution", e},
                              {"dt_s", def.dt}, {"bounces", bounces}}.dump()
            << "\n";
    else if (apexes.size() < static_cast<std::size_t>(def.bounces))
        out << "  Box2D stopped the ball after " << apexes.size()
            << " bounce(s) (its restitution threshold kills slower bounces)\n";
    return kOk;
}

void printDropJson(const DropRequest& q, const phys::DropResult& r, std::ostream& out) {
    const phys::DropDef& def = q.def;
    nlohmann::json j;
    j["height_m"] = def.height;
    j["restitution"] = r.restitution;
    j["integrator"] = phys::info(def.integrator).name;
    j["dt_s"] = def.dt;
    j["continuous"] = def.collision.continuous;
    j["came_to_rest"] = r.cameToRest;
    j["contact"] = q.contact;
    j["max_penetration_m"] = r.maxPenetration;
    j["bounces"] = nlohmann::json::array();
    for (const auto& b : r.bounces)
        j["bounces"].push_back({{"apex_m", b.apex},
                                {"expected_apex_m", b.expected},
                                {"relative_error", b.relativeError}});
    out << j.dump() << "\n";
}

void printDropText(const DropRequest& q, const phys::MaterialTable& table,
                   const phys::DropResult& r, std::ostream& out) {
    const phys::DropDef& def = q.def;
    const bool penalty = def.collision.model == phys::ContactModel::Penalty;
    char line[240];
    std::snprintf(line, sizeof line,
                  "drop from %g m, %s, e = %g against the floor, %s, dt = %g s, %s detection\n",
                  def.height, q.hasCor ? "ball given by --cor" : table[def.material].name.c_str(),
                  r.restitution, phys::info(def.integrator).name, def.dt,
                  penalty                    ? "no (penalty springs)"
                  : def.collision.continuous ? "continuous"
                                             : "overlap (bisection)");
    out << line;
    if (penalty) {
        std::snprintf(line, sizeof line,
                      "  penalty contact at %g Hz: the ball sank up to %.4g m into the floor "
                      "(w dt = %.3g; unstable above 2)\n",
                      def.collision.penaltyHertz, r.maxPenetration,
                      2.0 * 3.141592653589793 * def.collision.penaltyHertz * def.dt);
        out << line;
    }
    out << "  bounce   apex (m)        expected e^2k H (m)   error\n";
    for (std::size_t k = 0; k < r.bounces.size(); ++k) {
        const auto& b = r.bounces[k];
        if (b.expected > 0.0)
            std::snprintf(line, sizeof line, "  %-6zu   %-14.9g  %-20.9g  %+.4g %%\n", k + 1,
                          b.apex, b.expected, 100.0 * b.relativeError);
        else
            std::snprintf(line, sizeof line, "  %-6zu   %-14.9g  %-20.9g  %+.3g m\n", k + 1, b.apex,
                          b.expected, b.relativeError);
        out << line;
    }
    if (r.cameToRest)
        out << "  the ball came to rest on the floor (a contact slower than the resting speed\n"
               "  does not bounce); the remaining apexes are the floor\n";
}

} // namespace

int runDrop(const Args& args, std::ostream& out) {
    const phys::MaterialTable table;
    DropRequest q = readDropOptions(args, table);
    if (q.model == "rigid") return rigidDrop(q, table, out);
    // The fall takes sqrt(2H/g), each bounce at most twice that: bound the work.
    phys::DropDef& def = q.def;
    const double fall = std::sqrt(2.0 * def.height / def.gravity);
    def.maxTime = fall * (1.0 + 2.0 * def.bounces) + 1.0;
    if (def.maxTime / def.dt > 5e7)
        args.fail("--height, --bounces and --dt ask for more than 5e7 steps; use a larger --dt");
    const phys::DropResult r = phys::simulateDrop(def);
    if (q.json)
        printDropJson(q, r, out);
    else
        printDropText(q, table, r, out);
    return kOk;
}

} // namespace game::cli
