// The HUD and the panels are laid out on a 1280x720 design canvas, scaled to the
// screen: a 4K window shows the same layout as a 720p one, three times larger.
#pragma once

#include <algorithm>
#include <cmath>

namespace ui {

/// Design pixels to screen pixels for the HUD the renderer draws (any size of window).
inline double hudScale(double width, double height) {
    return std::clamp(std::min(width / 1280.0, height / 720.0), 0.4, 3.0);
}

/// The same for the ImGui panels, in quarter steps (their font is rasterized anew when
/// it changes, not at every pixel of a resize) and never below 1: on a small window the
/// HUD shrinks, but a panel's text at less than its 16 px design size does not read.
inline float panelScale(double width, double height) {
    return static_cast<float>(std::floor(std::max(1.0, hudScale(width, height)) * 4.0) / 4.0);
}

} // namespace ui
