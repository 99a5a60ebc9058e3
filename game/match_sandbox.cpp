// The sandbox's verbs: spawn things where the player points, grab and drag them. Like
// every change to the world they are commands at a tick, so a sandbox session replays
// to the last bit like a match.
#include "game/match.h"

#include "physics/projectiles.h"

#include <algorithm>
#include <cmath>

namespace game {

using namespace phys;

namespace {

/// The sandbox stops spawning past this many particles or blocks (a frame stays fast).
constexpr std::size_t kMaxSandboxParticles = 20'000;
constexpr std::size_t kMaxSandboxBlocks = 400;
/// The hand: a spring of angular frequency w, damped at zeta (a particle settles on the
/// pointer in about 1/(zeta w) = 0.1 s and sags g / w^2 = 7 cm under its weight).
constexpr double kHandOmega = 12.0;  // rad/s
constexpr double kHandZeta = 0.8;
/// How far from a particle's surface a grab still takes it, m.
constexpr double kGrabReach = 1.0;

bool insideBox(Vec2 local, Vec2 size) {
    return std::abs(local.x) <= 0.5 * size.x + 0.05 && std::abs(local.y) <= 0.5 * size.y + 0.05;
}

/// `p`, or where it lies under the ground, straight above it at `clearance` over the
/// ground's surface. The ground is a surface, not a solid: a body made under it falls
/// away under the world, so a click on the ground puts what it spawns on the ground.
Vec2 onOrAboveGround(const Heightfield& ground, Vec2 p, double clearance) {
    return {p.x, std::max(p.y, ground.heightAt(p.x) + clearance)};
}

} // namespace

std::string Match::spawn(const Command& cmd) {
    auto inside = [&](Vec2 p) {
        return p.x >= level_.worldMin.x && p.x <= level_.worldMax.x && p.y >= level_.worldMin.y &&
               p.y <= level_.worldMax.y;
    };
    if (!inside(cmd.at)) return "spawn point is outside the world";
    if (world_.particles.count() >= kMaxSandboxParticles)
        return "the sandbox is full (" + std::to_string(kMaxSandboxParticles) + " particles)";
    const double size = cmd.number;
    const std::string& what = cmd.text;
    Vec2 at = onOrAboveGround(terrain_, cmd.at, 0.0);

    if (what == "block") {
        if (blocks_.size() >= kMaxSandboxBlocks)
            return "the sandbox is full (" + std::to_string(kMaxSandboxBlocks) + " blocks)";
        Block b;
        b.size = Vec2{1.0, 1.0} * (size > 0.0 ? size : 1.0);
        b.position = onOrAboveGround(terrain_, at, 0.5 * b.size.y);
        addBlock(b);
    } else if (what == "rope" || what == "spring") {
        if (!inside(cmd.to)) return "the other end is outside the world";
        if (what == "rope") {
            // Pinned at `at`, free at `to`, or tied to a block that `to` lies in.
            Rope r;
            r.from = at;
            r.to = onOrAboveGround(terrain_, cmd.to, 0.0);
            r.segments = std::clamp(static_cast<int>(std::lround(length(r.to - r.from) / 0.5)), 2, 100);
            r.pinTo = false;
            r.massPerSegment = 2.0; // a 600 kg block stays within 1000 times a link's mass
            for (std::size_t i = 0; i < blocks_.size(); ++i)
                if (rigid_->alive(blocks_[i].body) &&
                    insideBox(rigid_->localPoint(blocks_[i].body, r.to), blocks_[i].def.size))
                    r.toBlock = static_cast<int>(i);
            addRope(r);
        } else {
            // A tennis ball hanging on a spring from the anchor at `at` (period ~1 s).
            const ProjectilePreset ball = projectileFromName("tennis-ball").value();
            const Vec2 hung = onOrAboveGround(terrain_, cmd.to, 0.5 * ball.diameter);
            ParticleDef pd = particleDef(ball, hung, {});
            pd.material = projectileMaterial(world_.materials, ball);
            const ParticleId id = world_.particles.add(pd);
            Spring s;
            s.a = id;
            s.anchor = at;
            s.restLength = length(hung - at);
            const double m = 1.0 / world_.particles.invMass[id];
            s.stiffness = m * 6.0 * 6.0;
            s.damping = 2.0 * 0.02 * m * 6.0;
            world_.springs.push_back(s);
        }
    } else if (what == "cloth") {
        // Hung from its top row at `at`: its bottom row over the ground at both ends.
        const double side = size > 0.0 ? size : 4.0;
        const double under = std::max(terrain_.heightAt(at.x), terrain_.heightAt(at.x + side));
        at.y = std::max(at.y, under + side + 0.1);
        addCloth(at, side);
    } else if (what == "blob") {
        Blob b;
        b.radius = size > 0.0 ? 0.5 * size : 1.0;
        b.center = onOrAboveGround(terrain_, at, b.radius + 0.1);
        addBlob(b);
    } else if (const auto preset = projectileFromName(what)) {
        at = onOrAboveGround(terrain_, at, 0.5 * preset->diameter);
        ParticleDef pd = particleDef(*preset, at, {});
        pd.material = projectileMaterial(world_.materials, *preset);
        world_.particles.add(pd);
    } else {
        return "cannot spawn \"" + what + "\"";
    }
    world_.wakeAll(); // whatever it lands on must notice
    return "";
}

void Match::addCloth(Vec2 topLeft, double size) {
    // A square of n x n particles with structural (grid) and shear (diagonal) springs,
    // hung from its top row. k and m keep w dt = sqrt(k/m) dt under 1 at 1/60 s.
    constexpr int n = 10;
    const double spacing = size / (n - 1);
    ClothState cloth;
    cloth.columns = n;
    cloth.spacing = spacing;
    std::vector<ParticleId>& ids = cloth.particles;
    for (int row = 0; row < n; ++row)
        for (int col = 0; col < n; ++col) {
            ParticleDef pd;
            pd.position = topLeft + Vec2{col * spacing, -row * spacing};
            pd.mass = row == 0 ? 0.0 : 0.05;
            pd.radius = std::min(0.08, 0.3 * spacing);
            pd.material = material::kTennis;
            ids.push_back(world_.particles.add(pd));
        }
    auto spring = [&](int r0, int c0, int r1, int c1) {
        Spring s;
        s.a = ids[static_cast<std::size_t>(r0 * n + c0)];
        s.b = ids[static_cast<std::size_t>(r1 * n + c1)];
        s.restLength = length(world_.particles.position(s.a) - world_.particles.position(s.b));
        s.stiffness = 100.0;
        s.damping = 0.05;
        world_.springs.push_back(s);
    };
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            if (c + 1 < n) spring(r, c, r, c + 1);
            if (r + 1 < n) spring(r, c, r + 1, c);
            if (r + 1 < n && c + 1 < n) {
                spring(r, c, r + 1, c + 1);
                spring(r, c + 1, r + 1, c);
            }
        }
    cloths_.push_back(std::move(cloth));
}

