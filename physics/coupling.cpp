#include "physics/coupling.h"

#include "physics/world.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace phys {

void ParticleBodyCoupling::prepare(World& world, RigidWorld& rigid) {
    ParticleSet& set = world.particles;
    settle(world, rigid); // two prepares without an exchange between: pay the first
    // A body pressing k spring-held particles lends each a k-th of its effective mass.
    std::vector<std::pair<BodyId, int>> shares;
    for (const ContactRow& row : contacts_)
        if (row.springHeld && row.lambda > 0.0) {
            auto it = std::find_if(shares.begin(), shares.end(), [&](const auto& s) { return s.first == row.body; });
            if (it == shares.end()) shares.emplace_back(row.body, 1);
            else ++it->second;
        }
    for (const ContactRow& row : contacts_) {
        if (!row.springHeld || !(row.lambda > 0.0) || row.particle >= set.slots()) continue;
        const ParticleId id = row.particle;
        if (!(set.flags[id] & kAlive) || !(set.invMass[id] > 0.0)) continue;
        const double wb = rigid.inverseEffectiveMass(row.body, row.point, row.normal);
        if (!(wb > 0.0)) continue;
        const int k = std::find_if(shares.begin(), shares.end(), [&](const auto& s) { return s.first == row.body; })->second;
        const double extra = 1.0 / (wb * k);
        Carried* c = nullptr;
        for (Carried& x : carried_)
            if (x.particle == id) c = &x;
        if (!c) {
            c = &carried_.emplace_back();
            c->particle = id;
            c->invMass = set.invMass[id];
            c->velocity = set.velocity(id);
        }
        c->rows.push_back({row.body, row.point, extra});
        set.invMass[id] = 1.0 / (1.0 / set.invMass[id] + extra);
    }
}

void ParticleBodyCoupling::settle(World& world, RigidWorld& rigid) {
    ParticleSet& set = world.particles;
    const double dt = world.def().tickSeconds;
    for (const Carried& c : carried_) {
        const ParticleId id = c.particle;
        set.invMass[id] = c.invMass;
        if (!(set.flags[id] & kAlive)) continue;
        // The tick moved particle and load together by dv: gravity's part each had
        // already; the rest is the forces' impulse, of which the body's share is its own.
        Vec2 dv = set.velocity(id) - c.velocity;
        if (!(set.flags[id] & kNoGravity)) dv -= world.def().forces.gravity * dt;
        for (const auto& r : c.rows) {
            const Vec2 asked = dv * r.mass;
            const Vec2 delivered = rigid.applyImpulse(r.body, asked, r.point);
            set.setVelocity(id, set.velocity(id) + (asked - delivered) * c.invMass);
        }
    }
    carried_.clear();
}

// Would moving the particle `depth` along `push` (out of a body) press it onto a static
// shape, or through one? Onto: it touches the shape (within a twentieth of its radius)
// and the push has it against the shape's normal by more than about 80 degrees from
// sliding along it; through: the moved particle would overlap the shape, or its centre
// would cross it (a segment has two sides).
bool ParticleBodyCoupling::grounded(const World& world, ParticleId particle, Vec2 push,
                                    double depth) const {
    const StaticShapes& shapes = world.shapes;
    const Vec2 p = world.particles.position(particle), q = p + push * depth;
    const double r = world.particles.radius[particle], reach = 1.05 * r + depth;
    const Aabb box{p - Vec2{reach, reach}, p + Vec2{reach, reach}};
    for (std::size_t k = 0; k < shapes.count(); ++k) {
        const ShapeRef ref = shapes.ref(k);
        if (!shapes.bounds(ref).overlaps(box)) continue;
        const SurfacePoint at = shapes.closestPoint(ref, p), moved = shapes.closestPoint(ref, q);
        if (dot(push, at.normal) >= -0.2) continue; // along or away from the shape
        if (at.distance < 1.05 * r || moved.distance < r || dot(at.normal, moved.normal) < 0.0)
            return true;
    }
    return false;
}

