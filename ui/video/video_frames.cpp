#include "ui/video/video_frames.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ui {

namespace {

/// A frame's time counts as passed once the simulation is this far beyond it: the sum of
/// ticks of 1/120 s lands on 1/30 s only to rounding, and a frame must not come a tick
/// early because of it.
constexpr double kClockTolerance = 1e-9; // s

} // namespace

std::unique_ptr<VideoFrameSink> VideoFrameSink::create(const game::cli::VideoRequest& request,
                                                       HeadlessBackend backend, std::string& why) {
    return create(request, VideoDef{}, backend, why);
}

std::unique_ptr<VideoFrameSink> VideoFrameSink::create(const game::cli::VideoRequest& request,
                                                       const VideoDef& writer,
                                                       HeadlessBackend backend, std::string& why) {
    VideoDef def = writer;
    def.file = request.file;
    def.width = request.width;
    def.height = request.height;
    def.fps = request.fps;
    def.audio = request.audio;
    def.source = request.sound;
    std::unique_ptr<VideoFrameSink> sink(new VideoFrameSink());
    // The file first: a bad name or folder is reported before a GL context is made.
    sink->writer_ = VideoWriter::open(def, why);
    if (!sink->writer_) return nullptr;
    sink->canvas_ =
        OffscreenMatch::create(request.width, request.height, request.hud, backend, why);
    if (!sink->canvas_) return nullptr;
    sink->request_ = request;
    return sink;
}

VideoFrameSink::~VideoFrameSink() {
    if (std::getenv("ARTILLERY_FRAME_TIMES") && writer_ && writer_->frames() > 0)
        std::fprintf(
            stderr,
            "video frames: %lld, drawing %.1f ms/frame, reading back and encoding %.1f ms/frame\n",
            writer_->frames(), drawMs_ / writer_->frames(), encodeMs_ / writer_->frames());
}

double VideoFrameSink::simulatedSeconds(const game::Match& m) {
    const double dt = m.world().def().tickSeconds;
    if (dt != tickSeconds_ && m.tick() > 0) {
        // The start, or a `set tick_hz`: the tick just run was the first of the new length.
        const std::uint64_t start = m.tick() - 1;
        baseSeconds_ += static_cast<double>(start - baseTick_) * tickSeconds_;
        baseTick_ = start;
        tickSeconds_ = dt;
    }
    // Counted per segment rather than summed tick by tick, so no rounding builds up.
    return baseSeconds_ + static_cast<double>(m.tick() - baseTick_) * tickSeconds_;
}

void VideoFrameSink::frame(const game::Match& match) {
    using Clock = std::chrono::steady_clock;
    if (tickSeconds_ != 0.0 && match.tick() == lastTick_) return; // this tick was seen
    lastTick_ = match.tick();
    if (request_.afterTick) request_.afterTick(match);
    canvas_->observe(match); // every tick: trails and effects as the window shows them
    const double now = simulatedSeconds(match);
    // Every frame whose time the simulation has now passed (several when ticks are
    // longer than frames: they repeat the picture).
    Image picture;
    while (static_cast<double>(writer_->frames()) / request_.fps + kClockTolerance < now) {
        const auto t0 = Clock::now();
        if (picture.rgba.empty()) canvas_->draw(match, 1.0 / request_.fps);
        const auto t1 = Clock::now();
        if (picture.rgba.empty()) picture = canvas_->readBack();
        if (!writer_->addFrame(picture)) return; // finish() reports it
        drawMs_ += std::chrono::duration<double, std::milli>(t1 - t0).count();
        encodeMs_ += std::chrono::duration<double, std::milli>(Clock::now() - t1).count();
    }
}

std::string VideoFrameSink::finish() {
    if (!writer_->finish()) return writer_->error();
    return "";
}

game::cli::VideoSinkFactory videoSinkFactory() {
    return [](const game::cli::VideoRequest& request,
              std::string& why) -> std::unique_ptr<game::cli::VideoSink> {
        return VideoFrameSink::create(request, HeadlessBackend::Auto, why);
    };
}

} // namespace ui