std::string Match::grabAt(Vec2 at) {
    if (grab_.kind != GrabState::Kind::None) release();
    // A block under the pointer first, then the nearest particle within reach.
    for (const BlockState& b : blocks_) {
        if (!rigid_->alive(b.body)) continue;
        const Vec2 local = rigid_->localPoint(b.body, at);
        if (!insideBox(local, b.def.size)) continue;
        grab_ = {};
        grab_.kind = GrabState::Kind::Body;
        grab_.body = b.body;
        grab_.local = local;
        grab_.target = at;
        return "";
    }
    const ParticleSet& set = world_.particles;
    ParticleId best = kNoParticle;
    double bestGap = kGrabReach;
    for (std::size_t i = 0; i < set.slots(); ++i) {
        if (!(set.flags[i] & kAlive) || !(set.invMass[i] > 0.0)) continue;
        const auto id = static_cast<ParticleId>(i);
        const double gap = length(set.position(id) - at) - set.radius[i];
        if (gap < bestGap) {
            bestGap = gap;
            best = id;
        }
    }
    if (best == kNoParticle) return "nothing to grab within " + std::to_string(kGrabReach) + " m";
    const double m = 1.0 / set.invMass[best];
    Spring hand;
    hand.a = best;
    hand.anchor = at;
    hand.restLength = 0.0;
    hand.stiffness = m * kHandOmega * kHandOmega;
    hand.damping = 0.0; // damped in every direction by pullGrabbed(), not only along it
    grab_ = {};
    grab_.kind = GrabState::Kind::Particle;
    grab_.particle = best;
    grab_.target = at;
    grab_.spring = world_.springs.size();
    world_.springs.push_back(hand);
    world_.particles.flags[best] &= ~kSleeping;
    return "";
}

void Match::dragTo(Vec2 at) {
    grab_.target = at;
    if (grab_.kind == GrabState::Kind::Particle) {
        world_.springs[grab_.spring].anchor = at;
        world_.particles.flags[grab_.particle] &= ~kSleeping;
    }
}

void Match::release() {
    // The hand's spring stops acting; it stays in the list so no other index moves.
    if (grab_.kind == GrabState::Kind::Particle) world_.springs[grab_.spring].broken = true;
    grab_ = {};
}

void Match::pullGrabbed() {
    if (grab_.kind == GrabState::Kind::Particle) {
        // A spring's damper acts along it only; a hand of zero length would let the
        // particle circle it undamped. Damp the whole velocity instead, exactly:
        // v *= exp(-2 zeta w dt) (what dv/dt = -2 zeta w v gives over one tick).
        ParticleSet& set = world_.particles;
        const ParticleId id = grab_.particle;
        if (!set.alive(id)) {
            release();
            return;
        }
        const double k = std::exp(-2.0 * kHandZeta * kHandOmega * world_.def().tickSeconds);
        set.setVelocity(id, set.velocity(id) * k);
        set.flags[id] &= ~(kVerletPrimed | kLeapfrogPrimed); // the history no longer fits
        return;
    }
    if (grab_.kind != GrabState::Kind::Body) return;
    if (!rigid_->alive(grab_.body)) {
        grab_ = {};
        return;
    }
    // F = m (w^2 (target - p) - 2 zeta w v(p)) - m g: a damped spring to the hand that
    // also carries the block's weight, applied at the grabbed point (so it swings).
    const RigidBodyState s = rigid_->state(grab_.body);
    const Vec2 p = rigid_->worldPoint(grab_.body, grab_.local);
    const Vec2 v = rigid_->velocityAt(grab_.body, p);
    const Vec2 f = ((grab_.target - p) * (kHandOmega * kHandOmega) - v * (2.0 * kHandZeta * kHandOmega) -
                    rigid_->def().gravity) *
                   s.mass;
    rigid_->applyForce(grab_.body, f, p);
}

} // namespace game
