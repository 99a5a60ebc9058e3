// The 2D renderer: every shape becomes triangles in one vertex list (position in world
// metres, colour per vertex), uploaded to one VBO and drawn with one small shader in a
// single call per flush, so the painter's order is the order of the calls. Lines are
// quads a given number of pixels wide (core GL has no wide lines), circles are fans
// whose segment count follows their size on screen.
//
// It implements phys::DebugDraw, so physics (and the game) can describe a scene in
// world units without knowing GL. Text is collected as labels in pixel coordinates and
// drawn by ImGui after the geometry (ui/platform/imgui_layer.h).
#pragma once

#include "physics/debug_draw.h"
#include "ui/render/camera.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace ui {

using phys::Color;
using phys::Vec2;

struct Vertex {
    float x, y;           ///< world, m
    std::uint8_t rgba[4]; ///< straight alpha
};

/// A text label waiting to be drawn: pixel position of its top-left corner.
struct Label {
    Vec2 pixel;
    std::string text;
    Color color;
    float scale = 1.0f;  ///< relative to the UI font size
    float alignX = 0.0f; ///< which point of the text sits at `pixel`: 0 left, 0.5 centre, 1 right
    /// Placed by a point of the world (label()), not laid out in pixels by the HUD or a
    /// chart (screenLabel()): an overlay of its own over the field.
    bool world = false;
};

struct RenderStats {
    std::size_t vertices = 0;  ///< in the last flush
    std::size_t drawCalls = 0; ///< since begin()
};

class Renderer2D final : public phys::DebugDraw {
  public:
    /// Compiles the shader and makes the buffers; needs a current GL 3.3 core context
    /// with ui::gl loaded. Throws std::runtime_error with the GL log on failure.
    Renderer2D();
    ~Renderer2D() override;
    Renderer2D(const Renderer2D&) = delete;
    Renderer2D& operator=(const Renderer2D&) = delete;

    /// Starts a frame seen through `camera`; drops the previous frame's labels.
    void begin(const Camera& camera);
    const Camera& camera() const { return camera_; }
    /// Draws everything added since the last flush (keeps the labels).
    void flush();
    /// Starts drawing into a rectangle of the framebuffer (`camera`'s size, its lower-left
    /// corner at `originPx` in GL's bottom-up pixels) over what is there, keeping the
    /// frame's labels: a picture in the picture. endInset() drops the labels the inset
    /// added (they are placed for the inset's pixels) and draws full-frame again through
    /// `frame`.
    void beginInset(const Camera& camera, int originXPx, int originYPx);
    void endInset(const Camera& frame);

    // Primitives. Widths and minimum radii are in pixels so they read the same at any zoom.
    void line(Vec2 a, Vec2 b, Color color, float widthPx = 1.5f);
    /// Mitred joints; `closed` joins the last point to the first.
    void polyline(std::span<const Vec2> points, Color color, float widthPx = 1.5f,
                  bool closed = false);
    void fillCircle(Vec2 center, double radius, Color color, float minRadiusPx = 0.0f);
    void strokeCircle(Vec2 center, double radius, Color color, float widthPx = 1.5f,
                      float minRadiusPx = 0.0f);
    /// A filled convex polygon (any winding).
    void fillConvex(std::span<const Vec2> points, Color color);
    /// One triangle with a colour per corner (gradients).
    void triangle(Vec2 a, Vec2 b, Vec2 c, Color ca, Color cb, Color cc);
    /// An axis-aligned rectangle with a vertical gradient (bottom colour, top colour).
    void fillRectGradient(Vec2 lo, Vec2 hi, Color bottom, Color top);
    /// A line with a filled head at `to`.
    void arrow(Vec2 from, Vec2 to, Color color, float widthPx = 2.0f, float headPx = 10.0f);
    /// A text label whose top-left corner is at world point p, nudged by `offsetPx`. Its
    /// size and nudge are in design pixels, scaled to the picture as the panels' text is
    /// (panelScale, design_canvas.h), so a label reads the same on a 4K screen.
    void label(Vec2 p, std::string text, Color color, Vec2 offsetPx = {}, float scale = 1.0f,
               float alignX = 0.0f);
    /// A label at a pixel position at `scale` x the design font size, as given: text laid
    /// out in pixels by its caller (the HUD, the charts).
    void screenLabel(Vec2 pixel, std::string text, Color color, float scale = 1.0f,
                     float alignX = 0.0f);

    // phys::DebugDraw
    void segment(Vec2 a, Vec2 b, Color color) override { line(a, b, color); }
    void circle(Vec2 center, double radius, Color color) override;
    void solidCircle(Vec2 center, double radius, Vec2 axis, Color color) override;
    void polygon(std::span<const Vec2> vertices, Color color) override;
    void solidPolygon(std::span<const Vec2> vertices, Color color) override;
    void point(Vec2 p, float sizePixels, Color color) override;
    void text(Vec2 p, std::string_view text, Color color) override;

    const std::vector<Label>& labels() const { return labels_; }
    const RenderStats& stats() const { return stats_; }
    /// Number of segments a circle of this many pixels of radius is drawn with.
    static int circleSegments(double radiusPx);

  private:
    void push(Vec2 p, Color c);
    void quad(Vec2 a, Vec2 b, Vec2 c, Vec2 d, Color color);

    Camera camera_;
    int originX_ = 0, originY_ = 0; ///< the viewport's lower-left corner, px (insets)
    std::size_t frameLabels_ = 0;   ///< labels kept across an inset
    std::vector<Vertex> vertices_;
    std::vector<Label> labels_;
    float labelScale_ = 1.0f; ///< world labels' design pixels to pixels, set by begin()
    std::vector<Vec2> scratch_;
    RenderStats stats_;
    unsigned program_ = 0;
    unsigned vao_ = 0;
    unsigned vbo_ = 0;
    int clipFromWorldLoc_ = -1;
};

} // namespace ui
