// A video file from pictures and sound, through Debian's FFmpeg libraries: OUT.mp4 holds
// H.264 (libx264, when the libavcodec build has it; else MPEG-4 part 2) in yuv420p with
// AAC audio, stereo at 48 kHz; OUT.gif holds the pictures alone. The frame rate is
// constant: frame k is shown at k / fps, and the audio is pulled from its source in
// lockstep with that clock (samples counted, never read from a clock). The file is
// written under a temporary name and renamed into place by finish(); a writer that fails
// or is dropped unfinished removes it.
#pragma once

#include "ui/render/screenshot.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

namespace ui {

/// The video's sound: fills `frames` stereo frames (2 * frames floats, left then right)
/// at kVideoSampleRate, continuing where the previous call stopped.
using AudioSource = std::function<void(float* interleaved, std::size_t frames)>;

inline constexpr int kVideoSampleRate = 48000; ///< audio samples per second and channel
inline constexpr int kVideoChannels = 2;       ///< stereo
inline constexpr int kMaxVideoFps = 60;

/// What to write. Validated by VideoWriter::open.
struct VideoDef {
    std::string file;   ///< ends in .mp4 or .gif
    int width = 1280;   ///< pixels; even for MP4 (yuv420p halves the colour planes)
    int height = 720;   ///< pixels; even for MP4
    int fps = 30;       ///< frames per second, 1..kMaxVideoFps
    bool audio = true;  ///< MP4: an AAC track, silent when `source` is empty; GIF has none
    AudioSource source; ///< the sound, pulled as frames are added
    bool mpeg4 = false; ///< MP4: MPEG-4 part 2 even when an H.264 encoder is there
};

class VideoWriter {
  public:
    /// Opens the temporary file and the encoders. Null, and `why` in one line, when the
    /// extension is unknown, the size or rate is out of range, an encoder is missing or
    /// the file cannot be written.
    static std::unique_ptr<VideoWriter> open(const VideoDef& def, std::string& why);
    ~VideoWriter();
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    /// Appends the next frame (its pts is frames() / fps): the audio up to its time is
    /// pulled and encoded first. The picture must have the video's size. False on an
    /// encoding or write error (error() says which; later calls do nothing).
    bool addFrame(const Image& picture);
    /// Pulls the audio up to the end of the last frame, drains the encoders, writes the
    /// index and renames the file into place. False, with error(), when any step failed.
    bool finish();

    /// The first error ("" when none).
    const std::string& error() const;
    /// The video codec: "h264", "mpeg4" or "gif".
    const char* codec() const;
    long long frames() const;
    /// frames() / fps: the video's length.
    double seconds() const;
    /// Audio frames (stereo samples) written so far.
    long long audioFrames() const;

  private:
    struct Encoding;
    explicit VideoWriter(std::unique_ptr<Encoding> encoding);
    std::unique_ptr<Encoding> enc_;
};

/// Where a video is written until it is complete: FILE.part beside FILE.
inline std::string partialVideoFile(const std::string& file) {
    return file + ".part";
}

/// The stereo frames that belong before video frame `frame` at `fps`: floor(frame *
/// kVideoSampleRate / fps), exact in integers so the audio never drifts from the pictures.
constexpr long long audioFramesBefore(long long frame, int fps) {
    return frame * kVideoSampleRate / fps;
}

} // namespace ui
