// The debug-draw interface: how physics describes what to draw without knowing how
// (docs/architecture.md, "Layers"; the idea is Box2D's b2Draw). ui/ implements it with OpenGL; a
// test can implement it with a recorder. Everything is in world units (m, y up) except
// where a size says pixels, so a shape drawn here lands on the same spot at any zoom.
//
// Pure C++: no GL, no ImGui, no allocation required of callers.
#pragma once

#include "physics/vec2.h"

#include <cstdint>
#include <span>
#include <string_view>

namespace phys {

/// A colour, linear 0..1 per channel, straight (not premultiplied) alpha.
struct Color {
    float r = 1.0f;
    float g = 1.0f;
    float b = 1.0f;
    float a = 1.0f;

    constexpr Color() = default;
    constexpr Color(float r_, float g_, float b_, float a_ = 1.0f) : r(r_), g(g_), b(b_), a(a_) {}
    /// From 0xRRGGBB, opaque.
    static constexpr Color hex(std::uint32_t rgb, float alpha = 1.0f) {
        return {static_cast<float>((rgb >> 16) & 0xff) / 255.0f,
                static_cast<float>((rgb >> 8) & 0xff) / 255.0f,
                static_cast<float>(rgb & 0xff) / 255.0f, alpha};
    }
    constexpr Color withAlpha(float alpha) const { return {r, g, b, alpha}; }
    constexpr bool operator==(const Color&) const = default;
};

class DebugDraw {
  public:
    virtual ~DebugDraw() = default;

    /// A line segment from a to b.
    virtual void segment(Vec2 a, Vec2 b, Color color) = 0;
    /// A circle outline.
    virtual void circle(Vec2 center, double radius, Color color) = 0;
    /// A filled circle with a darker rim; `axis` (unit vector, or zero for none) marks
    /// the body's orientation with a radius line, as b2Draw does for rotating bodies.
    virtual void solidCircle(Vec2 center, double radius, Vec2 axis, Color color) = 0;
    /// A closed polygon outline (vertices counter-clockwise).
    virtual void polygon(std::span<const Vec2> vertices, Color color) = 0;
    /// A filled convex polygon with a darker rim (vertices counter-clockwise).
    virtual void solidPolygon(std::span<const Vec2> vertices, Color color) = 0;
    /// A dot of a fixed size on screen, whatever the zoom.
    virtual void point(Vec2 p, float sizePixels, Color color) = 0;
    /// A text label whose top-left corner is at p.
    virtual void text(Vec2 p, std::string_view text, Color color) = 0;
};

} // namespace phys
