// RigidWorld: the Box2D bridge. Section index: set-up, bodies, step, coupling; the joints,
// the queries and the validation of definitions have files of their own (rigid_joints.cpp,
// rigid_queries.cpp, rigid_validate.cpp).
#include "physics/rigid/rigid_world.h"

#include "physics/rigid/box2d_bridge.h"

#include <box2d/box2d.h>

#include "physics/diagnostics.h"
#include "physics/phase_clock.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace phys {

using namespace box2d_bridge;

// ---- set-up ----------------------------------------------------------------------------

RigidWorld::RigidWorld(const RigidWorldDef& def)
    : def_(def), world_(std::make_unique<b2World>(toB2(def.gravity))) {
    // Forces are cleared by step() after all sub-steps, so a force acts for a whole tick
    // whatever the sub-step count.
    world_->SetAutoClearForces(false);
    setDef(def);
}

RigidWorld::~RigidWorld() = default;

void RigidWorld::setDef(const RigidWorldDef& def) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    def_ = def;
    world_->SetGravity(toB2(def.gravity));
    world_->SetAllowSleeping(def.allowSleeping);
    world_->SetWarmStarting(def.warmStarting);
    world_->SetContinuousPhysics(def.continuousPhysics);
    const auto threshold = static_cast<float>(def.restitutionThreshold);
    for (b2Body* b = world_->GetBodyList(); b; b = b->GetNext())
        for (b2Fixture* f = b->GetFixtureList(); f; f = f->GetNext())
            f->SetRestitutionThreshold(threshold);
    // Existing contacts cached the mixed value; make them re-read it.
    for (b2Contact* c = world_->GetContactList(); c; c = c->GetNext())
        c->ResetRestitutionThreshold();
}

double RigidWorld::maxSpeed(double tickSeconds) const {
    return b2_maxTranslation * def_.substeps / tickSeconds;
}


// ---- bodies ----------------------------------------------------------------------------

b2Body* RigidWorld::lookup(BodyId id) const {
    if (id.index >= bodies_.size()) return nullptr;
    const BodySlot& s = bodies_[id.index];
    return s.generation == id.generation ? s.body : nullptr;
}

BodyId RigidWorld::idOf(const b2Body* body) const {
    // userData holds slot index + 1 (0 is Box2D's "no data").
    const auto index =
        static_cast<std::uint32_t>(const_cast<b2Body*>(body)->GetUserData().pointer - 1);
    return {index, bodies_[index].generation};
}

BodyId RigidWorld::createBody(const BodyDef& def) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    std::uint32_t index;
    if (!freeBodies_.empty()) {
        index = freeBodies_.back();
        freeBodies_.pop_back();
    } else {
        index = static_cast<std::uint32_t>(bodies_.size());
        bodies_.push_back({});
    }
    b2BodyDef bd;
    bd.type = toB2(def.type);
    bd.position = toB2(def.position);
    bd.angle = static_cast<float>(def.angle);
    bd.linearVelocity = toB2(def.linearVelocity);
    bd.angularVelocity = static_cast<float>(def.angularVelocity);
    bd.linearDamping = static_cast<float>(def.linearDamping);
    bd.angularDamping = static_cast<float>(def.angularDamping);
    bd.gravityScale = static_cast<float>(def.gravityScale);
    bd.bullet = def.bullet;
    bd.allowSleep = def.allowSleep;
    bd.awake = def.awake;
    bd.fixedRotation = def.fixedRotation;
    bd.userData.pointer = static_cast<uintptr_t>(index) + 1;
    bodies_[index].body = world_->CreateBody(&bd);
    return {index, bodies_[index].generation};
}

bool RigidWorld::addFixture(BodyId id, const void* shape, const RigidMaterial& material,
                            std::string* error) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    b2Body* body = lookup(id);
    if (!body) {
        setError(error, "unknown or destroyed body id " + std::to_string(id.index));
        return false;
    }
    if (std::string e = validate(material); !e.empty()) {
        setError(error, e);
        return false;
    }
    b2FixtureDef fd;
    fd.shape = static_cast<const b2Shape*>(shape);
    fd.density = static_cast<float>(material.density);
    fd.friction = static_cast<float>(material.friction);
    fd.restitution = static_cast<float>(material.restitution);
    fd.restitutionThreshold = static_cast<float>(def_.restitutionThreshold);
    body->CreateFixture(&fd);
    return true;
}

bool RigidWorld::addBox(BodyId body, Vec2 half, const RigidMaterial& material, Vec2 center,
                        double angle, std::string* error) {
    if (!(half.x > 0.0 && half.y > 0.0) || !finite(half) || !finite(center)) {
        setError(error, "box half extents " + fmt(half) + " m: must be finite and > 0");
        return false;
    }
    b2PolygonShape box;
    box.SetAsBox(static_cast<float>(half.x), static_cast<float>(half.y), toB2(center),
                 static_cast<float>(angle));
    return addFixture(body, &box, material, error);
}

