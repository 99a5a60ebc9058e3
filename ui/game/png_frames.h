// The frame sink of `artillery run --png DIR`: each frame the headless runner
// hands over is drawn by OffscreenMatch (the window's drawing code, in an OSMesa context,
// EGL surfaceless as the fallback) and written as DIR/frame_TTTTTT.png, TTTTTT being the
// tick, so frames sort in time order and name the tick they show. With the environment
// variable ARTILLERY_FRAME_TIMES set, the sink prints its drawing and encoding times.
#pragma once

#include "game/cli/verbs.h"
#include "game/headless.h"
#include "ui/game/offscreen_match.h"
#include "ui/platform/gl_context.h"

#include <memory>
#include <string>

namespace ui {

class PngFrameSink final : public game::FrameSink {
  public:
    /// Creates DIR and a headless context of the size. Null (and `why`) on failure.
    static std::unique_ptr<PngFrameSink> create(const std::string& folder, int width, int height,
                                                bool hud, HeadlessBackend backend, std::string& why);
    ~PngFrameSink() override;

    /// Draws and writes the frame; throws std::runtime_error when it cannot be written.
    void frame(const game::Match& match) override;
    /// Files written so far, and the first write error ("" when none).
    int written() const { return written_; }
    const std::string& error() const { return error_; }

  private:
    PngFrameSink() = default;
    std::unique_ptr<OffscreenMatch> canvas_;
    std::string folder_;
    int written_ = 0;
    double drawMs_ = 0.0;  ///< wall time drawing (with the GL finish), for ARTILLERY_FRAME_TIMES
    double writeMs_ = 0.0; ///< reading back and PNG encoding
    std::string error_;
};

/// The factory runHeadlessVerb takes (game/cli/verbs.h).
game::cli::FrameSinkFactory pngFrameSinkFactory();

/// `artillery run` with the renderer: the game layer's verb (same name, options and help)
/// given this factory.
game::cli::Verb runVerbWithRenderer();

} // namespace ui
