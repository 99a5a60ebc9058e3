// The rigid-body layer: what must rotate and stack is a Box2D body (model no
// more than a scene needs). RigidWorld owns one b2World and hands out stable ids
// instead of b2Body pointers, so the game, replays and the particle coupling never hold
// a pointer Box2D may free.
//
// Section index
//   set-up        RigidWorld(def), validate(), setDef()
//   bodies        createBody / add{Box,Circle,Polygon} / createBox / createCircle /
//                 createPolygon / createTerrain / destroyBody
//   joints        createRevolute / createWeld / createDistance / createPrismatic
//   step          step(dt), profile(), hash()
//   coupling      applyImpulse, velocityAt, state, inverseEffectiveMass, applyBlast
//   queries       queryAABB, rayCast, circleContacts, contacts
//
// What Box2D 2.4 cannot do exactly (the lead's tests should expect these):
//   - float state. Positions, velocities and masses are 32-bit floats, so two bodies
//     exchanging an impulse conserve momentum to float rounding (~1e-7 relative), not
//     to 1e-9. applyImpulse() returns the impulse actually delivered after rounding, so
//     a coupling that gives the particle minus that value conserves total momentum to
//     double rounding.
//   - restitution is mixed by max(e1, e2) per pair; there is no pair table.
//   - the restitution threshold (see RigidWorldDef) makes slow bounces fully inelastic.
//   - position correction: overlap is removed by a position pass (Baumgarte-like factor
//     0.2, allowed overlap b2_linearSlop = 5 mm) that moves bodies without changing
//     velocities, so energy and momentum are not exactly what the impulse solver made.
//   - polygons and edges carry a skin of b2_polygonRadius = 1 cm: contact starts when
//     the skins touch, and bodies rest 5 mm (skin minus slop) apart from the visible
//     outline of polygons/terrain.
//   - no speculative contacts in 2.4 (those came with Box2D v3): a contact exists only
//     once the AABBs overlap and the shapes are within the skin; a fast body is caught
//     by the time-of-impact pass instead (static targets always, dynamic ones for
//     bullets only), which moves it back to the moment of impact and spends the rest of
//     the sub-step without gravity.
//   - a body moves at most b2_maxTranslation = 2 m per sub-step: speeds above
//     maxSpeed() = 2 m x substeps / tick (240 m/s at 1/120 s) are silently clipped.
//     Shells faster than that stay particles or need more sub-steps.
#pragma once

#include "physics/forces.h"
#include "physics/rigid/rigid_types.h"
#include "physics/vec2.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

class b2World;
class b2Body;
class b2Joint;
class b2Fixture;

namespace phys {

/// One fixture of a body, in world coordinates, for drawing (forEachShape). The span
/// points into scratch storage that is valid only during the callback.
struct RigidShapeView {
    enum class Kind { Polygon, Circle, Chain } kind = Kind::Polygon;
    BodyId body;
    BodyType type = BodyType::Static;
    bool awake = false;
    std::span<const Vec2> vertices; ///< polygon (counter-clockwise) or chain points, world m
    bool loop = false;              ///< chain: closed
    Vec2 center;                    ///< circle centre, world m
    double radius = 0.0;            ///< circle, m
    double angle = 0.0;             ///< the body's angle, rad (marks a circle's spin)
};

/// One point of a touching contact between two bodies' fixtures, for drawing (contacts()).
struct RigidContactView {
    BodyId a;                ///< the normal points from a into b
    BodyId b;                ///< the body that is not static, when one of the two is
    Vec2 point;              ///< m
    Vec2 normal;             ///< unit
    double separation = 0.0; ///< m; < 0 means overlap
};

/// "" when the definition is usable at this tick length (s), else what is wrong and the
/// allowed range.
std::string validate(const RigidWorldDef& def, double tickSeconds);

/// "" when the vertices make a polygon Box2D can use exactly as given: 3 to
/// b2_maxPolygonVertices (8) finite vertices, no two closer than half of b2_linearSlop,
/// strictly convex (no reflex or flat corner), simple, in either winding. Box2D itself
/// would silently replace a bad polygon by its convex hull or by a 2 m box.
std::string validateConvexPolygon(std::span<const Vec2> vertices);

/// "" when the polyline can be a chain (terrain): >= 2 finite points (>= 3 for a loop),
/// consecutive points at least b2_linearSlop (5 mm) apart.
std::string validateChain(std::span<const Vec2> points, bool loop);

class RigidWorld {
  public:
    explicit RigidWorld(const RigidWorldDef& def = {});
    ~RigidWorld();
    RigidWorld(const RigidWorld&) = delete;
    RigidWorld& operator=(const RigidWorld&) = delete;

    const RigidWorldDef& def() const { return def_; }
    /// Applies new settings. The restitution threshold is re-applied to every fixture.
    void setDef(const RigidWorldDef& def);
    /// Speed above which Box2D clips motion in one sub-step (b2_maxTranslation), m/s.
    double maxSpeed(double tickSeconds) const;

