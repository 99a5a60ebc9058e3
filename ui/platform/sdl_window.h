// The game window: SDL2 with a GL 3.3 core context, as a GLContext.
#pragma once

#include "ui/platform/gl_context.h"

#include <memory>
#include <string>

struct SDL_Window;
union SDL_Event;

namespace ui {

class SdlWindow final : public GLContext {
  public:
    /// Opens a resizable window with a current GL 3.3 core context. Returns null and
    /// says why in `error` when there is no display or no such context.
    static std::unique_ptr<SdlWindow> open(const char* title, int width, int height,
                                           std::string& error);
    ~SdlWindow() override;

    const char* name() const override { return "sdl-window"; }
    int width() const override;
    int height() const override;
    ProcAddressFn procAddress() const override;
    void present() override;
    bool interactive() const override { return true; }

    SDL_Window* window() const { return window_; }
    /// F11 or Alt+Enter: switches between the window and the full screen (the desktop's
    /// resolution, no mode change). True when the event was that key, which is then
    /// nobody else's.
    bool toggleFullScreenOn(const SDL_Event& event);
    void* glContext() const { return glContext_; }

  private:
    SdlWindow(SDL_Window* window, void* context) : window_(window), glContext_(context) {}
    SDL_Window* window_;
    void* glContext_;
};

/// True when a display server is configured (X11 or Wayland), so a window can be tried.
bool displayAvailable();

} // namespace ui
