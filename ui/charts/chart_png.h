// Charts to PNG headlessly: the same drawing code as the in-game panel, in an offscreen
// GL context (OSMesa, EGL fallback), with ImGui drawing the text labels.
#pragma once

#include "ui/charts/chart.h"
#include "ui/render/screenshot.h"

#include <functional>
#include <string>

namespace ui::charts {

/// Draws into a width x height picture cleared to `background` through `draw` (given the
/// renderer and the whole picture as a rectangle), and returns it; "" in `error` on
/// success. A transparent background stays transparent where nothing is drawn.
Image renderChartImage(int width, int height, const std::function<void(Renderer2D&, Rect)>& draw,
                       std::string& error, Color background = {0.0f, 0.0f, 0.0f, 1.0f});

/// Same, written to `path` as PNG. Returns "" on success, else why not.
std::string renderChartPng(const std::string& path, int width, int height,
                           const std::function<void(Renderer2D&, Rect)>& draw,
                           Color background = {0.0f, 0.0f, 0.0f, 1.0f});

} // namespace ui::charts
