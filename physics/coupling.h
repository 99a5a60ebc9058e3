// Two-way coupling between the particle layer and Box2D bodies (DESIGN.md, tick phase 5):
// a particle touching a body exchanges an impulse with it, with restitution and Coulomb
// friction, so a cannonball topples a tower and bounces off by the right amount.
//
// Per particle and touching body, after the particle step and before the rigid step:
//   n = unit normal from the body to the particle, r = contact point,
//   u = v_p - v_b(r) relative velocity at the contact, u_n = u.n
//   if u_n < 0 (approaching):  j_n = -(1 + e) u_n / (w_p + w_b),
//        w_p = 1/m_p, w_b = 1/m_b + (r_b x n)^2 / I_b (the body's inverse effective mass)
//   friction along t = (u - u_n n)/|..|: j_t = -|u_t| / (w_p + w_b^t), clamped to mu j_n
//   the body receives J = j_n n + j_t t at r; the particle receives minus what the body
//   actually got (Box2D rounds to float), so total momentum is conserved to double
//   rounding whatever Box2D's precision.
//   A penetrating particle is moved out along n (position only; no momentum change).
// e = e_particle * e_body (the particle material's e against the reference floor times
// the fixture's: the combine rule of physics/materials.h), mu = sqrt(mu_p mu_body).
#pragma once

#include "physics/materials.h"
#include "physics/particles.h"
#include "physics/rigid/rigid_world.h"

#include <vector>

namespace phys {

struct CouplingStats {
    int contacts = 0;      ///< particle-body contacts seen this tick
    int impulses = 0;      ///< of which exchanged an impulse (approaching)
    double impulseSum = 0; ///< sum of |J|, N s
};

/// One impulse exchanged in the last call of exchange().
struct BodyContactEvent {
    ParticleId particle = kNoParticle;
    BodyId body;
    Vec2 point;          ///< m
    Vec2 normal;         ///< unit, from the body to the particle
    double closingSpeed; ///< m/s, before the impulse
    Vec2 impulse;        ///< N s, received by the particle
};

class ParticleBodyCoupling {
  public:
    /// Exchanges impulses between every awake particle and the bodies it touches.
    CouplingStats exchange(ParticleSet& set, const MaterialTable& materials, RigidWorld& rigid);
    /// The impulses of the last exchange (hits for the game).
    const std::vector<BodyContactEvent>& events() const { return events_; }

  private:
    std::vector<RigidCircleContact> contacts_;
    std::vector<BodyContactEvent> events_;
};

} // namespace phys
