#include "ui/render/camera.h"

#include <algorithm>

namespace ui {

Camera Camera::framing(phys::Vec2 lo, phys::Vec2 hi, int width, int height, double marginPx) {
    Camera c;
    c.width = width;
    c.height = height;
    c.center = (lo + hi) * 0.5;
    const double w = std::max(hi.x - lo.x, 1e-6);
    const double h = std::max(hi.y - lo.y, 1e-6);
    const double sx = (width - 2.0 * marginPx) / w;
    const double sy = (height - 2.0 * marginPx) / h;
    c.pixelsPerMetre = std::max(std::min(sx, sy), 1e-6);
    return c;
}

phys::Vec2 Camera::toPixel(phys::Vec2 world) const {
    return {(world.x - center.x) * pixelsPerMetre + 0.5 * width,
            0.5 * height - (world.y - center.y) * pixelsPerMetre};
}

phys::Vec2 Camera::toWorld(phys::Vec2 pixel) const {
    return {center.x + (pixel.x - 0.5 * width) / pixelsPerMetre,
            center.y + (0.5 * height - pixel.y) / pixelsPerMetre};
}

void Camera::zoomAt(phys::Vec2 pixel, double factor) {
    const phys::Vec2 anchor = toWorld(pixel);
    pixelsPerMetre = std::clamp(pixelsPerMetre * factor, 0.05, 5000.0);
    // Move the centre so that `anchor` maps back to `pixel`.
    center = center + (anchor - toWorld(pixel));
}

void Camera::panPixels(phys::Vec2 deltaPx) {
    center.x -= deltaPx.x / pixelsPerMetre;
    center.y += deltaPx.y / pixelsPerMetre;
}

std::array<float, 16> Camera::clipFromWorld() const {
    // x_clip = (x - cx) * 2 s / W, y_clip = (y - cy) * 2 s / H (y up in both spaces).
    const double sx = 2.0 * pixelsPerMetre / width;
    const double sy = 2.0 * pixelsPerMetre / height;
    std::array<float, 16> m{};
    m[0] = static_cast<float>(sx);
    m[5] = static_cast<float>(sy);
    m[10] = 1.0f;
    m[12] = static_cast<float>(-center.x * sx);
    m[13] = static_cast<float>(-center.y * sy);
    m[15] = 1.0f;
    return m;
}

} // namespace ui
