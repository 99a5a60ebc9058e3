// The 2D camera: world metres (y up) to pixels (origin top-left, y down, as in
// screenshots, mouse coordinates and ImGui), and to GL clip space for the shader.
#pragma once

#include "physics/vec2.h"

#include <array>

namespace ui {

struct Camera {
    phys::Vec2 center{0.0, 0.0};  ///< world point at the middle of the viewport, m
    double pixelsPerMetre = 20.0; ///< zoom, px/m, > 0
    int width = 1280;             ///< viewport, px
    int height = 720;             ///< viewport, px

    /// A camera of the given viewport that shows the box [lo, hi] whole, centred, with
    /// `marginPx` pixels to spare on the tighter side.
    static Camera framing(phys::Vec2 lo, phys::Vec2 hi, int width, int height,
                          double marginPx = 0.0);

    /// Pixel coordinates of a world point (top-left origin; pixel centres at +0.5).
    phys::Vec2 toPixel(phys::Vec2 world) const;
    /// World point under a pixel coordinate.
    phys::Vec2 toWorld(phys::Vec2 pixel) const;
    /// The visible world rectangle.
    phys::Vec2 visibleMin() const { return toWorld({0.0, static_cast<double>(height)}); }
    phys::Vec2 visibleMax() const { return toWorld({static_cast<double>(width), 0.0}); }
    /// World length of `px` pixels at this zoom.
    double metres(double px) const { return px / pixelsPerMetre; }

    /// Zooms by `factor` keeping the world point under `pixel` where it is (mouse wheel).
    void zoomAt(phys::Vec2 pixel, double factor);
    /// Moves the view by a mouse drag of `deltaPx` (the world follows the mouse).
    void panPixels(phys::Vec2 deltaPx);

    /// World -> clip space, column-major 4x4 for glUniformMatrix4fv.
    std::array<float, 16> clipFromWorld() const;
};

} // namespace ui
