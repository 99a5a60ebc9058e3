// RigidWorld: the Box2D bridge. Section index: conversions, validation, set-up,
// bodies, joints, step, coupling, queries.
#include "physics/rigid/rigid_world.h"

#include "physics/diagnostics.h"
#include "physics/phase_clock.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>

namespace phys {
namespace {

// ---- conversions ---------------------------------------------------------------------
// Box2D is float; the rest of the project is double. Converting only here keeps the
// rounding in one place.
b2Vec2 toB2(Vec2 v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y)};
}
Vec2 fromB2(const b2Vec2& v) {
    return {static_cast<double>(v.x), static_cast<double>(v.y)};
}

b2BodyType toB2(BodyType t) {
    switch (t) {
    case BodyType::Static:
        return b2_staticBody;
    case BodyType::Kinematic:
        return b2_kinematicBody;
    case BodyType::Dynamic:
        break;
    }
    return b2_dynamicBody;
}

BodyType fromB2(b2BodyType t) {
    switch (t) {
    case b2_staticBody:
        return BodyType::Static;
    case b2_kinematicBody:
        return BodyType::Kinematic;
    case b2_dynamicBody:
        break;
    }
    return BodyType::Dynamic;
}

bool finite(Vec2 v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

std::string fmt(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}
std::string fmt(Vec2 v) {
    // One stream, not string concatenation: GCC 12 warns falsely (-Wrestrict) on the latter.
    std::ostringstream s;
    s << '(' << v.x << ", " << v.y << ')';
    return s.str();
}

void setError(std::string* out, const std::string& what) {
    if (out) *out = what;
}

std::string validate(const RigidMaterial& m) {
    if (!(m.density >= 0.0) || !std::isfinite(m.density))
        return "material density " + fmt(m.density) + " kg/m^2: must be finite and >= 0";
    if (!(m.friction >= 0.0) || !std::isfinite(m.friction))
        return "material friction " + fmt(m.friction) + ": must be finite and >= 0";
    if (!(m.restitution >= 0.0 && m.restitution <= 1.0))
        return "material restitution " + fmt(m.restitution) + ": must be in 0..1";
    return {};
}

// ---- query callbacks ----------------------------------------------------------------
class CollectBodies final : public b2QueryCallback {
  public:
    CollectBodies(const b2AABB& box, std::vector<const b2Body*>& out) : box_(box), out_(out) {}
    bool ReportFixture(b2Fixture* f) override {
        // The tree holds fattened boxes; test the shape's exact box so callers get only
        // real overlaps.
        // The query reports a fixture once per child proxy it touches, without the
        // child, so a terrain chain of n edges would cost n^2 box computations: each
        // child is skipped unless its proxy box (the union of its exact boxes at the
        // last two transforms, which holds the exact box) touches the query's.
        // A fixture reported again (another of its children) was tested whole already.
        const b2Shape* shape = f->GetShape();
        if (shape->GetChildCount() > 1) {
            if (std::find(tested_.begin(), tested_.end(), f) != tested_.end()) return true;
            tested_.push_back(f);
        }
        // A static body's proxy box is its exact box (both transforms are the same one).
        const b2Transform& xf = f->GetBody()->GetTransform();
        const bool still = f->GetBody()->GetType() == b2_staticBody;
        for (int32 c = 0; c < shape->GetChildCount(); ++c) {
            if (!b2TestOverlap(f->GetAABB(c), box_)) continue;
            b2AABB exact = f->GetAABB(c);
            if (!still) shape->ComputeAABB(&exact, xf, c);
            if (b2TestOverlap(exact, box_)) {
                out_.push_back(f->GetBody());
                break;
            }
        }
        return true;
    }

  private:
    b2AABB box_;
    std::vector<const b2Body*>& out_;
    std::vector<const b2Fixture*> tested_; ///< chains (several children) tested so far
};

class ClosestRay final : public b2RayCastCallback {
  public:
    float ReportFixture(b2Fixture* f, const b2Vec2& point, const b2Vec2& normal,
                        float fraction) override {
        // Returning the fraction clips the ray, so the last report is the closest.
        body = f->GetBody();
        hitPoint = point;
        hitNormal = normal;
        hitFraction = fraction;
        return fraction;
    }
    const b2Body* body = nullptr;
    b2Vec2 hitPoint{0.0f, 0.0f};
    b2Vec2 hitNormal{0.0f, 0.0f};
    float hitFraction = 1.0f;
};

} // namespace

