// Value types of the rigid-body layer: handles, definitions with defaults and units,
// and the results of queries. Nothing here names a Box2D type, so the game and the UI
// can hold and pass these without including Box2D.
//
// Units are SI (m, kg, s, rad), y up, like the particle layer. Box2D stores everything
// as float; these structs use double and the conversion happens at the boundary
// (rigid_world.cpp). Read the precision consequences in rigid_world.h.
#pragma once

#include "physics/vec2.h"

#include <cstdint>
#include <limits>

namespace phys {

/// Stable handle of a rigid body. The slot index is reused after a body is destroyed,
/// the generation is not, so a stale handle is detected instead of naming a new body.
struct BodyId {
    static constexpr std::uint32_t kNone = 0xffffffffu;
    std::uint32_t index = kNone;
    std::uint32_t generation = 0;
    constexpr bool valid() const { return index != kNone; }
    constexpr bool operator==(const BodyId&) const = default;
    constexpr auto operator<=>(const BodyId&) const = default;
};

/// Stable handle of a joint (same scheme as BodyId).
struct JointId {
    static constexpr std::uint32_t kNone = 0xffffffffu;
    std::uint32_t index = kNone;
    std::uint32_t generation = 0;
    constexpr bool valid() const { return index != kNone; }
    constexpr bool operator==(const JointId&) const = default;
};

/// Settings of the rigid world, with defaults and units.
struct RigidWorldDef {
    Vec2 gravity{0.0, -9.81};   ///< uniform gravity, m/s^2 (same default as ForceDef)
    int velocityIterations = 8; ///< Box2D velocity solver iterations per sub-step, >= 1
    int positionIterations = 3; ///< Box2D position (NGS) iterations per sub-step, >= 0
    /// Box2D steps per tick: each advances tick/substeps, >= 1. More sub-steps make
    /// stacks stiffer, bounces closer to the restitution preset and raise the speed cap
    /// (see maxSpeed()).
    int substeps = 1;
    bool allowSleeping = true;     ///< resting bodies sleep (Box2D: 0.5 s below 0.01 m/s, 2 deg/s)
    bool warmStarting = true;      ///< reuse last step's impulses (off only to show its effect)
    bool continuousPhysics = true; ///< time of impact against static bodies, and for bullets
    /// Normal approach speed below which a contact does not bounce, m/s, >= 0. Box2D's
    /// default is 1 m/s, which silently turns every bounce slower than that into a dead
    /// stop (a ball dropped from 5 cm would not bounce at all). It must stay above the
    /// speed gravity adds in one sub-step, |g| tick/substeps (0.082 m/s at 1/120 s), or
    /// bodies resting on each other bounce on that speed every step, jitter and never
    /// sleep. 0.25 m/s loses only bounces whose apex would be below v^2/(2g) = 3.2 mm.
    /// validate(def, tick) checks the lower bound.
    double restitutionThreshold = 0.25;
    /// Skip b2World::Step while every body sleeps and nothing was changed through the
    /// API since the last step (Box2D would only walk its lists). Same results either
    /// way; off only to measure what Box2D itself costs for a sleeping scene.
    bool skipQuiescentSteps = true;
};

/// Material of one fixture. Box2D combines a touching pair as: friction sqrt(f1 f2),
/// restitution max(e1, e2), threshold min(t1, t2). There is no pair table in Box2D, so
/// a restitution preset is exact only against a surface whose restitution is <= it
/// (static terrain uses 0 by default for that reason).
struct RigidMaterial {
    double density = 1000.0;  ///< kg/m^2 (Box2D is 2D: mass = density x area), >= 0
    double friction = 0.6;    ///< Coulomb coefficient, >= 0
    double restitution = 0.0; ///< coefficient of restitution, 0..1
};

enum class BodyType {
    Static,    ///< never moves, infinite mass (terrain, walls)
    Kinematic, ///< moves at its set velocity, ignores forces and contacts
    Dynamic,   ///< moved by gravity, contacts, joints and impulses
};

/// Definition of one body (its shapes are added separately), with defaults and units.
struct BodyDef {
    BodyType type = BodyType::Dynamic;
    Vec2 position;                ///< body origin, m
    double angle = 0.0;           ///< rad, counter-clockwise
    Vec2 linearVelocity;          ///< m/s, of the origin
    double angularVelocity = 0.0; ///< rad/s
    double linearDamping = 0.0;   ///< 1/s: v *= 1/(1 + h c) per sub-step (a crude drag)
    double angularDamping = 0.0;  ///< 1/s
    double gravityScale = 1.0;    ///< multiplies world gravity for this body
    /// Continuous collision against other dynamic bodies too (not only static ones), so
    /// a fast body cannot pass through a thin dynamic one. Costs a time-of-impact solve.
    bool bullet = false;
    bool allowSleep = true; ///< false keeps it awake (e.g. a player-controlled body)
    bool awake = true;
    bool fixedRotation = false;
};

/// Common part of every joint definition, with defaults and units.
struct JointBase {
    BodyId a;                      ///< first body
    BodyId b;                      ///< second body
    bool collideConnected = false; ///< may the two bodies still collide with each other
    /// The joint is destroyed after a sub-step in which its reaction force exceeds this,
    /// N. Infinity = unbreakable.
    double breakForce = std::numeric_limits<double>::infinity();
    /// Same for the reaction torque, N m (revolute limits/motors and welds carry torque).
    double breakTorque = std::numeric_limits<double>::infinity();
};

/// A pin: the bodies share the anchor point and rotate freely about it.
struct RevoluteJointDef : JointBase {
    Vec2 anchor; ///< world point, m
    bool enableLimit = false;
    double lowerAngle = 0.0; ///< rad, relative to the angle at creation
    double upperAngle = 0.0; ///< rad
    bool enableMotor = false;
    double motorSpeed = 0.0;     ///< rad/s
    double maxMotorTorque = 0.0; ///< N m
};

/// Glues the bodies together at the anchor (relative position and angle fixed).
struct WeldJointDef : JointBase {
    Vec2 anchor;            ///< world point, m
    double stiffness = 0.0; ///< angular stiffness, N m/rad; 0 = rigid
    double damping = 0.0;   ///< angular damping, N m s/rad
};

/// Keeps two anchor points at a distance: a rod (stiffness 0), a spring, or a rope
/// (minLength 0, maxLength = length).
struct DistanceJointDef : JointBase {
    Vec2 anchorA;            ///< world point on a, m
    Vec2 anchorB;            ///< world point on b, m
    double length = -1.0;    ///< rest length, m; < 0 = the current distance
    double minLength = -1.0; ///< m; < 0 = length
    double maxLength = -1.0; ///< m; < 0 = length
    double stiffness = 0.0;  ///< N/m; 0 = rigid rod
    double damping = 0.0;    ///< N s/m
};

/// A slider: b moves along an axis fixed in a; no relative rotation.
struct PrismaticJointDef : JointBase {
    Vec2 anchor;         ///< world point, m
    Vec2 axis{1.0, 0.0}; ///< world direction, normalised on creation
    bool enableLimit = false;
    double lowerTranslation = 0.0; ///< m
    double upperTranslation = 0.0; ///< m
    bool enableMotor = false;
    double motorSpeed = 0.0;    ///< m/s
    double maxMotorForce = 0.0; ///< N
};

/// Where a body is and how it moves, plus what coupling needs to compute an impulse.
struct RigidBodyState {
    BodyType type = BodyType::Static;
    Vec2 position;                ///< body origin, m
    double angle = 0.0;           ///< rad
    Vec2 centerOfMass;            ///< world, m
    Vec2 linearVelocity;          ///< of the centre of mass, m/s
    double angularVelocity = 0.0; ///< rad/s
    double mass = 0.0;            ///< kg; 0 for static and kinematic bodies
    double inertia = 0.0;         ///< about the centre of mass, kg m^2; 0 when not dynamic
    bool awake = false;
};

/// Closest hit of a ray.
struct RigidRayHit {
    BodyId body;
    Vec2 point;            ///< m
    Vec2 normal;           ///< unit surface normal at the hit, pointing out of the body
    double fraction = 0.0; ///< 0..1 along from -> to
};

/// Contact of a probe circle (a particle) with one shape of a body.
struct RigidCircleContact {
    BodyId body;
    Vec2 point;               ///< midway between the two surfaces, m
    Vec2 normal;              ///< unit, from the body towards the circle's centre
    double separation = 0.0;  ///< m; < 0 means penetration
    double friction = 0.0;    ///< of the body's fixture
    double restitution = 0.0; ///< of the body's fixture
};

/// What the last step did and cost. Counts are exact and deterministic; the time is for
/// profiling only (the clock is read around b2World::Step, never inside the simulation).
struct RigidProfile {
    double stepUs = 0.0;    ///< wall time inside b2World::Step, all sub-steps, microseconds
    int awakeBodies = 0;    ///< non-static bodies awake after the step
    int sleepingBodies = 0; ///< non-static bodies asleep after the step
    int contacts = 0;       ///< contacts Box2D keeps (AABB pairs), touching or not
    int jointsBroken = 0; ///< joints destroyed by breakForce / breakTorque this step
    bool skipped = false; ///< Box2D was not stepped: everything asleep, nothing changed
    bool continuous = false; ///< Box2D's time of impact ran (kMostContinuousBodies)
};

} // namespace phys
