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

/// The surface a path lands on: a height for every x.
struct Ground {
    const Heightfield* terrain = nullptr; ///< null: the launch height
    double launchHeight = 0.0;

    double at(double x) const { return terrain ? terrain->heightAt(x) : launchHeight; }
    bool below(Vec2 q) const { return q.y < at(q.x); }

    /// Where, in [0, dt] after the state (p, v), the shell goes down through the ground
    /// (it is above at p, and below at `after`, dt later): on the parabola under g, or on
    /// the chord to `after` if drag kept the parabola from reaching the ground. Flat
    /// ground is solved in closed form, terrain by bisection (to the last bit of time).
    struct Crossing {
        double t;
        Vec2 point;
    };
    Crossing crossing(Vec2 p, Vec2 v, Vec2 g, Vec2 after, double dt) const {
        auto parabola = [&](double t) { return p + v * t + g * (0.5 * t * t); };
        if (!terrain) {
            const double t = std::clamp(descendingCrossing(p, v, g, launchHeight), 0.0, dt);
            return {t, {parabola(t).x, launchHeight}};
        }
        const bool chord = !below(parabola(dt));
        auto point = [&](double t) { return chord ? p + (after - p) * (t / dt) : parabola(t); };
        double lo = 0.0, hi = dt; // above at lo, below at hi
        for (int i = 0; i < 200 && lo < hi; ++i) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            (below(point(mid)) ? hi : lo) = mid;
        }
        return {hi, point(hi)};
    }
};

/// One shell flown with `integrator` at `tick` (s) through the match's forces, nothing
/// in its way, until it goes down through the ground.
IntegratorPath fly(const Match& match, phys::Integrator integrator, double tick,
                   const phys::ParticleDef& shell, double maxSeconds, const Ground& ground) {
    phys::WorldDef wd = match.world().def();
    wd.model = phys::ModelPolicy::Integrate;
    wd.integrator = integrator;
    wd.tickSeconds = tick;
    phys::World w(wd);
    w.setProfiling(false); // one shell, stepped at up to 1/16 of the tick
    const phys::ParticleId id = w.particles.add(shell);
    const Vec2 g = wd.forces.gravity;

    IntegratorPath path;
    path.integrator = integrator;
    path.name = phys::info(integrator).name;
    path.points.push_back(shell.position);
    Vec2 p = shell.position, v = shell.velocity;
    const long steps = std::lround(maxSeconds / tick);
    for (long i = 0; i < steps; ++i) {
        w.step();
        const Vec2 q = w.particles.position(id);
        if (ground.below(q) && !ground.below(p)) {
            // Went down through the ground in this tick: land from the state before it.
            const Ground::Crossing c = ground.crossing(p, v, g, q, tick);
            path.landing = c.point;
            path.flightTime = static_cast<double>(i) * tick + c.t;
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

/// The exact parabola, sampled at the tick, to where it goes down through the ground.
IntegratorPath closedForm(const phys::ParticleDef& shell, Vec2 g, double tick, double maxSeconds,
                          const Ground& ground) {
    IntegratorPath path;
    path.name = "closed-form";
    path.isReference = true;
    auto state = [&](double t) { return phys::ballisticState(shell.position, shell.velocity, g, t); };
    path.points.push_back(shell.position);
    const long steps = std::lround(maxSeconds / tick);
    Vec2 p = shell.position;
    for (long i = 1; i <= steps; ++i) {
        const double t0 = static_cast<double>(i - 1) * tick, t1 = static_cast<double>(i) * tick;
        const Vec2 q = state(t1).position;
        if (ground.below(q) && !ground.below(p)) {
            const Ground::Crossing c = ground.crossing(p, state(t0).velocity, g, q, tick);
            path.landed = true;
            path.landing = c.point;
            path.flightTime = t0 + c.t;
            path.points.push_back(c.point);
            return path;
        }
        path.points.push_back(q);
        p = q;
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

    Ground ground;
    ground.launchHeight = shell.position.y;
    if (def.surface == LandingSurface::Terrain) ground.terrain = &match.terrain();

    const bool exact = match.ballisticOnly();
    IntegratorPath ref;
    if (exact) {
        ref = closedForm(shell, match.world().def().forces.gravity, tick, def.maxSeconds, ground);
    } else {
        const int n = std::max(1, def.referenceRefinement);
        ref = fly(match, phys::Integrator::RK4, tick / n, shell, def.maxSeconds, ground);
        ref.name = "rk4 (dt/" + std::to_string(n) + ")";
        ref.isReference = true;
    }
    ref.reference = exact ? LandingReference::ClosedForm : LandingReference::FineRK4;

    std::vector<IntegratorPath> out;
    for (const phys::IntegratorInfo& info : phys::integrators()) {
        IntegratorPath path = fly(match, info.id, tick, shell, def.maxSeconds, ground);
        path.reference = ref.reference;
        path.landingError = path.landed && ref.landed ? length(path.landing - ref.landing) : INFINITY;
        out.push_back(std::move(path));
    }
    out.push_back(std::move(ref));
    return out;
}

} // namespace game
