// The frame sink of `artillery run --video FILE`: the headless runner hands it every tick;
// it keeps the video's clock (frame k at k / fps) beside the simulation's (the sum of
// the ticks' lengths) and, whenever the simulation passes a frame's time, draws the
// match through OffscreenMatch (the window's drawing code) and hands the picture to the
// VideoWriter. At 30 frames per second and 120 ticks per second that is every 4th tick
// (ticks 1, 5, 9, ...: each frame shows the first tick after its time), so the video
// plays at real speed and runs ceil(seconds * fps) frames.
#pragma once

#include "game/cli/verbs.h"
#include "ui/game/offscreen_match.h"
#include "ui/video/video_writer.h"

#include <cstdint>
#include <memory>
#include <string>

namespace ui {

class VideoFrameSink final : public game::cli::VideoSink {
  public:
    /// Opens the video and a headless context of its size. Null (and `why`) on failure.
    static std::unique_ptr<VideoFrameSink> create(const game::cli::VideoRequest& request,
                                                  HeadlessBackend backend, std::string& why);
    /// `writer`'s settings with `request`'s; for tests that choose the codec.
    static std::unique_ptr<VideoFrameSink> create(const game::cli::VideoRequest& request,
                                                  const VideoDef& writer, HeadlessBackend backend,
                                                  std::string& why);
    ~VideoFrameSink() override;

    void frame(const game::Match& match) override;
    std::string finish() override;
    const char* codec() const override { return writer_->codec(); }
    long long frames() const override { return writer_->frames(); }
    double seconds() const override { return writer_->seconds(); }

  private:
    VideoFrameSink() = default;
    /// Simulated seconds at the match's current tick (ticks may change length mid-run).
    double simulatedSeconds(const game::Match& match);

    std::unique_ptr<OffscreenMatch> canvas_;
    std::unique_ptr<VideoWriter> writer_;
    game::cli::VideoRequest request_;
    std::uint64_t baseTick_ = 0; ///< the tick at which the tick length last changed
    double baseSeconds_ = 0.0;   ///< simulated seconds at baseTick_
    double tickSeconds_ = 0.0;   ///< the tick length since baseTick_ (0: not started)
    std::uint64_t lastTick_ = 0;
    double drawMs_ = 0.0;   ///< wall time drawing, for ARTILLERY_FRAME_TIMES
    double encodeMs_ = 0.0; ///< reading back and encoding
};

/// The factory runHeadlessVerb takes (game/cli/video_request.h).
game::cli::VideoSinkFactory videoSinkFactory();

} // namespace ui
