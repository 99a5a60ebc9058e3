#include "ui/platform/sdl_window.h"

#include <SDL.h>

#include <cstdlib>

namespace ui {

namespace {
void* sdlProc(const char* name) {
    return SDL_GL_GetProcAddress(name);
}
} // namespace

bool displayAvailable() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

std::unique_ptr<SdlWindow> SdlWindow::open(const char* title, int width, int height,
                                           std::string& error) {
    // Ask for the display server that is configured, so SDL does not try the others
    // first (and print their errors). SDL_VIDEODRIVER in the environment still wins.
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    SDL_SetHintWithPriority(SDL_HINT_VIDEODRIVER, wayland && *wayland ? "wayland" : "x11",
                            SDL_HINT_DEFAULT);
    if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_EVENTS) != 0) {
        error = std::string("sdl: cannot start video: ") + SDL_GetError();
        return nullptr;
    }
    // When no display answers, SDL falls back to drivers that show nothing; a window
    // nobody can see is not a window (the caller draws headless instead).
    const std::string driver = SDL_GetCurrentVideoDriver() ? SDL_GetCurrentVideoDriver() : "";
    if (driver == "offscreen" || driver == "dummy" || driver.empty()) {
        error = "sdl: no display answers (SDL's video driver is '" + driver + "')";
        SDL_Quit();
        return nullptr;
    }
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);
    SDL_GL_SetAttribute(SDL_GL_STENCIL_SIZE, 0);
    const Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI;
    SDL_Window* window = SDL_CreateWindow(title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                          width, height, flags);
    if (!window) {
        error = std::string("sdl: cannot open a window: ") + SDL_GetError();
        SDL_Quit();
        return nullptr;
    }
    SDL_GLContext context = SDL_GL_CreateContext(window);
    if (!context) {
        error = std::string("sdl: no GL 3.3 core context: ") + SDL_GetError();
        SDL_DestroyWindow(window);
        SDL_Quit();
        return nullptr;
    }
    SDL_GL_MakeCurrent(window, context);
    SDL_GL_SetSwapInterval(1); // vsync where the display has it
    return std::unique_ptr<SdlWindow>(new SdlWindow(window, context));
}

SdlWindow::~SdlWindow() {
    SDL_GL_DeleteContext(glContext_);
    SDL_DestroyWindow(window_);
    SDL_Quit();
}

bool SdlWindow::toggleFullScreenOn(const SDL_Event& event) {
    if (event.type != SDL_KEYDOWN || event.key.repeat) return false;
    const SDL_Keycode key = event.key.keysym.sym;
    const bool alt = (event.key.keysym.mod & KMOD_ALT) != 0;
    if (key != SDLK_F11 && !(alt && (key == SDLK_RETURN || key == SDLK_KP_ENTER))) return false;
    const bool full = (SDL_GetWindowFlags(window_) & SDL_WINDOW_FULLSCREEN_DESKTOP) != 0;
    SDL_SetWindowFullscreen(window_, full ? 0 : SDL_WINDOW_FULLSCREEN_DESKTOP);
    return true;
}

int SdlWindow::width() const {
    int w = 0, h = 0;
    SDL_GL_GetDrawableSize(window_, &w, &h);
    return w;
}

int SdlWindow::height() const {
    int w = 0, h = 0;
    SDL_GL_GetDrawableSize(window_, &w, &h);
    return h;
}

ProcAddressFn SdlWindow::procAddress() const {
    return sdlProc;
}

void SdlWindow::present() {
    SDL_GL_SwapWindow(window_);
}

} // namespace ui
