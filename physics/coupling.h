// Two-way coupling between the particle layer and Box2D bodies (once a tick, after the
// particles' step: docs/architecture.md, "One tick"):
// a particle touching a body exchanges an impulse with it, with restitution and Coulomb
// friction, so a cannonball topples a tower and bounces off by the right amount; a
// body lands on a rope or a spring net and stays there; a rope holds a body it is tied to.
//
// Contacts, per particle and touching body, after the particle step and before the
// rigid step:
//   n = unit normal from the body to the particle, r = contact point,
//   u = v_p - v_b(r) relative velocity at the contact, u_n = u.n
//   if u_n < 0 (approaching):  j_n = -(1 + e) u_n / (w_p + w_b),
//        w_p = 1/m_p, w_b = 1/m_b + (r_b x n)^2 / I_b (the body's inverse effective mass)
//   friction along t = (u - u_n n)/|..|: j_t = -|u_t| / (w_p + w_b^t), clamped to mu j_n
//   the body receives J = j_n n + j_t t at r; the particle receives minus what the body
//   actually got (Box2D rounds to float), so total momentum is conserved to double
//   rounding whatever Box2D's precision.
//   A penetrating free particle is moved out along n (position only; no momentum change),
//   unless n presses it onto a static shape it touches (a ball on the ground under a
//   crate): then it is grounded, w_p = 0, the ground carries the body through it, and a
//   Baumgarte bias pushes the body out instead. Moved, it would be pushed through the
//   ground, and fall for ever.
// e = e_particle * e_body (the particle material's e against the reference floor times
// the fixture's: the combine rule of physics/materials.h), mu = sqrt(mu_p mu_body).
//
// Joints tie a particle to a point fixed on a body (a rope's end to a crate): the
// relative velocity at the point is brought to -beta C / dt, C = p_particle - p_point,
// by the 2x2 impulse K P = -(u + beta C / dt), K = w_p I + (1/m_b) I + r_perp r_perp^T / I_b.
//
// Rods and cables joining the particles pass the load on. One impulse per contact is
// exact for a free particle but not for a rope link: a 2 kg link under a 50 kg crate
// would hand the crate back almost all its velocity, and the crate sinks through the
// bridge. When a contact or joint touches a particle of a rod or cable, the exchange is
// iterated (sequential impulses with accumulated, clamped normal impulses, Catto 2005),
// and between passes the rods' velocity solve runs with each such particle lumped with
// its share of the body (mass splitting: m_p + m_b,eff / k for k links on one body), so
// the rope feels the crate's mass at once rather than over n^2 Gauss-Seidel sweeps. The
// impulse the rods give a lumped particle is split between particle and body by mass:
// momentum stays exact. Such contacts are not moved out by position (that would stretch
// the rods every tick); a Baumgarte bias beta max(d - slop, 0) / dt removes the depth d.
#pragma once

#include "physics/constraints/rods_and_cables.h"
#include "physics/materials.h"
#include "physics/particles.h"
#include "physics/rigid/rigid_world.h"

#include <vector>

namespace phys {

class World;

struct CouplingStats {
    int contacts = 0;      ///< particle-body contacts seen this tick
    int impulses = 0;      ///< of which exchanged an impulse (approaching)
    double impulseSum = 0; ///< sum of |J|, N s
    int joints = 0;        ///< particle-body joints solved
    int passes = 0;        ///< exchange passes run (1 unless rods link a contact or joint;
                           ///< then until converged, at most CouplingDef::iterations)
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

/// A particle tied to a point fixed on a body (a rope's end on a crate).
struct ParticleBodyJoint {
    ParticleId particle = kNoParticle;
    BodyId body;
    Vec2 localAnchor; ///< m, in the body's coordinates
};

struct CouplingDef {
    /// Passes when rods or cables link a contact or joint (1 pass otherwise), >= 1.
    int iterations = 12;
    /// Fraction of a joint's or rope contact's position error removed per tick, (0, 1].
    double baumgarte = 0.2;
    /// Depth a rope contact may keep without correction, m (Box2D's linear slop).
    double slop = 0.005;
    /// The passes stop once the rods change no lumped particle by more than this, m/s.
    double tolerance = 1e-4;
};

class ParticleBodyCoupling {
  public:
    explicit ParticleBodyCoupling(const CouplingDef& def = {}) : def_(def) {}

    /// Ties `particle` to the body point now at `worldPoint`. Returns its index.
    std::size_t attach(ParticleId particle, BodyId body, Vec2 worldPoint, const RigidWorld& rigid);
    const std::vector<ParticleBodyJoint>& joints() const { return joints_; }
    /// Unties every joint of a body (it was destroyed) or of a particle (removed).
    void detachBody(BodyId body);
    void detachParticle(ParticleId particle);

