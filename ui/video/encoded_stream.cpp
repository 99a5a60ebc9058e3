#include "ui/video/encoded_stream.h"

extern "C" {
#include <libavutil/dict.h>
#include <libavutil/error.h>
}

#include <stdexcept>

namespace ui::video {

std::string avError(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

EncodedStream::EncodedStream(AVFormatContext* container, const AVCodec* codec)
    : container_(container), ctx_(avcodec_alloc_context3(codec)),
      stream_(avformat_new_stream(container, nullptr)), packet_(av_packet_alloc()) {
    if (!ctx_ || !stream_ || !packet_) {
        avcodec_free_context(&ctx_);
        av_packet_free(&packet_);
        throw std::bad_alloc();
    }
    // Containers that keep codec headers once (MP4) want them out of the packets.
    if (container->oformat->flags & AVFMT_GLOBALHEADER) ctx_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
}

EncodedStream::~EncodedStream() {
    avcodec_free_context(&ctx_);
    av_packet_free(&packet_);
}

std::string EncodedStream::open(const char* options) {
    AVDictionary* opts = nullptr;
    if (options && *options) av_dict_parse_string(&opts, options, "=", ":", 0);
    const int rc = avcodec_open2(ctx_, ctx_->codec, &opts);
    av_dict_free(&opts);
    if (rc < 0)
        return std::string("the ") + ctx_->codec->name + " encoder refused to open: " + avError(rc);
    stream_->time_base = ctx_->time_base;
    const int copied = avcodec_parameters_from_context(stream_->codecpar, ctx_);
    if (copied < 0)
        return "cannot describe the " + std::string(ctx_->codec->name) +
               " stream: " + avError(copied);
    return "";
}

std::string EncodedStream::encode(const AVFrame* frame) {
    int rc = avcodec_send_frame(ctx_, frame);
    if (rc < 0) return std::string("the ") + ctx_->codec->name + " encoder failed: " + avError(rc);
    for (;;) {
        rc = avcodec_receive_packet(ctx_, packet_);
        if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return "";
        if (rc < 0)
            return std::string("the ") + ctx_->codec->name + " encoder failed: " + avError(rc);
        av_packet_rescale_ts(packet_, ctx_->time_base, stream_->time_base);
        packet_->stream_index = stream_->index;
        // Takes the packet's reference; the container interleaves sound and pictures by time.
        rc = av_interleaved_write_frame(container_, packet_);
        if (rc < 0) return "cannot write: " + avError(rc);
    }
}

} // namespace ui::video