bool RigidWorld::addCircle(BodyId body, double radius, const RigidMaterial& material, Vec2 center,
                           std::string* error) {
    if (!(radius > 0.0) || !std::isfinite(radius) || !finite(center)) {
        setError(error, "circle radius " + fmt(radius) + " m: must be finite and > 0");
        return false;
    }
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(radius);
    circle.m_p = toB2(center);
    return addFixture(body, &circle, material, error);
}

bool RigidWorld::addPolygon(BodyId body, std::span<const Vec2> vertices,
                            const RigidMaterial& material, std::string* error) {
    if (std::string e = validateConvexPolygon(vertices); !e.empty()) {
        setError(error, e);
        return false;
    }
    std::array<b2Vec2, b2_maxPolygonVertices> pts;
    for (std::size_t i = 0; i < vertices.size(); ++i)
        pts[i] = toB2(vertices[i]);
    b2PolygonShape polygon;
    polygon.Set(pts.data(), static_cast<int32>(vertices.size()));
    return addFixture(body, &polygon, material, error);
}

BodyId RigidWorld::createBox(const BodyDef& def, Vec2 half, const RigidMaterial& material,
                             std::string* error) {
    const BodyId id = createBody(def);
    if (!addBox(id, half, material, {}, 0.0, error)) {
        destroyBody(id);
        return {};
    }
    return id;
}

BodyId RigidWorld::createCircle(const BodyDef& def, double radius, const RigidMaterial& material,
                                std::string* error) {
    const BodyId id = createBody(def);
    if (!addCircle(id, radius, material, {}, error)) {
        destroyBody(id);
        return {};
    }
    return id;
}

BodyId RigidWorld::createPolygon(const BodyDef& def, std::span<const Vec2> vertices,
                                 const RigidMaterial& material, std::string* error) {
    const BodyId id = createBody(def);
    if (!addPolygon(id, vertices, material, error)) {
        destroyBody(id);
        return {};
    }
    return id;
}

BodyId RigidWorld::createTerrain(std::span<const Vec2> points, const RigidMaterial& material,
                                 bool loop, std::string* error) {
    if (std::string e = validateChain(points, loop); !e.empty()) {
        setError(error, e);
        return {};
    }
    std::vector<b2Vec2> pts;
    pts.reserve(points.size());
    for (Vec2 p : points)
        pts.push_back(toB2(p));
    // Box2D's chain collides on the side its edge normals point to, which is the right
    // of the direction of travel. The API promises the solid on the right for open
    // chains (so the colliding side is the left), and the solid inside for loops
    // (counter-clockwise loops have their right-hand normals pointing out).
    b2ChainShape chain;
    if (loop) {
        double area2 = 0.0;
        for (std::size_t i = 0; i < points.size(); ++i)
            area2 += cross(points[i], points[(i + 1) % points.size()]);
        if (area2 < 0.0) std::reverse(pts.begin(), pts.end());
        chain.CreateLoop(pts.data(), static_cast<int32>(pts.size()));
    } else {
        std::reverse(pts.begin(), pts.end());
        // Ghost vertices continue the end edges straight on, so nothing catches there.
        const b2Vec2 prev = 2.0f * pts.front() - pts[1];
        const b2Vec2 next = 2.0f * pts.back() - pts[pts.size() - 2];
        chain.CreateChain(pts.data(), static_cast<int32>(pts.size()), prev, next);
    }
    BodyDef bd;
    bd.type = BodyType::Static;
    const BodyId id = createBody(bd);
    if (!addFixture(id, &chain, material, error)) {
        destroyBody(id);
        return {};
    }
    return id;
}

void RigidWorld::destroyBody(BodyId id) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    b2Body* body = lookup(id);
    if (!body) return;
    // Box2D does not wake what rested on the body: a block pulled out of a sleeping
    // castle would leave the rest floating. Wake everything it touches.
    for (b2ContactEdge* e = body->GetContactList(); e; e = e->next)
        if (e->contact->IsTouching()) e->other->SetAwake(true);
    // Box2D destroys the body's joints with it (waking the bodies at their other ends);
    // free their slots first so their ids go stale instead of dangling.
    for (b2JointEdge* e = body->GetJointList(); e; e = e->next)
        freeJointSlot(static_cast<std::uint32_t>(e->joint->GetUserData().pointer - 1));
    world_->DestroyBody(body);
    BodySlot& slot = bodies_[id.index];
    slot.body = nullptr;
    ++slot.generation;
    freeBodies_.push_back(id.index);
}

