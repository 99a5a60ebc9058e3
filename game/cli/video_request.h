// What `artillery run --video FILE` asks of the video encoder, which lives in ui/ beside
// the renderer (game/ links no FFmpeg): the request, and the sink that writes the file.
#pragma once

#include "game/headless.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

namespace game::cli {

/// What `run --video FILE` asks of the renderer and the video encoder (ui/ provides them).
struct VideoRequest {
    std::string file; ///< .mp4 or .gif
    int width = 1280; ///< pixels
    int height = 720; ///< pixels
    int fps = 30;     ///< frames per second, 1..60
    bool hud = true;
    bool audio = true; ///< MP4: a sound track (silent without `sound`)
    /// Called with the match after every tick (a sound track observes here).
    std::function<void(const Match&)> afterTick;
    /// The sound: stereo float frames at 48 kHz, interleaved, pulled in step with the video.
    std::function<void(float* interleaved, std::size_t frames)> sound;
};

/// A frame sink that writes a video; it wants every tick (HeadlessOptions::every = 1).
class VideoSink : public FrameSink {
  public:
    /// Finishes the file. "" on success, else why (the file is then not there).
    virtual std::string finish() = 0;
    virtual const char* codec() const = 0; ///< "h264", "mpeg4", "gif"
    virtual long long frames() const = 0;
    virtual double seconds() const = 0; ///< frames / fps
};

/// Opens a video (null and `why` when the file cannot be written or encoded).
using VideoSinkFactory =
    std::function<std::unique_ptr<VideoSink>(const VideoRequest& request, std::string& why)>;

} // namespace game::cli