// ---- validation ------------------------------------------------------------------------

std::string validate(const RigidWorldDef& def, double tickSeconds) {
    if (!(tickSeconds > 0.0) || !std::isfinite(tickSeconds))
        return "tick " + fmt(tickSeconds) + " s: must be finite and > 0";
    if (!finite(def.gravity)) return "gravity " + fmt(def.gravity) + ": must be finite";
    if (def.velocityIterations < 1)
        return "velocityIterations " + std::to_string(def.velocityIterations) + ": must be >= 1";
    if (def.positionIterations < 0)
        return "positionIterations " + std::to_string(def.positionIterations) + ": must be >= 0";
    if (def.substeps < 1 || def.substeps > 64)
        return "substeps " + std::to_string(def.substeps) + ": must be in 1..64";
    const double perStep = length(def.gravity) * tickSeconds / def.substeps;
    if (!(def.restitutionThreshold > perStep) || !std::isfinite(def.restitutionThreshold))
        return "restitutionThreshold " + fmt(def.restitutionThreshold) +
               " m/s is not above the speed gravity adds in one sub-step (" + fmt(perStep) +
               " m/s = |g| x tick / substeps): resting bodies would bounce on it and never "
               "sleep; raise it above " +
               fmt(perStep) + " or use more sub-steps";
    return {};
}

std::string validateConvexPolygon(std::span<const Vec2> v) {
    const std::size_t n = v.size();
    if (n < 3 || n > static_cast<std::size_t>(b2_maxPolygonVertices))
        return "polygon has " + std::to_string(n) + " vertices; Box2D allows 3.." +
               std::to_string(b2_maxPolygonVertices) +
               " (b2_maxPolygonVertices): split it into convex pieces (addPolygon per piece)";
    for (std::size_t i = 0; i < n; ++i)
        if (!finite(v[i])) return "vertex " + std::to_string(i) + " is not finite";
    // Box2D welds points closer than half the linear slop, which would change the count.
    const double weld = 0.5 * b2_linearSlop;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (length(v[i] - v[j]) < weld)
                return "vertices " + std::to_string(i) + " " + fmt(v[i]) + " and " +
                       std::to_string(j) + " " + fmt(v[j]) + " are closer than " + fmt(weld) +
                       " m (half of b2_linearSlop): remove one";
    double area2 = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        area2 += cross(v[i], v[(i + 1) % n]);
    if (!(std::abs(area2) > 2.0 * b2_linearSlop * b2_linearSlop))
        return "polygon area " + fmt(0.5 * area2) + " m^2 is degenerate (vertices collinear?)";
    const double winding = area2 > 0.0 ? 1.0 : -1.0;
    // Strict convexity: every corner turns the same way as the winding, by a clear
    // margin (Box2D's hull would silently drop a flat corner and change the shape).
    double turning = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 e0 = v[(i + 1) % n] - v[i];
        const Vec2 e1 = v[(i + 2) % n] - v[(i + 1) % n];
        const double s = winding * cross(e0, e1) / (length(e0) * length(e1));
        if (!(s > 1e-6))
            return "corner at vertex " + std::to_string((i + 1) % n) + " " + fmt(v[(i + 1) % n]) +
                   " is " + (s < 0.0 ? "reflex" : "flat") +
                   ": the polygon must be strictly convex (split concave shapes, drop "
                   "collinear points)";
        turning += std::atan2(winding * cross(e0, e1), dot(e0, e1));
    }
    // All corners turning one way is not enough: a star pentagon does too, but its
    // turning adds up to 4 pi, not 2 pi.
    if (std::abs(turning - 2.0 * std::numbers::pi) > 1e-6)
        return "polygon crosses itself (its edges wind " + fmt(turning / (2.0 * std::numbers::pi)) +
               " times around): list the vertices in order around the outline";
    return {};
}