std::vector<BodyId> RigidWorld::bodies() const {
    std::vector<BodyId> out;
    for (std::uint32_t i = 0; i < bodies_.size(); ++i)
        if (bodies_[i].body) out.push_back({i, bodies_[i].generation});
    return out;
}

int RigidWorld::bodyCount() const {
    return world_->GetBodyCount();
}


// ---- step ------------------------------------------------------------------------------

int RigidWorld::breakOverloadedJoints(double invSubstep) {
    // Box2D keeps each joint's accumulated impulse of the last step; divided by the step
    // length it is the force the joint had to exert. Slot order keeps this deterministic.
    const auto inv = static_cast<float>(invSubstep);
    int broke = 0;
    for (std::uint32_t i = 0; i < joints_.size(); ++i) {
        b2Joint* joint = joints_[i].joint;
        if (!joint) continue;
        const double force = length(fromB2(joint->GetReactionForce(inv)));
        const double torque = std::abs(static_cast<double>(joint->GetReactionTorque(inv)));
        if (force > joints_[i].breakForce || torque > joints_[i].breakTorque) {
            world_->DestroyJoint(joint);
            freeJointSlot(i);
            ++broke;
        }
    }
    return broke;
}

void RigidWorld::step(double dt) {
    const int n = std::max(1, def_.substeps);
    const auto h = static_cast<float>(dt / n);
    ++tick_;
    // Quiescent world: nothing awake after the last step, nothing changed since, same
    // sub-step length. Box2D would only walk its lists and change no state that is read
    // later, so skipping it gives the same bits (tested) and a sleeping scene costs next
    // to nothing. A new sub-step length is not skipped: Box2D rescales warm starting by
    // the ratio of consecutive step lengths.
    if (quiet_ && def_.skipQuiescentSteps && h == lastStepH_) {
        profile_.stepUs = 0.0;
        profile_.jointsBroken = 0;
        profile_.skipped = true; // the counts are those of the last step, still true
        return;
    }
    profile_ = {};
    lastStepH_ = h;
    lastInvSubstep_ = h > 0.0f ? 1.0 / static_cast<double>(h) : 0.0;
    int dynamicBodies = 0;
    for (const BodySlot& slot : bodies_)
        dynamicBodies += slot.body && slot.body->GetType() != b2_staticBody ? 1 : 0;
    profile_.continuous = def_.continuousPhysics && dynamicBodies <= kMostContinuousBodies;
    world_->SetContinuousPhysics(profile_.continuous);
    const PhaseClock clock; // always on: the rigid world is stepped once a tick
    for (int s = 0; s < n; ++s) {
        // Box2D step: broad phase, narrow phase, island solve (integrate velocities,
        // velocity iterations with restitution, integrate positions, position
        // iterations), time of impact, sleep. The clock is read around it only.
        const auto t0 = clock.now();
        world_->Step(h, def_.velocityIterations, def_.positionIterations);
        profile_.stepUs += clock.microsSince(t0);
        // Break overloaded joints after every sub-step, so a joint that fails does not
        // hold for the rest of the tick.
        profile_.jointsBroken += breakOverloadedJoints(lastInvSubstep_);
    }
    world_->ClearForces();
    brokenJoints_ += profile_.jointsBroken;

    // Counts for the stats panel and for tests (deterministic, unlike the time).
    for (const BodySlot& slot : bodies_) {
        if (!slot.body || slot.body->GetType() == b2_staticBody) continue;
        if (slot.body->IsAwake())
            ++profile_.awakeBodies;
        else
            ++profile_.sleepingBodies;
    }
    quiet_ = profile_.awakeBodies == 0;
    profile_.contacts = world_->GetContactCount();
}

int RigidWorld::solvedContacts() const {
    int solved = 0;
    for (const b2Contact* c = world_->GetContactList(); c; c = c->GetNext()) {
        if (!c->IsTouching() || !c->IsEnabled()) continue;
        if (c->GetFixtureA()->GetBody()->IsAwake() || c->GetFixtureB()->GetBody()->IsAwake())
            ++solved;
    }
    return solved;
}

std::uint64_t RigidWorld::hash(std::uint64_t h) const {
    for (std::uint32_t i = 0; i < bodies_.size(); ++i) {
        const b2Body* b = bodies_[i].body;
        if (!b) continue;
        const b2Vec2 p = b->GetPosition();
        const b2Vec2 v = b->GetLinearVelocity();
        const float s[6] = {p.x, p.y, b->GetAngle(), v.x, v.y, b->GetAngularVelocity()};
        const std::uint8_t awake = b->IsAwake() ? 1 : 0;
        h = hashBytes(h, &i, sizeof i);
        h = hashBytes(h, &bodies_[i].generation, sizeof bodies_[i].generation);
        h = hashBytes(h, s, sizeof s);
        h = hashBytes(h, &awake, sizeof awake);
    }
    return h;
}