bool ParticleBodyCoupling::tiedTo(ParticleId particle, BodyId body) const {
    // A rope's end inside the crate it holds does not collide with it (Box2D's
    // collideConnected = false for joints).
    return std::any_of(joints_.begin(), joints_.end(), [&](const ParticleBodyJoint& j) {
        return j.particle == particle && j.body == body;
    });
}

std::size_t ParticleBodyCoupling::attach(ParticleId particle, BodyId body, Vec2 worldPoint,
                                         const RigidWorld& rigid) {
    joints_.push_back({particle, body, rigid.localPoint(body, worldPoint)});
    return joints_.size() - 1;
}

void ParticleBodyCoupling::detachBody(BodyId body) {
    std::erase_if(joints_, [&](const ParticleBodyJoint& j) { return j.body == body; });
}

void ParticleBodyCoupling::detachParticle(ParticleId particle) {
    std::erase_if(joints_, [&](const ParticleBodyJoint& j) { return j.particle == particle; });
}

CouplingStats ParticleBodyCoupling::exchange(World& world, RigidWorld& rigid) {
    const double dt = world.def().tickSeconds;
    settle(world, rigid);
    CouplingStats stats;
    events_.clear();
    contacts_.clear();
    jointRows_.clear();
    const bool tethers = markLinked(world);
    Links links;
    gatherContacts(world, rigid, tethers, links, stats);
    gatherJoints(world, rigid, tethers, links);
    stats.joints = static_cast<int>(jointRows_.size());
    // A body carried or held by tethered particles takes this tick's gravity before the
    // exchange and gives it back after: the exchange then balances its weight this tick,
    // instead of one tick late once Box2D has moved it g dt^2 into its support.
    kicked_.clear();
    if (links.any) lendGravity(rigid, dt);
    stats.passes = exchangeImpulses(world, rigid, links);
    for (const auto& [body, g] : kicked_) {
        const RigidBodyState st = rigid.state(body);
        rigid.setVelocity(body, st.linearVelocity - g, st.angularVelocity);
    }
    for (const ContactRow& row : contacts_)
        if (row.event != ContactRow::kNoEvent) {
            ++stats.impulses;
            stats.impulseSum += length(events_[row.event].impulse);
        }
    return stats;
}

// Particles held by rods, cables or springs (linked_: 1 rods or cables, 2 springs only);
// whether any spring, rod or cable exists.
bool ParticleBodyCoupling::markLinked(const World& world) {
    const ParticleSet& set = world.particles;
    const bool tethers = !world.constraints.empty() || !world.springs.empty();
    if (!tethers) return false;
    linked_.assign(set.slots(), 0);
    for (const Spring& sp : world.springs)
        if (!sp.broken)
            for (const ParticleId id : {sp.a, sp.b})
                if (id < set.slots()) linked_[id] = 2;
    for (const DistanceConstraint& c : world.constraints)
        for (const ParticleId id : {c.a, c.b})
            if (id < set.slots()) linked_[id] = 1;
    return true;
}

// The contacts of every free, awake particle with the bodies; free particles are moved
// out of the body at once.
void ParticleBodyCoupling::gatherContacts(World& world, RigidWorld& rigid, bool tethers,
                                          Links& links, CouplingStats& stats) {
    const ParticleSet& set = world.particles;
    for (std::size_t i = 0; i < set.slots(); ++i) {
        const std::uint32_t flags = set.flags[i];
        if (!(flags & kAlive) || (flags & (kNoCollide | kSleeping)) || set.invMass[i] <= 0.0)
            continue;
        const auto id = static_cast<ParticleId>(i);
        rigid.circleContacts(set.position(id), set.radius[i], found_);
        for (const RigidCircleContact& c : found_) {
            if (c.separation > 0.0 || tiedTo(id, c.body) ||
                std::find(mirrors_.begin(), mirrors_.end(), c.body) != mirrors_.end())
                continue;
            ++stats.contacts;
            addContactRow(world, rigid, id, c, tethers, links);
        }
    }
}

