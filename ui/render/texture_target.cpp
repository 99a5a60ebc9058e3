#include "ui/render/texture_target.h"

#include "ui/render/gl.h"

namespace ui {

TextureTarget::~TextureTarget() {
    if (fbo_ && gl::fn.DeleteFramebuffers) gl::fn.DeleteFramebuffers(1, &fbo_);
    if (texture_ && gl::fn.DeleteTextures) gl::fn.DeleteTextures(1, &texture_);
}

bool TextureTarget::create(int width, int height, int samples) {
    width_ = width;
    height_ = height;
    gl::fn.GenTextures(1, &texture_);
    gl::fn.BindTexture(GL_TEXTURE_2D, texture_);
    gl::fn.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl::fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl::fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl::fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl::fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl::fn.GenFramebuffers(1, &fbo_);
    gl::fn.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
    gl::fn.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    const bool complete = gl::fn.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    gl::fn.BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (complete) msaa_.resize(width, height, samples);
    return complete;
}

void TextureTarget::bind() const {
    msaa_.bind(fbo_);
}

void TextureTarget::finish(unsigned restoreFbo) const {
    msaa_.resolveInto(fbo_);
    gl::fn.BindFramebuffer(GL_FRAMEBUFFER, restoreFbo);
}

} // namespace ui
