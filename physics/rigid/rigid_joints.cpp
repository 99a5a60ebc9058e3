// RigidWorld's joints: revolute, weld, distance and prismatic, and breaking the overloaded.
#include "physics/rigid/rigid_world.h"

#include "physics/rigid/box2d_bridge.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

namespace phys {

using namespace box2d_bridge;

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


} // namespace phys