std::string validateChain(std::span<const Vec2> p, bool loop) {
    const std::size_t need = loop ? 3 : 2;
    if (p.size() < need)
        return std::string(loop ? "terrain loop" : "terrain polyline") + " has " +
               std::to_string(p.size()) + " points; needs at least " + std::to_string(need);
    for (std::size_t i = 0; i < p.size(); ++i)
        if (!finite(p[i])) return "terrain point " + std::to_string(i) + " is not finite";
    const std::size_t edges = loop ? p.size() : p.size() - 1;
    for (std::size_t i = 0; i < edges; ++i) {
        const std::size_t j = (i + 1) % p.size();
        if (length(p[j] - p[i]) < b2_linearSlop)
            return "terrain points " + std::to_string(i) + " " + fmt(p[i]) + " and " +
                   std::to_string(j) + " " + fmt(p[j]) + " are closer than b2_linearSlop (" +
                   fmt(b2_linearSlop) + " m): merge them";
    }
    return {};
}

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

void RigidWorld::forEachShape(const std::function<void(const RigidShapeView&)>& fn) const {
    auto world = [](const b2Transform& xf, const b2Vec2& v) {
        const b2Vec2 w = b2Mul(xf, v);
        return Vec2{w.x, w.y};
    };
    for (std::uint32_t i = 0; i < bodies_.size(); ++i) {
        const b2Body* body = bodies_[i].body;
        if (!body) continue;
        RigidShapeView view;
        view.body = {i, bodies_[i].generation};
        view.type = body->GetType() == b2_staticBody      ? BodyType::Static
                    : body->GetType() == b2_kinematicBody ? BodyType::Kinematic
                                                          : BodyType::Dynamic;
        view.awake = body->IsAwake();
        view.angle = body->GetAngle();
        const b2Transform& xf = body->GetTransform();
        for (const b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) {
            const b2Shape* shape = f->GetShape();
            scratchVertices_.clear();
            view.loop = false;
            switch (shape->GetType()) {
            case b2Shape::e_circle: {
                const auto* c = static_cast<const b2CircleShape*>(shape);
                view.kind = RigidShapeView::Kind::Circle;
                view.center = world(xf, c->m_p);
                view.radius = c->m_radius;
                break;
            }
            case b2Shape::e_polygon: {
                const auto* p = static_cast<const b2PolygonShape*>(shape);
                view.kind = RigidShapeView::Kind::Polygon;
                for (int k = 0; k < p->m_count; ++k)
                    scratchVertices_.push_back(world(xf, p->m_vertices[k]));
                break;
            }
            case b2Shape::e_edge: {
                const auto* e = static_cast<const b2EdgeShape*>(shape);
                view.kind = RigidShapeView::Kind::Chain;
                scratchVertices_.push_back(world(xf, e->m_vertex1));
                scratchVertices_.push_back(world(xf, e->m_vertex2));
                break;
            }
            case b2Shape::e_chain: {
                const auto* c = static_cast<const b2ChainShape*>(shape);
                view.kind = RigidShapeView::Kind::Chain;
                // Box2D stores a loop with its first vertex repeated at the end.
                int count = c->m_count;
                if (count > 1 && c->m_vertices[0] == c->m_vertices[count - 1]) {
                    view.loop = true;
                    --count;
                }
                for (int k = 0; k < count; ++k)
                    scratchVertices_.push_back(world(xf, c->m_vertices[k]));
                break;
            }
            default:
                continue;
            }
            view.vertices = scratchVertices_;
            fn(view);
        }
    }
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

// ---- joints ----------------------------------------------------------------------------

b2Joint* RigidWorld::lookup(JointId id) const {
    if (id.index >= joints_.size()) return nullptr;
    const JointSlot& s = joints_[id.index];
    return s.generation == id.generation ? s.joint : nullptr;
}

bool RigidWorld::checkJointBodies(const JointBase& def, std::string* error) const {
    if (!lookup(def.a) || !lookup(def.b)) {
        setError(error, std::string("joint body ") + (lookup(def.a) ? "b" : "a") +
                            " is unknown or destroyed");
        return false;
    }
    if (def.a == def.b) {
        setError(error, "joint connects a body to itself: give two different bodies");
        return false;
    }
    if (!(def.breakForce > 0.0) || !(def.breakTorque > 0.0)) {
        setError(error, "joint breakForce " + fmt(def.breakForce) + " N / breakTorque " +
                            fmt(def.breakTorque) + " N m: must be > 0 (infinity = unbreakable)");
        return false;
    }
    return true;
}

JointId RigidWorld::finishJoint(b2Joint* joint, const JointBase& def) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    std::uint32_t index;
    if (!freeJoints_.empty()) {
        index = freeJoints_.back();
        freeJoints_.pop_back();
    } else {
        index = static_cast<std::uint32_t>(joints_.size());
        joints_.push_back({});
    }
    JointSlot& slot = joints_[index];
    slot.joint = joint;
    slot.breakForce = def.breakForce;
    slot.breakTorque = def.breakTorque;
    joint->GetUserData().pointer = static_cast<uintptr_t>(index) + 1;
    return {index, slot.generation};
}