    // ---- bodies ---------------------------------------------------------------------
    /// A body with no shapes yet (add them with add*).
    BodyId createBody(const BodyDef& def);
    /// Adds a box of half extents (m) centred at `center` (body frame, m), turned by
    /// `angle` (rad). False when the body is unknown or the extents are not > 0.
    bool addBox(BodyId body, Vec2 halfExtents, const RigidMaterial& material, Vec2 center = {},
                double angle = 0.0, std::string* error = nullptr);
    bool addCircle(BodyId body, double radius, const RigidMaterial& material, Vec2 center = {},
                   std::string* error = nullptr);
    /// Vertices in the body frame; see validateConvexPolygon.
    bool addPolygon(BodyId body, std::span<const Vec2> vertices, const RigidMaterial& material,
                    std::string* error = nullptr);

    /// One-shape bodies. An invalid id (and *error set) when the shape is rejected.
    BodyId createBox(const BodyDef& def, Vec2 halfExtents, const RigidMaterial& material,
                     std::string* error = nullptr);
    BodyId createCircle(const BodyDef& def, double radius, const RigidMaterial& material,
                        std::string* error = nullptr);
    BodyId createPolygon(const BodyDef& def, std::span<const Vec2> vertices,
                         const RigidMaterial& material, std::string* error = nullptr);
    /// Static terrain: a chain of edges through the world points. Box2D chains collide
    /// on one side only, so the winding says where the solid is. Open polyline: the
    /// solid lies to the right of the direction of travel (ground drawn left to right
    /// lies below it; draw it right to left for a ceiling). Loop: the solid is inside,
    /// either winding. Ghost vertices stop bodies catching on the joints between edges.
    BodyId createTerrain(std::span<const Vec2> points, const RigidMaterial& material,
                         bool loop = false, std::string* error = nullptr);

    /// Destroys the body and every joint attached to it (their ids become stale).
    void destroyBody(BodyId body);
    bool alive(BodyId body) const { return lookup(body) != nullptr; }
    /// Every live body, in slot order (deterministic).
    std::vector<BodyId> bodies() const;
    int bodyCount() const;
    /// Calls `fn` for every fixture of every live body (slot order, then fixture order),
    /// transformed to world coordinates: what a renderer needs without seeing b2Body.
    /// Edges are reported as two-point chains.
    void forEachShape(const std::function<void(const RigidShapeView&)>& fn) const;

    // ---- joints ---------------------------------------------------------------------
    JointId createRevolute(const RevoluteJointDef& def, std::string* error = nullptr);
    JointId createWeld(const WeldJointDef& def, std::string* error = nullptr);
    JointId createDistance(const DistanceJointDef& def, std::string* error = nullptr);
    JointId createPrismatic(const PrismaticJointDef& def, std::string* error = nullptr);
    void destroyJoint(JointId joint);
    bool alive(JointId joint) const { return lookup(joint) != nullptr; }
    int jointCount() const;
    /// Reaction force (N) and torque (N m) the joint exerted in the last sub-step.
    Vec2 jointReactionForce(JointId joint) const;
    double jointReactionTorque(JointId joint) const;

    // ---- step -----------------------------------------------------------------------
    /// Advances one tick of `dt` seconds (the particle world's fixed tick) in
    /// def().substeps Box2D steps. After each sub-step, joints loaded past their break
    /// force or torque are destroyed. Forces set with applyForce act for the whole tick.
    /// While every body sleeps and nothing was changed, Box2D is not stepped at all
    /// (RigidWorldDef::skipQuiescentSteps; same results).
    void step(double dt);
    /// Box2D's time of impact scans its whole contact list for each impact it resolves
    /// (up to eight a contact and step), so its cost grows as the square of the
    /// contacts, and a heap of small blocks made a tick last seconds. With more
    /// dynamic bodies than this a step runs without it (def().continuousPhysics aside);
    /// the shipped levels have at most 24 blocks.
    static constexpr int kMostContinuousBodies = 256;
    const RigidProfile& profile() const { return profile_; }
    /// Touching contacts with an awake body: the ones the solver iterates over. Sleeping
    /// islands cost nothing there; this is the deterministic proxy for their cost. Counted
    /// when asked (a walk of Box2D's contact list), not every step.
    int solvedContacts() const;
    std::uint64_t tick() const { return tick_; }
    /// Joints broken since the world was made.
    int brokenJoints() const { return brokenJoints_; }
    /// FNV-1a 64-bit over the exact bits of every live body's slot, generation,
    /// position, angle, velocities and awake flag. Equal after equal ticks.
    std::uint64_t hash(std::uint64_t seed = 0xcbf29ce484222325ull) const;

