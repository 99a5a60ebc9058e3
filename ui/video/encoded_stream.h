// One stream of a video file (pictures or sound): its encoder, the container's stream it
// feeds and the packets in between. Internal to ui/video/.
#pragma once

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <string>

namespace ui::video {

/// FFmpeg's message for an error code.
std::string avError(int code);

/// Frees what FFmpeg allocated, for std::unique_ptr.
struct AvFree {
    void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
    void operator()(AVFrame* f) const { av_frame_free(&f); }
    void operator()(AVPacket* p) const { av_packet_free(&p); }
};

class EncodedStream {
  public:
    /// A stream of `container` encoded by `codec`; configure context() and then open().
    EncodedStream(AVFormatContext* container, const AVCodec* codec);
    ~EncodedStream();
    EncodedStream(const EncodedStream&) = delete;
    EncodedStream& operator=(const EncodedStream&) = delete;

    AVCodecContext* context() const { return ctx_; }
    AVStream* stream() const { return stream_; }
    /// Opens the encoder (with its private `options`, "key=value:..."), and copies its
    /// parameters to the stream. "" or why not.
    std::string open(const char* options);
    /// Encodes `frame` (null: drain the encoder at the end) and writes every packet it
    /// gives to the container, its timestamps moved from the encoder's time base to the
    /// stream's. "" or why not.
    std::string encode(const AVFrame* frame);

  private:
    AVFormatContext* container_;
    AVCodecContext* ctx_ = nullptr;
    AVStream* stream_ = nullptr;
    AVPacket* packet_ = nullptr;
};

} // namespace ui::video
