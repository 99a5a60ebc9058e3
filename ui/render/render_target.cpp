#include "ui/render/render_target.h"

#include "ui/render/gl.h"

#include <algorithm>

namespace ui {

MultisampleTarget::~MultisampleTarget() {
    release();
}

void MultisampleTarget::release() {
    if (fbo_ && gl::fn.DeleteFramebuffers) gl::fn.DeleteFramebuffers(1, &fbo_);
    if (colour_ && gl::fn.DeleteRenderbuffers) gl::fn.DeleteRenderbuffers(1, &colour_);
    fbo_ = colour_ = 0;
}

bool MultisampleTarget::resize(int width, int height, int samples) {
    if (width == width_ && height == height_ && samples == samples_ && (fbo_ || samples <= 1))
        return enabled() || samples <= 1;
    release();
    width_ = width, height_ = height, samples_ = samples;
    if (samples <= 1) return true;
    GLint maxSamples = 0;
    gl::fn.GetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    samples_ = std::min(samples, static_cast<int>(maxSamples));
    if (samples_ <= 1) return false;
    gl::fn.GenRenderbuffers(1, &colour_);
    gl::fn.BindRenderbuffer(GL_RENDERBUFFER, colour_);
    gl::fn.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width, height);
    gl::fn.GenFramebuffers(1, &fbo_);
    gl::fn.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
    gl::fn.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    const bool complete = gl::fn.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    gl::fn.BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!complete) {
        release();
        samples_ = 0;
    }
    return complete;
}

void MultisampleTarget::bind(unsigned fallbackFbo) const {
    gl::fn.BindFramebuffer(GL_FRAMEBUFFER, fbo_ ? fbo_ : fallbackFbo);
}

void MultisampleTarget::resolveInto(unsigned destinationFbo) const {
    if (fbo_) {
        gl::fn.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
        gl::fn.BindFramebuffer(GL_DRAW_FRAMEBUFFER, destinationFbo);
        gl::fn.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                               GL_NEAREST);
    }
    gl::fn.BindFramebuffer(GL_FRAMEBUFFER, destinationFbo);
}

} // namespace ui
