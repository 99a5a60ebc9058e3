// Charts to PNG headlessly: the same drawing code as the in-game panel, in an offscreen
// GL context (OSMesa, EGL fallback), with ImGui drawing the text labels.
#pragma once

#include "ui/charts/chart.h"
#include "ui/render/screenshot.h"

#include <functional>
#include <string>

namespace ui::charts {

/// Draws into a width x height picture through `draw` (given the renderer and the whole
/// picture as a rectangle), and returns it; "" in `error` on success.
Image renderChartImage(int width, int height, const std::function<void(Renderer2D&, Rect)>& draw,
                       std::string& error);

/// Same, written to `path` as PNG. Returns "" on success, else why not.
std::string renderChartPng(const std::string& path, int width, int height,
                           const std::function<void(Renderer2D&, Rect)>& draw);

} // namespace ui::charts
