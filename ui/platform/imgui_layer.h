// Dear ImGui on a GLContext: the OpenGL3 renderer backend everywhere, the SDL2 platform
// backend in a window, and a fixed display size with no input headless, so panels and
// labels draw the same in screenshots as on screen.
#pragma once

#include "ui/platform/gl_context.h"
#include "ui/platform/key_taps.h"
#include "ui/render/pixel_rect.h"
#include "ui/render/renderer2d.h"

#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

union SDL_Event;

struct ImFont;

namespace ui {

class SdlWindow;

/// Where the ImGui window `name` was drawn open (not folded) in the last frame, in
/// framebuffer pixels, or nothing: what a panel covers, for what the game draws beside it.
std::optional<PixelRect> openWindowRect(const char* name);
/// The panels' font at twice its size (a lesson's formula), for ImGui::PushFont.
ImFont* largeFont();

/// Every window drawn in the last frame (folded ones by their title bar; tooltips and
/// pop-ups too), by its ImGui name, in framebuffer pixels: what the panels cover.
std::vector<std::pair<std::string, PixelRect>> drawnWindowRects();
/// Where `label` will be drawn, in framebuffer pixels, in the font of the panels being built.
PixelRect labelRect(const Label& label);
/// How wide `text` is at `scale` x the panels' design font size, in design pixels (the
/// 1280x720 canvas): what a box the HUD lays out in design pixels needs to hold it.
double designTextWidth(const std::string& text, double scale);

/// Design pixels (the 1280x720 canvas of ui/render/design_canvas.h) to pixels of the
/// panels being built: what a fixed width or position in a panel is given in, so it
/// scales with their text on a large screen.
float panelPx(float designPixels);

/// A line in the disabled (dim) colour, wrapped at the window's edge (or the wrap
/// position pushed): a note that never runs out of its panel.
void dimWrapped(const std::string& text);

/// Call between Begin and End: a panel that grew past the bottom or the right of the
/// display (it fits what it holds, and holds more now) moves back in, `margin` pixels
/// from that edge.
void keepPanelOnScreen(float margin);

/// Where a panel's edge goes (one axis) when the display goes from `was` to `now`
/// pixels and the panels' scale by a factor `k`: a panel nearer the start keeps its
/// margin to the start, scaled; one nearer the end its margin to the end.
float keepToNearestEdge(float pos, float size, float was, float now, float k);

class ImGuiLayer {
  public:
    /// `window` is null headless. Throws std::runtime_error when the backend cannot start.
    ImGuiLayer(GLContext& context, SdlWindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    /// Passes an SDL event to ImGui; true when its backend took it in (every key, button
    /// and wheel event: that is not ImGui wanting it, which wantsMouse and wantsKeyboard
    /// tell).
    bool processEvent(const SDL_Event& event);
    /// Starts an ImGui frame of `dtSeconds`.
    void newFrame(double dtSeconds);
    /// Queues the renderer's text labels behind every ImGui window; where each was put,
    /// in framebuffer pixels.
    std::vector<PixelRect> drawLabels(std::span<const Label> labels);
    /// Draws the ImGui frame into the currently bound framebuffer.
    void render();

    bool wantsMouse() const;
    bool wantsKeyboard() const;
    /// A button press on a window drawn in the last frame. ImGui's capture flag
    /// (wantsMouse) is set from where the pointer was when the last frame began, so a
    /// press that comes with the pointer's first move onto a panel (a tap on a touch
    /// screen, a quick flick and click) is not yet in it, and would reach the world too.
    bool pressOnWindow(const SDL_Event& event) const;

  private:
    /// Rasterizes the font and sizes the style for panels at `scale` x their design size.
    void setPanelScale(float scale);
    /// Moves the panels for a display that changed from `was` to `now` (a resize, full
    /// screen, or a layout saved at another size).
    void keepPanelsInPlace(Vec2 was, Vec2 now);

    GLContext& context_;
    SdlWindow* window_;
    float scale_ = 0.0f;   ///< the panels' scale (design_canvas.h), 0 before the first
    Vec2 layoutDisplay_{}; ///< the display the panels are placed for, in points
    KeyTaps taps_;         ///< quick taps' releases, held back a frame
    bool pointerOut_ = false;  ///< the pointer left the window
    bool pointerSeen_ = false; ///< a motion event has come: pointer_ holds its place
    Vec2 pointer_{};           ///< the last motion event's place, in window points
};

} // namespace ui
