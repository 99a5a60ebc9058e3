#include "game/exact_path.h"

#include "game/match.h"
#include "game/shot_model.h"
#include "physics/ballistics.h"

#include <cmath>
#include <cstdio>

namespace game {

namespace {
constexpr int kPathPoints = 96; ///< enough for a smooth parabola at any zoom the game has
} // namespace

std::optional<ExactPath> exactPathOf(const Match& match, const GameEvent& landed,
                                     const std::string& model) {
    if (landed.kind != EventKind::Landed || !landed.closedFormErrorM || model.empty() ||
        model == kClosedFormModel)
        return std::nullopt;
    const ShellFlight& f = match.flight();
    const phys::Vec2 g = match.world().def().forces.gravity;
    ExactPath out;
    out.model = model;
    out.tickHz = 1.0 / match.world().def().tickSeconds;
    out.substeps = match.world().def().substeps;
    out.errorM = *landed.closedFormErrorM;
    out.flownLanding = landed.where;
    // The exact landing lies errorM back along the direction of fire, on the parabola.
    const double forward = f.launchVelocity.x < 0.0 ? -1.0 : 1.0;
    const double exactX = landed.where.x - forward * out.errorM;
    if (std::abs(f.launchVelocity.x) < 1e-9) return std::nullopt; // straight up: no x to go by
    const double tEnd = (exactX - f.launchPosition.x) / f.launchVelocity.x;
    if (!(tEnd > 0.0)) return std::nullopt;
    for (int i = 0; i <= kPathPoints; ++i) {
        const double t = tEnd * i / kPathPoints;
        out.points.push_back(phys::ballisticState(f.launchPosition, f.launchVelocity, g, t).position);
    }
    out.exactLanding = out.points.back();
    const auto energy = [&](phys::Vec2 p, phys::Vec2 v) { return 0.5 * phys::dot(v, v) - phys::dot(g, p); };
    const double e0 = energy(f.launchPosition, f.launchVelocity);
    if (e0 != 0.0)
        out.energyChange = (energy(f.preLandingPosition, f.preLandingVelocity) - e0) / std::abs(e0);
    return out;
}

std::string exactPathText(const ExactPath& p) {
    char rate[48];
    if (p.substeps > 1)
        std::snprintf(rate, sizeof rate, "%.0f Hz x %d", p.tickHz, p.substeps);
    else
        std::snprintf(rate, sizeof rate, "%.0f Hz", p.tickHz);
    char line[160];
    if (std::abs(p.errorM) < 0.005)
        std::snprintf(line, sizeof line, "%s, %s: on the exact path", shotModelLabel(p.model).c_str(), rate);
    else
        std::snprintf(line, sizeof line, "%s, %s: %.2f m %s of the exact path; energy %+.1f %%",
                      shotModelLabel(p.model).c_str(), rate, std::abs(p.errorM),
                      p.errorM > 0.0 ? "long" : "short", 100.0 * p.energyChange);
    return line;
}

} // namespace game
