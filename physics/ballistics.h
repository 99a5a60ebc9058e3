// Closed-form ballistics under uniform gravity (Rabin, Introduction to Game Development,
// 4.3, "Closed-form Equations of Motion"):
//   v(t) = v0 + g t,   p(t) = p0 + v0 t + 1/2 g t^2,
// exact for any t >= 0 while gravity is the only force. The world uses it to move
// projectiles in flight at O(1) cost and zero integration error, and the verbs and
// tests use it as the reference every integrator is measured against.
#pragma once

#include "physics/vec2.h"

#include <optional>
#include <vector>

namespace phys {

struct BallisticState {
    Vec2 position; ///< m
    Vec2 velocity; ///< m/s
};

/// State at time t after launch from (p0, v0) under the gravity vector g (m/s^2).
/// Inline: the closed-form flight asks for it twice a particle a step.
inline BallisticState ballisticState(Vec2 p0, Vec2 v0, Vec2 g, double t) {
    return {p0 + v0 * t + g * (0.5 * t * t), v0 + g * t};
}

// The functions below take g as the magnitude (m/s^2, > 0) of gravity pointing down.

/// Time after launch at which the vertical velocity is zero (0 if already falling).
double apexTime(Vec2 v0, double g);
/// Highest point of the flight.
Vec2 apex(Vec2 p0, Vec2 v0, double g);
/// Time after launch at which the projectile is at height y while descending
/// (or ascending, when `ascending`); nullopt when it never reaches y.
std::optional<double> timeToHeight(Vec2 p0, Vec2 v0, double g, double y, bool ascending = false);
/// Horizontal distance travelled when it comes back down to its launch height,
/// v0x * 2 v0y / g (0 if launched level or downward).
double range(Vec2 v0, double g);

/// One launch that hits the target.
struct FiringSolution {
    double angleDeg;      ///< counter-clockwise from +x, in (-180, 180]; left shots are > 90
    double flightTime;    ///< s
    Vec2 launchVelocity;  ///< m/s, |launchVelocity| = muzzle speed
};

/// Launch angles that take a projectile from `from` to `to` at muzzle speed `speed`
/// under gravity g (magnitude, down), after Millington, Game Physics Engine Development, 3.5.3:
///   |g|^2/4 t^4 - (s^2 + g.d) t^2 + |d|^2 = 0,  v = d/t - g t/2.
/// Returns none (out of range), one (grazing the edge of range, or g = 0) or two
/// solutions, shortest flight (the low, direct shot) first.
std::vector<FiringSolution> solveFiring(Vec2 from, Vec2 to, double speed, double g);

} // namespace phys
