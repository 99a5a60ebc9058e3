// The EGL headless context: Mesa's surfaceless platform, no window system and no
// display, a desktop GL 3.3 core context, drawing into a framebuffer object we own
// (a surfaceless context has no default framebuffer). The fallback for systems whose
// Mesa no longer ships OSMesa (removed in Mesa 25.1).
#include "ui/platform/gl_context.h"
#include "ui/render/gl.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>

namespace ui {

namespace {

void* eglProc(const char* name) {
    return reinterpret_cast<void*>(eglGetProcAddress(name));
}

class EglContextImpl final : public GLContext {
  public:
    EglContextImpl(EGLDisplay display, EGLContext context, int w, int h)
        : display_(display), context_(context), width_(w), height_(h) {}
    ~EglContextImpl() override {
        if (fbo_) gl::fn.DeleteFramebuffers(1, &fbo_);
        if (colour_) gl::fn.DeleteRenderbuffers(1, &colour_);
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }

    /// Makes the colour buffer the context draws into. Needs ui::gl loaded.
    bool makeFramebuffer() {
        gl::fn.GenRenderbuffers(1, &colour_);
        gl::fn.BindRenderbuffer(GL_RENDERBUFFER, colour_);
        gl::fn.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
        gl::fn.GenFramebuffers(1, &fbo_);
        gl::fn.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
        gl::fn.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                       colour_);
        return gl::fn.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }

    const char* name() const override { return "egl-surfaceless"; }
    int width() const override { return width_; }
    int height() const override { return height_; }
    ProcAddressFn procAddress() const override { return eglProc; }
    unsigned framebuffer() const override { return fbo_; }
    void present() override { gl::fn.Finish(); }

  private:
    EGLDisplay display_;
    EGLContext context_;
    int width_, height_;
    unsigned fbo_ = 0;
    unsigned colour_ = 0;
};

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + n, name))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

} // namespace

std::unique_ptr<GLContext> createEglContext(int width, int height, std::string& error) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        error =
            "egl: the EGL_MESA_platform_surfaceless extension is missing (install libegl-mesa0)";
        return nullptr;
    }
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) {
        error = "egl: eglGetPlatformDisplayEXT is missing";
        return nullptr;
    }
    EGLDisplay display =
        getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
        error = "egl: cannot initialise the surfaceless display";
        return nullptr;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(display);
        error = "egl: desktop OpenGL is not available";
        return nullptr;
    }
    // Surfaceless: no config needed when EGL_KHR_no_config_context is there; else any
    // config that can render desktop GL.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
        const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(display, want, &config, 1, &count) || count < 1) {
            eglTerminate(display);
            error = "egl: no config renders desktop OpenGL";
            return nullptr;
        }
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
        eglTerminate(display);
        error = "egl: cannot create a GL 3.3 core context";
        return nullptr;
    }
    auto result = std::make_unique<EglContextImpl>(display, context, width, height);
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        error = "egl: cannot make the surfaceless context current";
        return nullptr;
    }
    if (const char* missing = gl::loadGL(eglProc); *missing) {
        error = std::string("egl: the context lacks ") + missing;
        return nullptr;
    }
    if (!result->makeFramebuffer()) {
        error = "egl: the framebuffer object is incomplete";
        return nullptr;
    }
    return result;
}

} // namespace ui
