// Contact response: the impulse of one contact (the collision response with a coefficient
// of restitution of Claypool's "Game Physics" lecture, its equation 4, with Coulomb
// friction), and the penalty spring of the gradual model (Rabin, Introduction to Game
// Development, 4.3 "Real-time Game Physics").
#pragma once

#include "physics/materials.h"
#include "physics/vec2.h"

namespace phys {

/// The impulse on body a (body b receives -impulse), N s.
struct ContactImpulse {
    Vec2 impulse;
    double normal = 0.0;     ///< j_n, N s (>= 0)
    double tangential = 0.0; ///< |j_t|, N s
    bool stuck = false;      ///< static friction removed all sliding
};

/// Frictional impulse response at a contact with unit normal n (from b to a), relative
/// velocity vrel = v_a - v_b and inverse masses wa, wb (0: immovable):
///   j_n = -(1 + e) (vrel . n) / (wa + wb)
/// which is that equation 4, I = -m1 m2 (1 + e) (v1 - v2).n / (m1 + m2) n, written
/// with inverse masses so an immovable body (w = 0) needs no special case. Nothing
/// happens when the contact is separating (vrel . n >= 0) and no support is given.
/// Coulomb friction along the tangent t (the direction of sliding): the impulse that
/// would stop sliding, |vt| / (wa + wb), is applied if it is within mu_s N (static:
/// it sticks); otherwise mu_d N opposes the sliding (dynamic). N is j_n plus
/// `supportImpulse`, the normal impulse a resting contact delivers over the rest of
/// the step (m |a.n| (h - t)).
ContactImpulse contactImpulse(Vec2 vrel, Vec2 n, double wa, double wb, double restitution,
                              const PairProperties& pair, double supportImpulse = 0.0);

/// Penalty (gradual) response over one step of length h to an overlap `depth` (m, > 0)
/// along n: a spring-damper with natural frequency w = 2 pi hertz on the reduced mass,
///   F = m_eff (w^2 depth - 2 zeta w (vrel . n)),  m_eff = 1 / (wa + wb),
/// whose damping ratio reproduces the pair's restitution for a linear contact,
///   e = exp(-zeta pi / sqrt(1 - zeta^2))  =>  zeta = -ln e / sqrt(pi^2 + ln^2 e),
/// applied as the impulse F h (explicit in the force, so it is stable only while
/// w h < 2 and it lets bodies sink by about g / w^2 at rest: the model's trade-offs).
/// Returns the impulse on a along n.
double penaltyImpulse(double depth, double closingVelocity, double wa, double wb,
                      double restitution, double hertz, double h);

} // namespace phys