    /// A static body that only mirrors geometry the particle world already has as static
    /// shapes (the terrain and obstacles, given to Box2D so blocks stand on them): the
    /// particles collide with the shapes, exactly at their time of impact, and must not
    /// meet the mirror too. Box2D's skin (b2_polygonRadius, 1 cm) would otherwise push a
    /// ball that rests on the shape up by a centimetre and add a second bounce.
    void mirror(BodyId body) { mirrors_.push_back(body); }
    void unmirror(BodyId body) { std::erase(mirrors_, body); }

    /// Call before the particle step: a spring-held particle that carried a body in the
    /// last exchange is integrated with the body's share of mass lumped onto it, so the
    /// spring pushes the pair as one (see the file comment); exchange() pays the body.
    void prepare(World& world, RigidWorld& rigid);
    /// Exchanges impulses between every awake particle of `world` and the bodies it
    /// touches or is tied to, passing loads through the world's rods and cables.
    CouplingStats exchange(World& world, RigidWorld& rigid);
    /// The impulses of the last exchange (hits for the game).
    const std::vector<BodyContactEvent>& events() const { return events_; }

  private:
    struct ContactRow {
        static constexpr std::size_t kNoEvent = static_cast<std::size_t>(-1);
        ParticleId particle;
        BodyId body;
        Vec2 point, normal;
        double restitution, friction;
        double wp;             ///< the particle's inverse mass here: 0 when grounded
        double wn;             ///< w_p + w_b along the normal
        double bias;           ///< m/s the normal velocity is driven to at least (rope contacts)
        bool linked;           ///< the particle is held by a rod, cable or spring; the body is dynamic
        bool springHeld;       ///< by springs only: lumped in the next particle step
        double bounce = 0.0;   ///< -e u_n at the first pass
        double lambda = 0.0;   ///< accumulated normal impulse, >= 0
        Vec2 tangential{};     ///< accumulated friction impulse, |.| <= mu lambda
        double lumpMass = 0.0; ///< the body's share lumped onto the particle in the rod pass
        std::size_t event = kNoEvent;
    };
    struct JointRow {
        ParticleId particle;
        BodyId body;
        Vec2 point;  ///< the anchor in world coordinates this tick
        Vec2 target; ///< relative velocity wanted: -beta C / dt
        double lumpMass = 0.0;
    };
    /// What the tethered particles among the contacts and joints bring: a link to a
    /// dynamic body (springs, rods or cables), and by rods or cables.
    struct Links {
        bool any = false, rods = false;
    };
    bool markLinked(const World& world);
    void gatherContacts(World& world, RigidWorld& rigid, bool tethers, Links& links,
                        CouplingStats& stats);
    void addContactRow(World& world, const RigidWorld& rigid, ParticleId id,
                       const RigidCircleContact& c, bool tethers, Links& links);
    void gatherJoints(World& world, RigidWorld& rigid, bool tethers, Links& links);
    void lendGravity(RigidWorld& rigid, double dt);
    int exchangeImpulses(World& world, RigidWorld& rigid, const Links& links);
    bool tiedTo(ParticleId particle, BodyId body) const;
    bool grounded(const World& world, ParticleId particle, Vec2 push, double depth) const;
    void settle(World& world, RigidWorld& rigid);
    void contactPass(ParticleSet& set, RigidWorld& rigid, bool first);
    void jointPass(ParticleSet& set, RigidWorld& rigid);
    /// Returns the largest velocity change it gave a lumped particle, m/s.
    double rodPass(World& world, RigidWorld& rigid);

    CouplingDef def_;
    std::vector<ParticleBodyJoint> joints_;
    std::vector<BodyId> mirrors_; ///< static bodies the particle world has as shapes
    std::vector<RigidCircleContact> found_;
    std::vector<BodyContactEvent> events_;
    std::vector<ContactRow> contacts_;
    std::vector<JointRow> jointRows_;
    std::vector<unsigned char> linked_;
    std::vector<double> savedInvMass_, lumpedMass_;
    std::vector<Vec2> savedVelocity_; ///< before the rod pass, then the change it made
    std::vector<ParticleId> lumped_;
    /// A spring-held particle integrated with a share of the bodies it carries.
    struct Carried {
        ParticleId particle;
        double invMass; ///< its own
        Vec2 velocity;  ///< before the particle step
        struct Share {
            BodyId body;
            Vec2 point;
            double mass; ///< kg lent by the body
        };
        std::vector<Share> rows;
    };
    std::vector<Carried> carried_;
    std::vector<std::pair<BodyId, Vec2>> kicked_; ///< bodies given this tick's gravity early
    ConstraintScratch rodScratch_;
};

} // namespace phys
