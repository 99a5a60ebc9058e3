#include "ui/charts/chart_png.h"

#include "ui/platform/gl_context.h"
#include "ui/platform/imgui_layer.h"
#include "ui/render/gl.h"
#include "ui/render/render_target.h"

#include <exception>
#include <memory>

namespace ui::charts {

Image renderChartImage(int width, int height, const std::function<void(Renderer2D&, Rect)>& draw,
                       std::string& error, Color background) {
    error.clear();
    auto ctx = createHeadlessContext(width, height, HeadlessBackend::Auto, error);
    if (!ctx) {
        error = "no headless GL context: " + error;
        return {};
    }
    if (const char* missing = gl::loadGL(ctx->procAddress()); missing && *missing) {
        error = std::string("GL function missing: ") + missing;
        return {};
    }
    try {
        ImGuiLayer imgui(*ctx, nullptr);
        Renderer2D renderer;
        // Thin chart lines alias badly; 4 samples smooth them (falls back to none when the
        // driver refuses).
        MultisampleTarget msaa;
        msaa.resize(width, height, 4);
        imgui.newFrame(1.0 / 60.0);
        msaa.bind(ctx->framebuffer());
        gl::fn.Viewport(0, 0, width, height);
        gl::fn.ClearColor(background.r, background.g, background.b, background.a);
        gl::fn.Clear(GL_COLOR_BUFFER_BIT);
        // A camera whose world units are pixels (y up): the chart maps through it.
        renderer.begin(Camera::framing({0.0, 0.0}, {static_cast<double>(width),
                                                    static_cast<double>(height)},
                                       width, height));
        draw(renderer, Rect{0.0, 0.0, static_cast<double>(width), static_cast<double>(height)});
        renderer.flush();
        msaa.resolveInto(ctx->framebuffer());
        imgui.drawLabels(renderer.labels());
        imgui.render();
        ctx->present();
        return readFramebuffer(ctx->framebuffer(), width, height);
    } catch (const std::exception& e) {
        error = e.what();
        return {};
    }
}

std::string renderChartPng(const std::string& path, int width, int height,
                           const std::function<void(Renderer2D&, Rect)>& draw, Color background) {
    std::string error;
    const Image img = renderChartImage(width, height, draw, error, background);
    if (!error.empty()) return error;
    return writePng(path, img);
}

} // namespace ui::charts