void RigidWorld::freeJointSlot(std::uint32_t index) {
    JointSlot& slot = joints_[index];
    slot.joint = nullptr;
    ++slot.generation;
    freeJoints_.push_back(index);
}

JointId RigidWorld::createRevolute(const RevoluteJointDef& def, std::string* error) {
    if (!checkJointBodies(def, error)) return {};
    if (!finite(def.anchor)) {
        setError(error, "revolute anchor " + fmt(def.anchor) + ": must be finite");
        return {};
    }
    if (def.enableLimit && !(def.lowerAngle <= def.upperAngle)) {
        setError(error, "revolute lowerAngle " + fmt(def.lowerAngle) + " rad > upperAngle " +
                            fmt(def.upperAngle) + " rad");
        return {};
    }
    b2RevoluteJointDef jd;
    jd.Initialize(lookup(def.a), lookup(def.b), toB2(def.anchor));
    jd.collideConnected = def.collideConnected;
    jd.enableLimit = def.enableLimit;
    jd.lowerAngle = static_cast<float>(def.lowerAngle);
    jd.upperAngle = static_cast<float>(def.upperAngle);
    jd.enableMotor = def.enableMotor;
    jd.motorSpeed = static_cast<float>(def.motorSpeed);
    jd.maxMotorTorque = static_cast<float>(def.maxMotorTorque);
    return finishJoint(world_->CreateJoint(&jd), def);
}

JointId RigidWorld::createWeld(const WeldJointDef& def, std::string* error) {
    if (!checkJointBodies(def, error)) return {};
    if (!finite(def.anchor) || !(def.stiffness >= 0.0) || !(def.damping >= 0.0)) {
        setError(error, "weld anchor " + fmt(def.anchor) + " must be finite, stiffness " +
                            fmt(def.stiffness) + " and damping " + fmt(def.damping) +
                            " must be >= 0");
        return {};
    }
    b2WeldJointDef jd;
    jd.Initialize(lookup(def.a), lookup(def.b), toB2(def.anchor));
    jd.collideConnected = def.collideConnected;
    jd.stiffness = static_cast<float>(def.stiffness);
    jd.damping = static_cast<float>(def.damping);
    return finishJoint(world_->CreateJoint(&jd), def);
}

JointId RigidWorld::createDistance(const DistanceJointDef& def, std::string* error) {
    if (!checkJointBodies(def, error)) return {};
    if (!finite(def.anchorA) || !finite(def.anchorB)) {
        setError(error, "distance joint anchors must be finite");
        return {};
    }
    const double current = length(def.anchorB - def.anchorA);
    const double len = def.length < 0.0 ? current : def.length;
    const double lo = def.minLength < 0.0 ? len : def.minLength;
    const double hi = def.maxLength < 0.0 ? len : def.maxLength;
    if (!(lo <= len && len <= hi) || !(def.stiffness >= 0.0) || !(def.damping >= 0.0)) {
        setError(error, "distance joint needs minLength <= length <= maxLength (got " + fmt(lo) +
                            ", " + fmt(len) + ", " + fmt(hi) + " m) and stiffness, damping >= 0");
        return {};
    }
    b2DistanceJointDef jd;
    jd.Initialize(lookup(def.a), lookup(def.b), toB2(def.anchorA), toB2(def.anchorB));
    jd.collideConnected = def.collideConnected;
    jd.length = static_cast<float>(len);
    jd.minLength = static_cast<float>(lo);
    jd.maxLength = static_cast<float>(hi);
    jd.stiffness = static_cast<float>(def.stiffness);
    jd.damping = static_cast<float>(def.damping);
    return finishJoint(world_->CreateJoint(&jd), def);
}

