#include "physics/particles.h"

#include <cmath>

namespace phys {

namespace {
constexpr std::uint32_t kHistoryFlags = kVerletPrimed | kLeapfrogPrimed;
}

ParticleId ParticleSet::add(const ParticleDef& def) {
    ParticleId id;
    if (!freeSlots_.empty()) {
        id = freeSlots_.back();
        freeSlots_.pop_back();
    } else {
        id = static_cast<ParticleId>(px.size());
        for (auto* a : {&px, &py, &vx, &vy, &invMass, &radius, &dragCd, &prevX, &prevY, &halfVx,
                        &halfVy, &launchX, &launchY, &launchVx, &launchVy, &launchT})
            a->push_back(0.0);
        material.push_back(0);
        flags.push_back(0);
    }
    px[id] = def.position.x;
    py[id] = def.position.y;
    vx[id] = def.velocity.x;
    vy[id] = def.velocity.y;
    const bool fixed = !(def.mass > 0.0) || std::isinf(def.mass);
    invMass[id] = fixed ? 0.0 : 1.0 / def.mass;
    radius[id] = def.radius;
    dragCd[id] = def.dragCoefficient;
    material[id] = def.material;
    flags[id] = (def.flags | kAlive) & ~(kHistoryFlags | kBallistic); // the world picks the model
    prevX[id] = def.position.x;
    prevY[id] = def.position.y;
    halfVx[id] = def.velocity.x;
    halfVy[id] = def.velocity.y;
    return id;
}

void ParticleSet::remove(ParticleId id) {
    if (!alive(id)) return;
    flags[id] = 0;
    invMass[id] = 0.0;
    // Zero the whole state, so a slot removed for being non-finite holds no NaN that a
    // whole-array kernel could spread or a renderer could read.
    px[id] = py[id] = prevX[id] = prevY[id] = 0.0;
    vx[id] = vy[id] = 0.0;
    halfVx[id] = halfVy[id] = 0.0;
    radius[id] = 0.0;
    freeSlots_.push_back(id);
}

void ParticleSet::reserve(std::size_t n) {
    for (auto* a :
         {&px, &py, &vx, &vy, &invMass, &radius, &dragCd, &prevX, &prevY, &halfVx, &halfVy,
          &launchX, &launchY, &launchVx, &launchVy, &launchT})
        a->reserve(n);
    material.reserve(n);
    flags.reserve(n);
    freeSlots_.reserve(n);
}

void ParticleSet::clear() {
    for (auto* a :
         {&px, &py, &vx, &vy, &invMass, &radius, &dragCd, &prevX, &prevY, &halfVx, &halfVy,
          &launchX, &launchY, &launchVx, &launchVy, &launchT})
        a->clear();
    material.clear();
    flags.clear();
    freeSlots_.clear();
}

void ParticleSet::setPosition(ParticleId i, Vec2 p) {
    px[i] = p.x;
    py[i] = p.y;
    flags[i] &= ~(kHistoryFlags | kSleeping); // a moved particle must be simulated again
}

void ParticleSet::setVelocity(ParticleId i, Vec2 v) {
    vx[i] = v.x;
    vy[i] = v.y;
    flags[i] &= ~(kHistoryFlags | kSleeping); // a pushed particle wakes up
}

void ParticleSet::resetHistory() {
    for (auto& f : flags) f &= ~kHistoryFlags;
}

} // namespace phys
