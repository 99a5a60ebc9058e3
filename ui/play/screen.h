// What the play verb drives, in a window or headless: the physics demo (PlayScreen) or
// the game (GameScreen). The verb feeds wall time and events; the screen owns the rest.
#pragma once

#include <string>

union SDL_Event;

namespace ui {

class Screen {
  public:
    virtual ~Screen() = default;
    /// Advances by `wallSeconds` (fixed ticks inside) and draws the frame (not presented).
    virtual void frame(double wallSeconds) = 0;
    /// One window event. Returns false when the player quits.
    virtual bool handleEvent(const SDL_Event& event) = 0;
    /// False once the player chose Quit from a menu.
    virtual bool running() const { return true; }
    /// Writes the frame just drawn as PNG. "" on success, else the error.
    virtual std::string saveScreenshot(const std::string& path) = 0;
    /// True once when the player asked for a screenshot (F12) since the last call.
    virtual bool takeScreenshotRequest() = 0;
    virtual void setMeasuredFrameMs(double ms) = 0;
    /// Simulates `seconds` without drawing (--warmup).
    virtual void warmUp(double seconds) = 0;
    /// The last frame's layout as JSON (ui/game/screen_layout.h), "" for a screen that
    /// does not gather one.
    virtual std::string layoutJson() const { return ""; }
};

} // namespace ui