JointId RigidWorld::createPrismatic(const PrismaticJointDef& def, std::string* error) {
    if (!checkJointBodies(def, error)) return {};
    const double axisLength = length(def.axis);
    if (!finite(def.anchor) || !(axisLength > 0.0) || !std::isfinite(axisLength)) {
        setError(error, "prismatic anchor " + fmt(def.anchor) + " must be finite and axis " +
                            fmt(def.axis) + " non-zero");
        return {};
    }
    if (def.enableLimit && !(def.lowerTranslation <= def.upperTranslation)) {
        setError(error, "prismatic lowerTranslation " + fmt(def.lowerTranslation) +
                            " m > upperTranslation " + fmt(def.upperTranslation) + " m");
        return {};
    }
    b2PrismaticJointDef jd;
    jd.Initialize(lookup(def.a), lookup(def.b), toB2(def.anchor), toB2(def.axis / axisLength));
    jd.collideConnected = def.collideConnected;
    jd.enableLimit = def.enableLimit;
    jd.lowerTranslation = static_cast<float>(def.lowerTranslation);
    jd.upperTranslation = static_cast<float>(def.upperTranslation);
    jd.enableMotor = def.enableMotor;
    jd.motorSpeed = static_cast<float>(def.motorSpeed);
    jd.maxMotorForce = static_cast<float>(def.maxMotorForce);
    return finishJoint(world_->CreateJoint(&jd), def);
}

void RigidWorld::destroyJoint(JointId id) {
    quiet_ = false; // may create, move or wake something: step Box2D again
    b2Joint* joint = lookup(id);
    if (!joint) return;
    world_->DestroyJoint(joint);
    freeJointSlot(id.index);
}

int RigidWorld::jointCount() const {
    return world_->GetJointCount();
}

Vec2 RigidWorld::jointReactionForce(JointId id) const {
    const b2Joint* joint = lookup(id);
    return joint ? fromB2(joint->GetReactionForce(static_cast<float>(lastInvSubstep_))) : Vec2{};
}

