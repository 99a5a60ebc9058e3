#include "game/landing.h"

#include "game/match.h"
#include "physics/ballistics.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace game {

using phys::Vec2;

namespace {

/// Advancement stops this close to the surface, m: far below anything drawn or scored.
constexpr double kTouchTolerance = 1e-9;
/// How far around the shell a body is looked for at each advance, m.
constexpr double kBodyReach = 2.0;

/// Clearance of a circle from one body: its separation where the body is within the
/// reach, else the reach.
double bodyClearance(const phys::RigidWorld& rigid, phys::BodyId body, Vec2 centre, double radius) {
    std::vector<phys::RigidCircleContact> found;
    rigid.circleContacts(centre, radius, found, kBodyReach);
    double clearance = kBodyReach;
    for (const phys::RigidCircleContact& c : found)
        if (c.body == body) clearance = std::min(clearance, c.separation);
    return clearance;
}

} // namespace

std::optional<double> firstTouchTime(const ShellLaunch& launch, Vec2 gravity, double maxSeconds,
                                     double reach,
                                     const std::function<double(Vec2)>& clearance) {
    const double v0 = phys::length(launch.velocity), g = phys::length(gravity);
    double t = 0.0;
    // Each advance covers at least the tolerance or a reach; bounded so a path grazing a
    // surface cannot spin here.
    for (int i = 0; i < 100000 && t <= maxSeconds; ++i) {
        const Vec2 p = phys::ballisticState(launch.position, launch.velocity, gravity, t).position;
        const double c = std::min(clearance(p), reach);
        if (c <= kTouchTolerance) return t;
        const double speedBound = v0 + g * (t + c / std::max(v0, 1e-9)) + 1e-9;
        t += c / speedBound;
    }
    return std::nullopt;
}

double landingErrorAlongX(const ShellLaunch& launch, Vec2 gravity, double exactTime,
                          Vec2 flownCentre) {
    const Vec2 exact =
        phys::ballisticState(launch.position, launch.velocity, gravity, exactTime).position;
    const double forward = launch.velocity.x < 0.0 ? -1.0 : 1.0;
    return forward * (flownCentre.x - exact.x);
}

std::optional<double> closedFormErrorOnShapes(const phys::StaticShapes& shapes,
                                              const ShellLaunch& launch, Vec2 gravity,
                                              Vec2 flownCentre, double maxSeconds) {
    const auto clearance = [&](Vec2 p) {
        double nearest = INFINITY;
        for (std::size_t i = 0; i < shapes.count(); ++i)
            nearest = std::min(nearest, shapes.closestPoint(shapes.ref(i), p).distance);
        return nearest - launch.radius;
    };
    const std::optional<double> t =
        firstTouchTime(launch, gravity, maxSeconds, INFINITY, clearance);
    if (!t) return std::nullopt;
    return landingErrorAlongX(launch, gravity, *t, flownCentre);
}

std::optional<double> closedFormErrorOnBody(const phys::RigidWorld& rigid, phys::BodyId body,
                                            const ShellLaunch& launch, Vec2 gravity,
                                            Vec2 flownCentre, double maxSeconds) {
    const auto clearance = [&](Vec2 p) { return bodyClearance(rigid, body, p, launch.radius); };
    const std::optional<double> t =
        firstTouchTime(launch, gravity, maxSeconds, kBodyReach, clearance);
    if (!t) return std::nullopt;
    return landingErrorAlongX(launch, gravity, *t, flownCentre);
}

Vec2 firstTouchOnChord(const phys::RigidWorld& rigid, phys::BodyId body, Vec2 from, Vec2 to,
                       double radius) {
    if (bodyClearance(rigid, body, from, radius) <= 0.0) return from;
    double lo = 0.0, hi = 1.0; // clear at lo, touching (or as far as it went) at hi
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (bodyClearance(rigid, body, from + (to - from) * mid, radius) <= 0.0 ? hi : lo) = mid;
    }
    return from + (to - from) * hi;
}

// ---- the match's side: the shell's first contact, as a `landed` event -------------------

void Match::reportLanding(Vec2 shellNow) {
    flight_.landed = true;
    // The last state the flight alone made (the tick before; lastVelocity is that tick's
    // until the weapon's step takes this one's).
    flight_.preLandingPosition = flight_.lastPosition;
    flight_.preLandingVelocity = flight_.lastVelocity;
    const ShellLaunch launch{flight_.launchPosition, flight_.launchVelocity,
                             world_.particles.radius[shell_]};
    const Vec2 g = world_.def().forces.gravity;
    // The earliest contact of the tick with a shape or a particle (they carry a time in
    // the tick); a body's contact is reported by the coupling after the tick.
    const phys::ContactEvent* first = nullptr;
    for (const phys::ContactEvent& e : world_.contacts())
        if ((e.a == shell_ || e.b == shell_) && (!first || e.time < first->time)) first = &e;
    GameEvent ev;
    ev.tick = tick();
    ev.kind = EventKind::Landed;
    ev.player = current_;
    const bool exact = closedFormExact();
    if (first) {
        const bool onShape = first->b == phys::kNoParticle;
        ev.where = first->a == shell_ ? first->position : shellNow;
        ev.value = first->closingSpeed;
        ev.text = onShape ? "shape" : "particle";
        if (exact && onShape)
            ev.closedFormErrorM = closedFormErrorOnShapes(world_.shapes, launch, g, ev.where,
                                                          kMaxFlightSeconds);
    } else {
        for (const phys::BodyContactEvent& e : coupling_.events()) {
            if (e.particle != shell_) continue;
            ev.where = firstTouchOnChord(*rigid_, e.body, flight_.lastPosition, shellNow,
                                         launch.radius);
            ev.value = e.closingSpeed;
            ev.text = "body";
            if (exact)
                ev.closedFormErrorM = closedFormErrorOnBody(*rigid_, e.body, launch, g, ev.where,
                                                            kMaxFlightSeconds);
            break;
        }
    }
    emit(std::move(ev));
}

} // namespace game
