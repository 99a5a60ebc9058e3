// artillery solve: the firing solution (Millington 3.5.3) from the command line.
#include "game/cli/verbs.h"

#include "physics/ballistics.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <ostream>

namespace game::cli {

int runSolve(const Args& args, std::ostream& out) {
    const phys::Vec2 from = args.requiredVec2("from");
    const phys::Vec2 to = args.requiredVec2("to");
    const double speed = args.requiredNumber("speed", 1e-9, 1e6, "m/s");
    const double g = gravityOption(args);
    const bool json = args.flag("json");
    args.rejectUnknown();
    if (from == to) args.fail("--from and --to are the same point; there is nothing to aim at");

    const auto solutions = phys::solveFiring(from, to, speed, g);
    for (const auto& s : solutions)
        if (!std::isfinite(s.angleDeg) || !std::isfinite(s.flightTime))
            args.fail("at --gravity " + args.text("gravity", "9.81") +
                      " m/s^2 the high shot's flight time does not fit in a double; give "
                      "--gravity 0 for straight flight, or a larger gravity");
    if (json) {
        nlohmann::json j;
        j["solutions"] = nlohmann::json::array();
        for (const auto& s : solutions)
            j["solutions"].push_back({{"angle_deg", s.angleDeg}, {"flight_time_s", s.flightTime}});
        out << j.dump() << "\n";
        return kOk;
    }
    char line[160];
    std::snprintf(line, sizeof line, "from (%g, %g) to (%g, %g) at %g m/s, g = %g m/s^2\n",
                  from.x, from.y, to.x, to.y, speed, g);
    out << line;
    if (solutions.empty()) {
        out << "out of range: no launch angle reaches the target at this speed\n";
        return kOk;
    }
    const char* names[] = {"low ", "high"};
    for (std::size_t i = 0; i < solutions.size(); ++i) {
        std::snprintf(line, sizeof line, "  %s  angle %8.3f deg   flight time %8.4f s\n",
                      solutions.size() == 1 ? "only" : names[i], solutions[i].angleDeg,
                      solutions[i].flightTime);
        out << line;
    }
    return kOk;
}

} // namespace game::cli
