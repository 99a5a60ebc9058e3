#include "game/compare.h"

#include "physics/ballistics.h"
#include "physics/forces.h"
#include "physics/particles.h"
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

/// The surface a path lands on: a height for every x.
struct Ground {
    const Heightfield* terrain = nullptr; ///< null: the launch height
    double launchHeight = 0.0;

    double at(double x) const { return terrain ? terrain->heightAt(x) : launchHeight; }
    bool below(Vec2 q) const { return q.y < at(q.x); }

    /// Where, in [0, dt] after the state (p, v), the shell goes down through the ground
    /// (it is above at p, and below at q, with velocity w, dt later): on the cubic Hermite
    /// interpolant of the two states (Burden and Faires, Numerical Analysis, 3.4). It
    /// reproduces a parabola, so exact states under gravity land exactly, and its own
    /// error is O(dt^4), below that of every integrator here, so the landing keeps each
    /// method's order with drag too. Found by bisection (to the last bit of time); on a
    /// flat ground the point is put on it.
    struct Crossing {
        double t;
        Vec2 point;
    };
    Crossing crossing(Vec2 p, Vec2 v, Vec2 q, Vec2 w, double dt) const {
        auto point = [&](double t) {
            const double s = t / dt, s2 = s * s, s3 = s2 * s;
            return p * (2 * s3 - 3 * s2 + 1) + v * (dt * (s3 - 2 * s2 + s)) +
                   q * (3 * s2 - 2 * s3) + w * (dt * (s3 - s2));
        };
        double lo = 0.0, hi = dt; // above at lo, below at hi
        for (int i = 0; i < 200 && lo < hi; ++i) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            (below(point(mid)) ? hi : lo) = mid;
        }
        const Vec2 at = point(hi);
        return {hi, terrain ? at : Vec2{at.x, launchHeight}};
    }
};

/// The ground a path of `def` lands on, for a shell leaving at `muzzle`.
Ground groundOf(const Match& match, const CompareDef& def, Vec2 muzzle) {
    Ground ground;
    ground.launchHeight = muzzle.y;
    if (def.surface == LandingSurface::Terrain) ground.terrain = &match.terrain();
    return ground;
}

/// Ends `path` at the crossing found in the tick of `tick` s that began at step `i`.
void land(IntegratorPath& path, const Ground::Crossing& c, long i, double tick) {
    path.landing = c.point;
    path.flightTime = static_cast<double>(i) * tick + c.t;
    path.landed = true;
    path.points.push_back(c.point);
}

} // namespace

phys::ParticleDef compareShell(const Match& match, double angleDeg, double speedMps) {
    const double a = angleDeg * kDegToRad;
    return phys::particleDef(match.selectedAmmo().preset, match.muzzle(angleDeg),
                             {speedMps * std::cos(a), speedMps * std::sin(a)});
}

IntegratorPath flyPath(const Match& match, phys::Integrator integrator, double tick,
                       const phys::ParticleDef& shell, const CompareDef& def, bool keepPoints) {
    // The shell alone, stepped by the integrator itself under the match's forces: nothing
    // in its way, so none of a world's collision stages (the sweep flies thousands of
    // ticks on a key press).
    const phys::WorldDef& wd = match.world().def();
    phys::ParticleSet set;
    const phys::ParticleId id = set.add(shell);
    const std::vector<phys::Spring> noSprings;
    const phys::Dynamics dynamics(wd.forces, noSprings, set);
    phys::IntegratorScratch scratch;
    const int substeps = std::max(1, wd.substeps);
    const double h = tick / substeps;
    const Ground ground = groundOf(match, def, shell.position);

    IntegratorPath path;
    path.integrator = integrator;
    path.name = phys::info(integrator).name;
    path.points.push_back(shell.position);
    Vec2 p = shell.position, v = shell.velocity;
    const long steps = std::lround(def.maxSeconds / tick);
    for (long i = 0; i < steps; ++i) {
        for (int k = 0; k < substeps; ++k)
            phys::integrate(integrator, dynamics, set, h, scratch, wd.implicit);
        const Vec2 q = set.position(id), u = set.velocity(id);
        if (ground.below(q) && !ground.below(p)) {
            // Went down through the ground in this tick: between the states either side.
            land(path, ground.crossing(p, v, q, u, tick), i, tick);
            path.steps = i + 1;
            return path;
        }
        if (keepPoints) path.points.push_back(q);
        p = q;
        v = u;
    }
    path.steps = steps;
    return path;
}

namespace {

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
        const phys::BallisticState after = state(t1);
        if (ground.below(after.position) && !ground.below(p)) {
            land(path, ground.crossing(p, state(t0).velocity, after.position, after.velocity, tick),
                 i - 1, tick);
            return path;
        }
        path.points.push_back(after.position);
        p = after.position;
    }
    return path;
}

} // namespace

IntegratorPath referencePath(const Match& match, double tick, const phys::ParticleDef& shell,
                             const CompareDef& def) {
    if (match.closedFormExact()) {
        IntegratorPath ref = closedForm(shell, match.world().def().forces.gravity, tick,
                                        def.maxSeconds, groundOf(match, def, shell.position));
        ref.reference = LandingReference::ClosedForm;
        return ref;
    }
    const int n = std::max(1, def.referenceRefinement);
    IntegratorPath ref = flyPath(match, phys::Integrator::RK4, tick / n, shell, def);
    ref.name = "rk4 (dt/" + std::to_string(n) + ")";
    ref.isReference = true;
    ref.reference = LandingReference::FineRK4;
    return ref;
}

std::vector<IntegratorPath> compareIntegrators(const Match& match, double angleDeg,
                                               double speedMps, const CompareDef& def) {
    const double tick = def.tickSeconds > 0.0 ? def.tickSeconds : match.world().def().tickSeconds;
    const phys::ParticleDef shell = compareShell(match, angleDeg, speedMps);
    IntegratorPath ref = referencePath(match, tick, shell, def);
    std::vector<IntegratorPath> out;
    for (const phys::IntegratorInfo& info : phys::integrators()) {
        IntegratorPath path = flyPath(match, info.id, tick, shell, def);
        path.reference = ref.reference;
        path.landingError = path.landed && ref.landed ? length(path.landing - ref.landing) : INFINITY;
        out.push_back(std::move(path));
    }
    out.push_back(std::move(ref));
    return out;
}

} // namespace game
