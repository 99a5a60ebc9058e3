// Where GL draws: one interface over the window (SDL2) and the headless contexts
// (OSMesa, EGL surfaceless), so the renderer, ImGui and screenshots run the same code
// on all of them: the very same drawing code as the window.
#pragma once

#include <memory>
#include <string>

namespace ui {

/// Looks up a GL function by name in the current context (same type as ui::gl::ProcAddressFn;
/// declared again here so the OSMesa and EGL units need not include the loader header).
using ProcAddressFn = void* (*)(const char* name);

class GLContext {
  public:
    virtual ~GLContext() = default;

    /// "sdl-window", "osmesa" or "egl-surfaceless".
    virtual const char* name() const = 0;
    /// Size of the drawable in pixels.
    virtual int width() const = 0;
    virtual int height() const = 0;
    /// Looks up GL functions of this context (for ui::gl and ImGui's loader).
    virtual ProcAddressFn procAddress() const = 0;
    /// The framebuffer a frame ends up in (0: the context's default framebuffer).
    virtual unsigned framebuffer() const { return 0; }
    /// Shows the frame (window) or waits for it to be finished (headless).
    virtual void present() = 0;
    /// True for a window the user sees (input, vsync); false headless.
    virtual bool interactive() const { return false; }
};

/// Which headless implementation to use.
enum class HeadlessBackend { Auto, OSMesa, EGL };

/// A headless GL 3.3 core context of the given size, current on this thread. Auto tries
/// OSMesa first and falls back to EGL surfaceless (Mesa 25.1 removed OSMesa). Returns
/// null and says why in `error` when no backend works.
std::unique_ptr<GLContext> createHeadlessContext(int width, int height, HeadlessBackend backend,
                                                 std::string& error);

// The implementations, each in its own translation unit (GL/osmesa.h and EGL/egl.h
// bring their own GL headers, which clash with the loader's).
std::unique_ptr<GLContext> createOSMesaContext(int width, int height, std::string& error);
std::unique_ptr<GLContext> createEglContext(int width, int height, std::string& error);

} // namespace ui