void ParticleBodyCoupling::addContactRow(World& world, const RigidWorld& rigid, ParticleId id,
                                         const RigidCircleContact& c, bool tethers, Links& links) {
    ParticleSet& set = world.particles;
    const double dt = world.def().tickSeconds;
    const std::size_t i = id;
    const Vec2 n = c.normal;
    const double wb = rigid.inverseEffectiveMass(c.body, c.point, n);
    const bool linked = tethers && linked_[i] && wb > 0.0;
    const bool byRods = linked && linked_[i] == 1;
    links.any = links.any || linked;
    links.rods = links.rods || byRods;
    double bias = 0.0;
    // On (or pushed into) the ground: not moved by position; a free particle is immovable
    // there, one on springs keeps its mass (lumped with its springs).
    const bool onGround = !byRods && grounded(world, id, n, std::max(-c.separation, 0.0));
    if (byRods || onGround) {
        bias = def_.baumgarte * std::max(-c.separation - def_.slop, 0.0) / dt;
    } else {
        set.px[i] -= c.separation * n.x;
        set.py[i] -= c.separation * n.y;
    }
    const double wp = onGround && !linked ? 0.0 : set.invMass[i];
    const Material& pm = world.materials[set.material[i]];
    ContactRow& row = contacts_.emplace_back();
    row.particle = id;
    row.body = c.body;
    row.point = c.point;
    row.normal = n;
    row.restitution = pm.restitution * c.restitution;
    row.friction = std::sqrt(pm.dynamicFriction * c.friction);
    row.wp = wp;
    row.wn = wp + wb;
    row.bias = bias;
    row.linked = linked;
    row.springHeld = linked && !byRods;
}

// The particles joined to dynamic bodies, each a row driving its anchor together.
void ParticleBodyCoupling::gatherJoints(World& world, RigidWorld& rigid, bool tethers,
                                        Links& links) {
    ParticleSet& set = world.particles;
    const double dt = world.def().tickSeconds;
    for (const ParticleBodyJoint& j : joints_) {
        if (j.particle >= set.slots() || !(set.flags[j.particle] & kAlive)) continue;
        if (rigid.state(j.body).type != BodyType::Dynamic) continue;
        const Vec2 point = rigid.worldPoint(j.body, j.localAnchor);
        const Vec2 C = set.position(j.particle) - point;
        JointRow& row = jointRows_.emplace_back();
        row.particle = j.particle;
        row.body = j.body;
        row.point = point;
        row.target = C * (-def_.baumgarte / dt);
        set.flags[j.particle] &= ~kSleeping;
        if (tethers && linked_[j.particle]) links.any = true;
        if (tethers && linked_[j.particle] == 1) links.rods = true;
    }
}

void ParticleBodyCoupling::lendGravity(RigidWorld& rigid, double dt) {
    auto kick = [&](BodyId body) {
        for (const auto& [b, v] : kicked_)
            if (b == body) return;
        const Vec2 g = rigid.gravityKick(body, dt);
        const RigidBodyState st = rigid.state(body);
        rigid.setVelocity(body, st.linearVelocity + g, st.angularVelocity);
        kicked_.emplace_back(body, g);
    };
    for (const ContactRow& row : contacts_)
        if (row.linked) kick(row.body);
    for (const JointRow& row : jointRows_)
        kick(row.body);
}

