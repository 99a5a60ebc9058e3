// RigidWorld's queries: its shapes for drawing, boxes, rays, and the circles the coupling asks about.
#include "physics/rigid/rigid_world.h"

#include "physics/rigid/box2d_bridge.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

namespace phys {

using namespace box2d_bridge;

namespace {

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