// ---- coupling --------------------------------------------------------------------------

Vec2 RigidWorld::applyImpulse(BodyId id, Vec2 impulse, Vec2 point) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    b2Body* body = lookup(id);
    if (!body || body->GetType() != b2_dynamicBody) return {};
    const Vec2 v0 = fromB2(body->GetLinearVelocity());
    body->ApplyLinearImpulse(toB2(impulse), toB2(point), true);
    const Vec2 v1 = fromB2(body->GetLinearVelocity());
    // The momentum the body really gained, from the float velocities it now holds.
    return static_cast<double>(body->GetMass()) * (v1 - v0);
}

void RigidWorld::applyForce(BodyId id, Vec2 force, Vec2 point) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    if (b2Body* body = lookup(id)) body->ApplyForce(toB2(force), toB2(point), true);
}

Vec2 RigidWorld::velocityAt(BodyId id, Vec2 point) const {
    const b2Body* body = lookup(id);
    return body ? fromB2(body->GetLinearVelocityFromWorldPoint(toB2(point))) : Vec2{};
}

RigidBodyState RigidWorld::state(BodyId id) const {
    RigidBodyState s;
    const b2Body* b = lookup(id);
    if (!b) return s;
    s.type = fromB2(b->GetType());
    s.position = fromB2(b->GetPosition());
    s.angle = b->GetAngle();
    s.centerOfMass = fromB2(b->GetWorldCenter());
    s.linearVelocity = fromB2(b->GetLinearVelocity());
    s.angularVelocity = b->GetAngularVelocity();
    s.awake = b->IsAwake();
    if (b->GetType() == b2_dynamicBody) {
        s.mass = b->GetMass();
        // Box2D reports inertia about the body origin; shift it to the centre of mass
        // (parallel axis theorem).
        const Vec2 c = fromB2(b->GetLocalCenter());
        s.inertia = std::max(0.0, static_cast<double>(b->GetInertia()) - s.mass * dot(c, c));
    }
    return s;
}

double RigidWorld::inverseEffectiveMass(BodyId id, Vec2 point, Vec2 normal) const {
    const RigidBodyState s = state(id);
    if (s.type != BodyType::Dynamic || !(s.mass > 0.0)) return 0.0;
    const double rn = cross(point - s.centerOfMass, normal);
    const double invI = s.inertia > 0.0 ? 1.0 / s.inertia : 0.0; // fixed rotation: 0
    return 1.0 / s.mass + rn * rn * invI;
}

Vec2 RigidWorld::gravityKick(BodyId id, double dt) const {
    const b2Body* body = lookup(id);
    if (!body || body->GetType() != b2_dynamicBody) return {};
    return def_.gravity * (static_cast<double>(body->GetGravityScale()) * dt);
}

Vec2 RigidWorld::worldPoint(BodyId id, Vec2 local) const {
    const b2Body* body = lookup(id);
    return body ? fromB2(body->GetWorldPoint(toB2(local))) : local;
}

Vec2 RigidWorld::localPoint(BodyId id, Vec2 world) const {
    const b2Body* body = lookup(id);
    return body ? fromB2(body->GetLocalPoint(toB2(world))) : world;
}

int RigidWorld::applyBlast(const Blast& blast) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    if (!(blast.radius > 0.0)) return 0;
    int pushed = 0;
    for (const BodySlot& slot : bodies_) {
        b2Body* b = slot.body;
        if (!b || b->GetType() != b2_dynamicBody) continue;
        const Vec2 d = fromB2(b->GetWorldCenter()) - blast.center;
        const double dist = length(d);
        if (dist >= blast.radius) continue;
        // Same law and same centre rule as the particle blast (forces.cpp).
        const Vec2 dir = dist > 0.0 ? d / dist : Vec2{0.0, 1.0};
        const double j = blast.impulse * (1.0 - dist / blast.radius);
        b->ApplyLinearImpulseToCenter(toB2(dir * j), true);
        ++pushed;
    }
    return pushed;
}

void RigidWorld::setTransform(BodyId id, Vec2 position, double angle) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    if (b2Body* b = lookup(id)) b->SetTransform(toB2(position), static_cast<float>(angle));
}

void RigidWorld::setVelocity(BodyId id, Vec2 linear, double angular) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    if (b2Body* b = lookup(id)) {
        b->SetLinearVelocity(toB2(linear));
        b->SetAngularVelocity(static_cast<float>(angular));
    }
}

void RigidWorld::setAwake(BodyId id, bool awake) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    if (b2Body* b = lookup(id)) b->SetAwake(awake);
}

void RigidWorld::setBullet(BodyId id, bool bullet) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    if (b2Body* b = lookup(id)) b->SetBullet(bullet);
}


} // namespace phys