// Passes of contacts and joints, and the rods between them while links exist, until the
// rods hardly change what the contacts left; the passes taken.
int ParticleBodyCoupling::exchangeImpulses(World& world, RigidWorld& rigid, const Links& links) {
    ParticleSet& set = world.particles;
    const int passes = links.any ? std::max(def_.iterations, 1) : 1;
    int pass = 0;
    while (pass < passes) {
        contactPass(set, rigid, pass == 0);
        jointPass(set, rigid);
        ++pass;
        if (links.rods && rodPass(world, rigid) < def_.tolerance) break; // converged
    }
    if (links.any) { // end on the contacts: no body is left approaching a link
        contactPass(set, rigid, false);
        jointPass(set, rigid);
    }
    return pass;
}

void ParticleBodyCoupling::contactPass(ParticleSet& set, RigidWorld& rigid, bool first) {
    for (ContactRow& row : contacts_) {
        const ParticleId id = row.particle;
        const double wp = row.wp;
        const Vec2 n = row.normal;
        const Vec2 u = set.velocity(id) - rigid.velocityAt(row.body, row.point);
        const double un = dot(u, n);
        // Normal: the first pass is the textbook bounce j = -(1 + e) u_n / w; later
        // passes drive u_n to the same target with the accumulated impulse kept >= 0.
        double dl;
        if (first) {
            row.bounce = un < 0.0 ? -row.restitution * un : 0.0;
            dl = row.bias > row.bounce ? (row.bias - un) / row.wn : -(1.0 + row.restitution) * un / row.wn;
        } else {
            dl = (std::max(row.bounce, row.bias) - un) / row.wn;
        }
        const double lambda = std::max(row.lambda + dl, 0.0);
        dl = lambda - row.lambda;
        row.lambda = lambda;
        // Friction: Coulomb, the accumulated tangential impulse within mu lambda.
        Vec2 tangential;
        const Vec2 ut = u - n * un;
        const double slip = length(ut);
        if (lambda > 0.0 && slip > 0.0) {
            const Vec2 t = ut / slip;
            const double wt = wp + rigid.inverseEffectiveMass(row.body, row.point, t);
            const double cap = row.friction * lambda;
            if (row.tangential == Vec2{}) {
                tangential = t * std::max(-slip / wt, -cap);
            } else {
                tangential = row.tangential + t * (-slip / wt);
                const double len = length(tangential);
                if (len > cap) tangential = tangential * (cap / len);
            }
        }
        const Vec2 J = n * dl + (tangential - row.tangential);
        row.tangential = tangential;
        if (J == Vec2{}) continue;
        // The body gets -J (it pushes back on the particle with +J); the particle gets
        // minus what the body actually received.
        const Vec2 delivered = rigid.applyImpulse(row.body, -J, row.point);
        const Vec2 dv = delivered * -wp;
        set.setVelocity(id, set.velocity(id) + dv);
        if (row.event == ContactRow::kNoEvent && dl > 0.0) {
            row.event = events_.size();
            events_.push_back({id, row.body, row.point, n, -un, -delivered});
        } else if (row.event != ContactRow::kNoEvent) {
            events_[row.event].impulse -= delivered;
        }
    }
}

void ParticleBodyCoupling::jointPass(ParticleSet& set, RigidWorld& rigid) {
    for (JointRow& row : jointRows_) {
        const ParticleId id = row.particle;
        const double wp = set.invMass[id];
        const RigidBodyState s = rigid.state(row.body);
        const double invM = s.mass > 0.0 ? 1.0 / s.mass : 0.0;
        const double invI = s.inertia > 0.0 ? 1.0 / s.inertia : 0.0;
        const Vec2 r = row.point - s.centerOfMass;
        // K = (w_p + 1/m) I + [r_y^2, -r_x r_y; -r_x r_y, r_x^2] / I
        const double kxx = wp + invM + r.y * r.y * invI;
        const double kyy = wp + invM + r.x * r.x * invI;
        const double kxy = -r.x * r.y * invI;
        const double det = kxx * kyy - kxy * kxy;
        if (!(det > 0.0)) continue;
        const Vec2 rhs = row.target - (set.velocity(id) - rigid.velocityAt(row.body, row.point));
        const Vec2 P{(kyy * rhs.x - kxy * rhs.y) / det, (kxx * rhs.y - kxy * rhs.x) / det};
        const Vec2 delivered = rigid.applyImpulse(row.body, -P, row.point);
        set.setVelocity(id, set.velocity(id) - delivered * wp);
    }
}

