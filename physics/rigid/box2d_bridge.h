// What the parts of the Box2D bridge (rigid_world.h: rigid_world.cpp, rigid_joints.cpp,
// rigid_queries.cpp, rigid_validate.cpp) share: the conversions between Box2D's floats and
// the project's doubles, and the wording of what is refused. Only those files include it.
#pragma once

#include "physics/rigid/rigid_types.h"
#include "physics/vec2.h"

#include <box2d/box2d.h>

#include <cmath>
#include <sstream>
#include <string>

namespace phys::box2d_bridge {

// ---- conversions ---------------------------------------------------------------------
// Box2D is float; the rest of the project is double. Converting only here keeps the
// rounding in one place.
inline b2Vec2 toB2(Vec2 v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y)};
}
inline Vec2 fromB2(const b2Vec2& v) {
    return {static_cast<double>(v.x), static_cast<double>(v.y)};
}

inline b2BodyType toB2(BodyType t) {
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

inline BodyType fromB2(b2BodyType t) {
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

inline bool finite(Vec2 v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

inline std::string fmt(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}
inline std::string fmt(Vec2 v) {
    // One stream, not string concatenation: GCC 12 warns falsely (-Wrestrict) on the latter.
    std::ostringstream s;
    s << '(' << v.x << ", " << v.y << ')';
    return s.str();
}

inline void setError(std::string* out, const std::string& what) {
    if (out) *out = what;
}

inline std::string validate(const RigidMaterial& m) {
    if (!(m.density >= 0.0) || !std::isfinite(m.density))
        return "material density " + fmt(m.density) + " kg/m^2: must be finite and >= 0";
    if (!(m.friction >= 0.0) || !std::isfinite(m.friction))
        return "material friction " + fmt(m.friction) + ": must be finite and >= 0";
    if (!(m.restitution >= 0.0 && m.restitution <= 1.0))
        return "material restitution " + fmt(m.restitution) + ": must be in 0..1";
    return {};
}

} // namespace phys::box2d_bridge
