// A match drawn with no window: the window's drawing code (MatchView, drawMatchFrame and
// the ImGui labels) into a headless context (OSMesa, or EGL surfaceless), read back as a
// picture. The PNG frames of `run --png` and the video frames of `run --video` both come
// from here, so a frame looks the same in a screenshot, a video and the window.
#pragma once

#include "game/match.h"
#include "ui/game/match_view.h"
#include "ui/platform/gl_context.h"
#include "ui/render/screenshot.h"

#include <memory>
#include <string>

namespace ui {

class ImGuiLayer;
class Renderer2D;

class OffscreenMatch {
  public:
    /// A headless context of the size with its renderer and ImGui. Null (and `why`)
    /// when no backend gives OpenGL 3.3 core.
    static std::unique_ptr<OffscreenMatch> create(int width, int height, bool hud,
                                                  HeadlessBackend backend, std::string& why);
    ~OffscreenMatch();
    OffscreenMatch(const OffscreenMatch&) = delete;
    OffscreenMatch& operator=(const OffscreenMatch&) = delete;

    /// Lets the view follow a tick (trails, effects); draw() observes too.
    void observe(const game::Match& match) { view_.observe(match); }
    /// Draws the match as it is, from the level's camera, and waits until it is drawn.
    /// `frameSeconds` is the time ImGui is told this frame took.
    void draw(const game::Match& match, double frameSeconds);
    /// The picture draw() made, rows top to bottom.
    Image readBack() const;

    int width() const { return context_->width(); }
    int height() const { return context_->height(); }

  private:
    OffscreenMatch() = default;
    std::unique_ptr<GLContext> context_;
    std::unique_ptr<ImGuiLayer> imgui_;
    std::unique_ptr<Renderer2D> renderer_;
    MatchView view_;
    bool hud_ = true;
};

} // namespace ui
