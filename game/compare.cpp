#include "game/compare.h"

#include "physics/ballistics.h"
#include "physics/projectiles.h"
#include "physics/world.h"

#include <algorithm>
#include <cmath>

namespace game {

using phys::Vec2;

const char* landingReferenceName(LandingReference r) {
    return r == LandingReference::ClosedForm ? "closed form" : "rk4 at dt/16";
}

namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

/// Time after a state (p, v) at which y(t) = p.y + v.y t + g.y t^2/2 equals y0 on the
/// way down: the larger root (for g.y < 0), or the linear root when g.y = 0.
double descendingCrossing(Vec2 p, Vec2 v, Vec2 g, double y0) {
    const double a = 0.5 * g.y, b = v.y, c = p.y - y0;
    if (a == 0.0) return b != 0.0 ? -c / b : 0.0;
    const double disc = std::max(0.0, b * b - 4.0 * a * c);
    return (-b - std::sqrt(disc)) / (2.0 * a);
}

/// One shell flown through an empty world with `integrator` at `tick` (s).
IntegratorPath fly(const Match& match, phys::Integrator integrator, double tick,
                   const phys::ParticleDef& shell, double maxSeconds) {
    phys::WorldDef wd = match.world().def();
    wd.model = phys::ModelPolicy::Integrate;
    wd.integrator = integrator;
    wd.tickSeconds = tick;
    phys::World w(wd);
    const phys::ParticleId id = w.particles.add(shell);
    const Vec2 g = wd.forces.gravity;
    const double y0 = shell.position.y;

    IntegratorPath path;
    path.integrator = integrator;
    path.name = phys::info(integrator).name;
    path.points.push_back(shell.position);
    Vec2 p = shell.position, v = shell.velocity;
    const long steps = std::lround(maxSeconds / tick);
    for (long i = 0; i < steps; ++i) {
        w.step();
        const Vec2 q = w.particles.position(id);
        if (q.y < y0 && p.y >= y0) {
            // Crossed the launch height in this tick: land from the state before it.
            const double t = std::clamp(descendingCrossing(p, v, g, y0), 0.0, tick);
            path.landing = p + v * t + g * (0.5 * t * t);
            path.landing.y = y0;
            path.flightTime = static_cast<double>(i) * tick + t;
            path.landed = true;
            path.points.push_back(path.landing);
            return path;
        }
        path.points.push_back(q);
        p = q;
        v = {w.particles.vx[id], w.particles.vy[id]};
    }
    return path;
}

IntegratorPath closedForm(const phys::ParticleDef& shell, Vec2 g, double tick, double maxSeconds) {
    IntegratorPath path;
    path.name = "closed-form";
    path.isReference = true;
    const double t = descendingCrossing(shell.position, shell.velocity, g, shell.position.y);
    path.landed = t > 0.0 && t <= maxSeconds;
    const double end = path.landed ? t : maxSeconds;
    for (double s = 0.0; s < end; s += tick)
        path.points.push_back(phys::ballisticState(shell.position, shell.velocity, g, s).position);
    const Vec2 last = phys::ballisticState(shell.position, shell.velocity, g, end).position;
    path.points.push_back(last);
    if (path.landed) {
        path.landing = {last.x, shell.position.y};
        path.flightTime = t;
    }
    return path;
}

} // namespace

std::vector<IntegratorPath> compareIntegrators(const Match& match, double angleDeg,
                                               double speedMps, const CompareDef& def) {
    const double tick = def.tickSeconds > 0.0 ? def.tickSeconds : match.world().def().tickSeconds;
    const double a = angleDeg * kDegToRad;
    const phys::ParticleDef shell =
        phys::particleDef(match.selectedAmmo().preset, match.muzzle(angleDeg),
                          {speedMps * std::cos(a), speedMps * std::sin(a)});

    const bool exact = match.ballisticOnly();
    IntegratorPath ref;
    if (exact) {
        ref = closedForm(shell, match.world().def().forces.gravity, tick, def.maxSeconds);
    } else {
        const int n = std::max(1, def.referenceRefinement);
        ref = fly(match, phys::Integrator::RK4, tick / n, shell, def.maxSeconds);
        ref.name = "rk4 (dt/" + std::to_string(n) + ")";
        ref.isReference = true;
    }
    ref.reference = exact ? LandingReference::ClosedForm : LandingReference::FineRK4;

    std::vector<IntegratorPath> out;
    for (const phys::IntegratorInfo& info : phys::integrators()) {
        IntegratorPath path = fly(match, info.id, tick, shell, def.maxSeconds);
        path.reference = ref.reference;
        path.landingError = path.landed && ref.landed ? length(path.landing - ref.landing) : INFINITY;
        out.push_back(std::move(path));
    }
    out.push_back(std::move(ref));
    return out;
}

} // namespace game
