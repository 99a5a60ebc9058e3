#include "ui/game/offscreen_match.h"

#include "ui/game/match_frame.h"
#include "ui/platform/imgui_layer.h"
#include "ui/render/gl.h"
#include "ui/render/renderer2d.h"

#include <stdexcept>

namespace ui {

std::unique_ptr<OffscreenMatch> OffscreenMatch::create(int width, int height, bool hud,
                                                       HeadlessBackend backend, std::string& why) {
    std::unique_ptr<OffscreenMatch> m(new OffscreenMatch());
    m->context_ = createHeadlessContext(width, height, backend, why);
    if (!m->context_) return nullptr;
    if (const char* missing = gl::loadGL(m->context_->procAddress()); *missing) {
        why = std::string(m->context_->name()) + ": OpenGL 3.3 core is needed; " + missing +
              " is missing";
        return nullptr;
    }
    try {
        m->imgui_ = std::make_unique<ImGuiLayer>(*m->context_, nullptr);
        m->renderer_ = std::make_unique<Renderer2D>();
    } catch (const std::exception& e) {
        why = e.what();
        return nullptr;
    }
    m->hud_ = hud;
    return m;
}

OffscreenMatch::~OffscreenMatch() {
    // ImGui and the renderer free GL objects: they go before the context.
    renderer_.reset();
    imgui_.reset();
}

void OffscreenMatch::draw(const game::Match& match, double frameSeconds) {
    view_.observe(match);
    const int w = context_->width(), h = context_->height();
    MatchViewOptions o;
    o.hud = hud_;
    imgui_->newFrame(frameSeconds);
    gl::fn.BindFramebuffer(GL_FRAMEBUFFER, context_->framebuffer());
    drawMatchFrame(*renderer_, view_, match, levelCamera(match, w, h), o);
    imgui_->drawLabels(renderer_->labels());
    imgui_->render();
    context_->present(); // waits until the frame is drawn
}

Image OffscreenMatch::readBack() const {
    return readFramebuffer(context_->framebuffer(), context_->width(), context_->height());
}

} // namespace ui