    // ---- coupling -------------------------------------------------------------------
    /// Applies an impulse (N s) at a world point (m), waking the body. Returns the
    /// linear impulse actually delivered, m (v_after - v_before) in double from the
    /// float state: give the particle minus this to conserve momentum to double
    /// rounding. Zero for static/kinematic bodies or stale ids.
    Vec2 applyImpulse(BodyId body, Vec2 impulse, Vec2 point);
    /// A force (N) at a world point (m) for the whole next tick (cleared after it).
    void applyForce(BodyId body, Vec2 force, Vec2 point);
    /// Velocity of the body's material point at a world point, m/s: v + w x r.
    Vec2 velocityAt(BodyId body, Vec2 point) const;
    /// Position, velocity, mass and inertia; a default state for stale ids.
    RigidBodyState state(BodyId body) const;
    /// 1/m + (r x n)^2 / I for an impulse along unit n at a world point: the body's
    /// share of the effective mass of a contact. 0 for static/kinematic bodies.
    double inverseEffectiveMass(BodyId body, Vec2 point, Vec2 normal) const;
    /// The velocity gravity gives the body over `dt`: g x gravity scale x dt (0 unless
    /// dynamic).
    Vec2 gravityKick(BodyId body, double dt) const;
    /// A point fixed to the body: body coordinates <-> world coordinates, m. Stale ids
    /// map a point to itself.
    Vec2 worldPoint(BodyId body, Vec2 local) const;
    Vec2 localPoint(BodyId body, Vec2 world) const;
    /// Radial impulse J(d) = J0 (1 - d/R) (forces.h Blast) on every dynamic body whose
    /// centre of mass is within R, applied at the centre of mass (like the particle
    /// blast: a push, no spin; straight up at d = 0). Returns the bodies pushed.
    int applyBlast(const Blast& blast);

    void setTransform(BodyId body, Vec2 position, double angle);
    void setVelocity(BodyId body, Vec2 linear, double angular);
    void setAwake(BodyId body, bool awake);
    void setBullet(BodyId body, bool bullet);

    // ---- queries (not thread-safe: they share scratch buffers) ----------------------
    /// Bodies with a shape whose exact (not fattened) bounding box overlaps [lo, hi],
    /// sorted by id, each once. `out` is cleared first (reuse it: no allocation once
    /// its capacity suffices).
    void queryAABB(Vec2 lo, Vec2 hi, std::vector<BodyId>& out) const;
    /// Closest hit along the segment from -> to; shapes containing `from` are ignored.
    std::optional<RigidRayHit> rayCast(Vec2 from, Vec2 to) const;
    /// Contacts of a circle (a particle: centre m, radius m) with every body shape it
    /// touches or overlaps, within `margin` m. `out` is cleared first; order is by body
    /// slot, then fixture. `ignore` is skipped (the body itself when probing from one).
    void circleContacts(Vec2 center, double radius, std::vector<RigidCircleContact>& out,
                        double margin = 0.0, BodyId ignore = {}) const;
    /// Box2D's touching contacts after the last step, one entry per manifold point, in
    /// b2World's contact order. `out` is cleared first.
    void contacts(std::vector<RigidContactView>& out) const;

  private:
    struct BodySlot {
        b2Body* body = nullptr;
        std::uint32_t generation = 0;
    };
    struct JointSlot {
        b2Joint* joint = nullptr;
        std::uint32_t generation = 0;
        double breakForce = 0.0;
        double breakTorque = 0.0;
    };

    b2Body* lookup(BodyId id) const;
    b2Joint* lookup(JointId id) const;
    BodyId idOf(const b2Body* body) const;
    bool addFixture(BodyId body, const void* shape, const RigidMaterial& material,
                    std::string* error);
    JointId finishJoint(b2Joint* joint, const JointBase& def);
    bool checkJointBodies(const JointBase& def, std::string* error) const;
    void freeJointSlot(std::uint32_t index);
    int breakOverloadedJoints(double invSubstep);

    RigidWorldDef def_;
    std::unique_ptr<b2World> world_;
    std::vector<BodySlot> bodies_;
    std::vector<std::uint32_t> freeBodies_;
    std::vector<JointSlot> joints_;
    std::vector<std::uint32_t> freeJoints_;
    RigidProfile profile_;
    std::uint64_t tick_ = 0;
    int brokenJoints_ = 0;
    double lastInvSubstep_ = 0.0;
    bool quiet_ = false;     ///< nothing awake after the last step, nothing changed since
    float lastStepH_ = 0.0f; ///< sub-step length Box2D was last stepped with, s
    // Scratch for the queries, so a query per particle per tick does not allocate once
    // warm. (Queries are therefore not safe to call from two threads at once.)
    mutable std::vector<const b2Body*> scratchBodies_;
    mutable std::vector<BodyId> scratchIds_;
    mutable std::vector<Vec2> scratchVertices_;
};

} // namespace phys