double ParticleBodyCoupling::rodPass(World& world, RigidWorld& rigid) {
    ParticleSet& set = world.particles;
    // Mass splitting: a body pressed by k links lends each a k-th of its effective mass.
    std::vector<std::pair<BodyId, int>> shares;
    auto share = [&](BodyId body) -> int& {
        for (auto& [b, k] : shares)
            if (b == body) return k;
        shares.emplace_back(body, 0);
        return shares.back().second;
    };
    auto byRods = [&](ParticleId id) { return linked_[id] == 1; };
    for (const ContactRow& row : contacts_)
        if (row.linked && byRods(row.particle) && row.lambda > 0.0) ++share(row.body);
    for (const JointRow& row : jointRows_)
        if (byRods(row.particle)) ++share(row.body);

    lumped_.clear();
    lumpedMass_.resize(set.slots());
    savedInvMass_.resize(set.slots());
    savedVelocity_.resize(set.slots());
    auto lump = [&](ParticleId id, BodyId body, double wb) {
        if (!(set.invMass[id] > 0.0)) return 0.0; // a pinned end needs no help from the body
        const double extra = wb > 0.0 ? 1.0 / (wb * share(body)) : 0.0;
        if (std::find(lumped_.begin(), lumped_.end(), id) == lumped_.end()) {
            lumped_.push_back(id);
            lumpedMass_[id] = 1.0 / set.invMass[id];
            savedInvMass_[id] = set.invMass[id];
            savedVelocity_[id] = set.velocity(id);
        }
        lumpedMass_[id] += extra;
        return extra;
    };
    for (ContactRow& row : contacts_)
        row.lumpMass = row.linked && byRods(row.particle) && row.lambda > 0.0
                           ? lump(row.particle, row.body,
                                  rigid.inverseEffectiveMass(row.body, row.point, row.normal))
                           : 0.0;
    for (JointRow& row : jointRows_) {
        const double wb = 0.5 * (rigid.inverseEffectiveMass(row.body, row.point, {1.0, 0.0}) +
                                 rigid.inverseEffectiveMass(row.body, row.point, {0.0, 1.0}));
        row.lumpMass = byRods(row.particle) ? lump(row.particle, row.body, wb) : 0.0;
    }
    for (const ParticleId id : lumped_) set.invMass[id] = 1.0 / lumpedMass_[id];
    solveConstraints(world.constraints, set, rodScratch_, 0);
    for (const ParticleId id : lumped_) set.invMass[id] = savedInvMass_[id];

    // The rods moved each lumped particle (and its share of body) by dv: the body gets
    // its share's impulse, the particle what the body did not take (float rounding).
    double largest = 0.0;
    for (const ParticleId id : lumped_) {
        savedVelocity_[id] = set.velocity(id) - savedVelocity_[id];
        largest = std::max(largest, length(savedVelocity_[id]));
    }
    auto pass = [&](ParticleId id, BodyId body, Vec2 point, double lumpMass) {
        if (lumpMass <= 0.0) return;
        const Vec2 dv = savedVelocity_[id];
        const Vec2 asked = dv * lumpMass;
        const Vec2 delivered = rigid.applyImpulse(body, asked, point);
        set.setVelocity(id, set.velocity(id) + (asked - delivered) * set.invMass[id]);
    };
    for (const ContactRow& row : contacts_) pass(row.particle, row.body, row.point, row.lumpMass);
    for (const JointRow& row : jointRows_) pass(row.particle, row.body, row.point, row.lumpMass);
    return largest;
}

} // namespace phys