double RigidWorld::jointReactionTorque(JointId id) const {
    const b2Joint* joint = lookup(id);
    return joint ? joint->GetReactionTorque(static_cast<float>(lastInvSubstep_)) : 0.0;
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

// ---- queries ---------------------------------------------------------------------------

void RigidWorld::queryAABB(Vec2 lo, Vec2 hi, std::vector<BodyId>& out) const {
    out.clear();
    b2AABB box;
    box.lowerBound = toB2(Vec2{std::min(lo.x, hi.x), std::min(lo.y, hi.y)});
    box.upperBound = toB2(Vec2{std::max(lo.x, hi.x), std::max(lo.y, hi.y)});
    scratchBodies_.clear();
    CollectBodies collect(box, scratchBodies_);
    world_->QueryAABB(&collect, box);
    for (const b2Body* b : scratchBodies_)
        out.push_back(idOf(b));
    // The tree's order depends on its history; sort so callers see slot order.
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

std::optional<RigidRayHit> RigidWorld::rayCast(Vec2 from, Vec2 to) const {
    if (lengthSquared(to - from) <= 0.0) return std::nullopt;
    ClosestRay ray;
    world_->RayCast(&ray, toB2(from), toB2(to));
    if (!ray.body) return std::nullopt;
    return RigidRayHit{idOf(ray.body), fromB2(ray.hitPoint), fromB2(ray.hitNormal),
                       ray.hitFraction};
}

void RigidWorld::circleContacts(Vec2 center, double radius, std::vector<RigidCircleContact>& out,
                                double margin, BodyId ignore) const {
    out.clear();
    const double reach = radius + std::max(0.0, margin);
    std::vector<BodyId>& candidates = scratchIds_;
    queryAABB(center - Vec2{reach, reach}, center + Vec2{reach, reach}, candidates);
    // The probe is inflated by the margin; its separation and midpoint are corrected back.
    b2CircleShape probe;
    probe.m_radius = static_cast<float>(reach);
    b2Transform probeXf;
    probeXf.Set(toB2(center), 0.0f);
    const double extra = reach - radius;
    for (BodyId id : candidates) {
        if (id == ignore) continue;
        const b2Body* body = lookup(id);
        const b2Transform& xf = body->GetTransform();
        for (const b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) {
            const b2Shape* shape = f->GetShape();
            auto collect = [&](const b2Manifold& m, float shapeRadius) {
                if (m.pointCount == 0) return;
                b2WorldManifold wm;
                wm.Initialize(&m, xf, shapeRadius, probeXf, probe.m_radius);
                const Vec2 n = fromB2(wm.normal);
                out.push_back({id, fromB2(wm.points[0]) + n * (0.5 * extra), n,
                               static_cast<double>(wm.separations[0]) + extra, f->GetFriction(),
                               f->GetRestitution()});
            };
            b2Manifold m;
            switch (shape->GetType()) {
            case b2Shape::e_circle: {
                const auto* c = static_cast<const b2CircleShape*>(shape);
                b2CollideCircles(&m, c, xf, &probe, probeXf);
                collect(m, c->m_radius);
                break;
            }
            case b2Shape::e_polygon: {
                const auto* p = static_cast<const b2PolygonShape*>(shape);
                b2CollidePolygonAndCircle(&m, p, xf, &probe, probeXf);
                collect(m, p->m_radius);
                break;
            }
            case b2Shape::e_edge: {
                const auto* e = static_cast<const b2EdgeShape*>(shape);
                b2CollideEdgeAndCircle(&m, e, xf, &probe, probeXf);
                collect(m, e->m_radius);
                break;
            }
            case b2Shape::e_chain: {
                const auto* chain = static_cast<const b2ChainShape*>(shape);
                b2AABB box;
                box.lowerBound = toB2(center - Vec2{reach, reach});
                box.upperBound = toB2(center + Vec2{reach, reach});
                for (int32 c = 0; c < chain->GetChildCount(); ++c) {
                    b2AABB childBox;
                    chain->ComputeAABB(&childBox, xf, c);
                    if (!b2TestOverlap(childBox, box)) continue;
                    b2EdgeShape edge;
                    chain->GetChildEdge(&edge, c);
                    b2CollideEdgeAndCircle(&m, &edge, xf, &probe, probeXf);
                    collect(m, edge.m_radius);
                }
                break;
            }
            case b2Shape::e_typeCount:
                break;
            }
        }
    }
}

void RigidWorld::contacts(std::vector<RigidContactView>& out) const {
    out.clear();
    for (const b2Contact* c = world_->GetContactList(); c; c = c->GetNext()) {
        if (!c->IsTouching()) continue;
        const int n = c->GetManifold()->pointCount;
        if (n == 0) continue;
        b2WorldManifold wm;
        c->GetWorldManifold(&wm); // normal from fixture A to fixture B
        BodyId a = idOf(c->GetFixtureA()->GetBody()), b = idOf(c->GetFixtureB()->GetBody());
        Vec2 normal = fromB2(wm.normal);
        // Point into the body that moves: a ball on the ground gets a normal pointing up.
        if (c->GetFixtureB()->GetBody()->GetType() == b2_staticBody &&
            c->GetFixtureA()->GetBody()->GetType() != b2_staticBody) {
            std::swap(a, b);
            normal = -normal;
        }
        for (int k = 0; k < n; ++k)
            out.push_back({a, b, fromB2(wm.points[k]), normal,
                           static_cast<double>(wm.separations[k])});
    }
}

} // namespace phys
