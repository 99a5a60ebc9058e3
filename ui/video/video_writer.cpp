// Section index
//   Encoding      what one open video holds, and how it is torn down
//   open          format from the extension, encoders, converters, the temporary file
//   pictures      RGBA -> the encoder's pixel format (libswscale), frame k at pts k
//   sound         interleaved float -> the encoder's format (libswresample), in frames
//   finish        drain, index, rename
#include "ui/video/video_writer.h"

#include "ui/video/encoded_stream.h"

extern "C" {
#include <libavutil/audio_fifo.h>
#include <libavutil/channel_layout.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswresample/swresample.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <vector>

namespace ui {

using video::avError;
using video::AvFree;
using video::EncodedStream;

namespace {

/// Stereo frames pulled from the source at a time: bounded buffers for any frame rate.
constexpr int kPullChunk = 4096;

enum class Container { Mp4, Gif };

std::string lowerExtension(const std::string& file) {
    std::string ext = std::filesystem::path(file).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

} // namespace

// ---- Encoding -------------------------------------------------------------------------
struct VideoWriter::Encoding {
    VideoDef def;
    Container container = Container::Mp4;
    std::string temp; ///< where the bytes go until finish() renames them to def.file
    AVFormatContext* format = nullptr;
    std::unique_ptr<EncodedStream> picture;
    std::unique_ptr<EncodedStream> sound; ///< null for GIF or without audio
    SwsContext* scaler = nullptr;
    SwrContext* resampler = nullptr;
    AVAudioFifo* pending = nullptr; ///< converted samples waiting for a whole encoder frame
    std::unique_ptr<AVFrame, AvFree> pictureFrame;
    std::unique_ptr<AVFrame, AvFree> converted; ///< the resampler's output, kPullChunk long
    std::unique_ptr<AVFrame, AvFree> soundFrame;
    std::vector<float> pulled; ///< the source's interleaved float
    long long frames = 0;
    long long audioPulled = 0;  ///< stereo frames taken from the source
    long long audioEncoded = 0; ///< stereo frames handed to the encoder: the next pts
    std::string error;
    bool fileOpen = false;
    bool finished = false;

    ~Encoding() {
        // The encoders go before the container that owns their streams.
        picture.reset();
        sound.reset();
        sws_freeContext(scaler);
        swr_free(&resampler);
        if (pending) av_audio_fifo_free(pending);
        if (format) {
            if (fileOpen) avio_closep(&format->pb);
            avformat_free_context(format);
        }
        if (!finished && fileOpen) {
            std::error_code ec;
            std::filesystem::remove(temp, ec);
        }
    }

    bool fail(std::string why) {
        if (error.empty()) error = "video '" + def.file + "': " + std::move(why);
        return false;
    }

    std::string openPicture();
    std::string openSound();
    std::string pullAudio(long long until);
    std::string encodeSound(bool last);
};

VideoWriter::VideoWriter(std::unique_ptr<Encoding> encoding) : enc_(std::move(encoding)) {}
VideoWriter::~VideoWriter() = default;

const std::string& VideoWriter::error() const {
    return enc_->error;
}
long long VideoWriter::frames() const {
    return enc_->frames;
}
long long VideoWriter::audioFrames() const {
    return enc_->audioPulled;
}
double VideoWriter::seconds() const {
    return static_cast<double>(enc_->frames) / enc_->def.fps;
}
const char* VideoWriter::codec() const {
    return avcodec_get_name(enc_->picture->context()->codec_id);
}

// ---- open -----------------------------------------------------------------------------
std::unique_ptr<VideoWriter> VideoWriter::open(const VideoDef& def, std::string& why) {
    // The encoders' banners and statistics (libx264's settings, AAC's Qavg) are not for
    // the user; errors come back through `why`.
    av_log_set_level(AV_LOG_ERROR);
    auto e = std::make_unique<Encoding>();
    e->def = def;
    const std::string ext = lowerExtension(def.file);
    if (ext == ".mp4")
        e->container = Container::Mp4;
    else if (ext == ".gif")
        e->container = Container::Gif;
    else {
        why = "video '" + def.file + "': unknown format '" + ext +
              "'; the file name must end in .mp4 or .gif";
        return nullptr;
    }
    if (def.fps < 1 || def.fps > kMaxVideoFps) {
        why = "video '" + def.file + "': the frame rate must be 1.." +
              std::to_string(kMaxVideoFps) + " frames per second, got " + std::to_string(def.fps);
        return nullptr;
    }
    if (def.width < 16 || def.height < 16 || def.width > 8192 || def.height > 8192 ||
        (e->container == Container::Mp4 && (def.width % 2 || def.height % 2))) {
        why = "video '" + def.file + "': the size must be 16x16..8192x8192" +
              (e->container == Container::Mp4
                   ? ", even in both (MP4's yuv420p halves the colour planes)"
                   : "") +
              ", got " + std::to_string(def.width) + "x" + std::to_string(def.height);
        return nullptr;
    }
    e->temp = partialVideoFile(def.file);
    const char* formatName = e->container == Container::Mp4 ? "mp4" : "gif";
    const int allocated =
        avformat_alloc_output_context2(&e->format, nullptr, formatName, e->temp.c_str());
    if (allocated < 0 || !e->format) {
        why = "video '" + def.file + "': libavformat has no " + formatName + " muxer";
        return nullptr;
    }
    std::string err = e->openPicture();
    if (err.empty() && e->container == Container::Mp4 && def.audio) err = e->openSound();
    if (err.empty()) {
        const int rc = avio_open(&e->format->pb, e->temp.c_str(), AVIO_FLAG_WRITE);
        if (rc < 0)
            err = "cannot write '" + e->temp + "': " + avError(rc);
        else
            e->fileOpen = true;
    }
    if (err.empty()) {
        AVDictionary* opts = nullptr;
        // The index at the front, so a shared MP4 starts playing before it is all loaded.
        if (e->container == Container::Mp4) av_dict_set(&opts, "movflags", "+faststart", 0);
        const int rc = avformat_write_header(e->format, &opts);
        av_dict_free(&opts);
        if (rc < 0) err = "cannot write the header: " + avError(rc);
    }
    if (!err.empty()) {
        why = "video '" + def.file + "': " + err;
        return nullptr;
    }
    return std::unique_ptr<VideoWriter>(new VideoWriter(std::move(e)));
}

std::string VideoWriter::Encoding::openPicture() {
    const AVCodec* codec = nullptr;
    AVPixelFormat pixels = AV_PIX_FMT_YUV420P;
    const char* options = "";
    if (container == Container::Gif) {
        codec = avcodec_find_encoder(AV_CODEC_ID_GIF);
        // The GIF encoder's 3-3-2 fixed palette; libswscale dithers into it.
        pixels = AV_PIX_FMT_RGB8;
        if (!codec) return "this libavcodec has no GIF encoder";
    } else {
        if (!def.mpeg4) codec = avcodec_find_encoder_by_name("libx264");
        // "veryfast" keeps encoding well under the drawing's time per frame; crf 20 keeps
        // thin lines and text sharp.
        if (codec) options = "preset=veryfast:crf=20";
        if (!codec) codec = avcodec_find_encoder(AV_CODEC_ID_MPEG4);
        if (!codec) return "this libavcodec has neither an H.264 (libx264) nor an MPEG-4 encoder";
    }
    picture = std::make_unique<EncodedStream>(format, codec);
    AVCodecContext* c = picture->context();
    c->width = def.width;
    c->height = def.height;
    c->pix_fmt = pixels;
    c->time_base = AVRational{1, def.fps}; // frame k at k / fps
    c->framerate = AVRational{def.fps, 1};
    if (container == Container::Mp4) {
        c->gop_size = 2 * def.fps; // a key frame every 2 s: a player can seek
        if (codec->id == AV_CODEC_ID_MPEG4) {
            // Constant quality (qscale 3 of 1..31) instead of a guessed bit rate.
            c->flags |= AV_CODEC_FLAG_QSCALE;
            c->global_quality = FF_QP2LAMBDA * 3;
        }
    }
    if (std::string err = picture->open(options); !err.empty()) return err;
    picture->stream()->avg_frame_rate = c->framerate;
    scaler = sws_alloc_context();
    if (scaler) {
        av_opt_set_int(scaler, "srcw", def.width, 0);
        av_opt_set_int(scaler, "srch", def.height, 0);
        av_opt_set_int(scaler, "src_format", AV_PIX_FMT_RGBA, 0);
        av_opt_set_int(scaler, "dstw", def.width, 0);
        av_opt_set_int(scaler, "dsth", def.height, 0);
        av_opt_set_int(scaler, "dst_format", pixels, 0);
        av_opt_set_int(scaler, "sws_flags", SWS_BICUBIC, 0);
        // GIF: an ordered (Bayer) dither is the same wherever the picture is the same, so
        // the encoder stores only what changed; error diffusion lets one change ripple
        // over the whole frame (a 6 s clip: 4.4 MB against about 0.1 MB).
        if (container == Container::Gif) av_opt_set(scaler, "sws_dither", "bayer", 0);
        if (sws_init_context(scaler, nullptr, nullptr) < 0) {
            sws_freeContext(scaler);
            scaler = nullptr;
        }
    }
    pictureFrame.reset(av_frame_alloc());
    if (!scaler || !pictureFrame) return "out of memory for the picture converter";
    pictureFrame->format = pixels;
    pictureFrame->width = def.width;
    pictureFrame->height = def.height;
    if (const int rc = av_frame_get_buffer(pictureFrame.get(), 0); rc < 0)
        return "cannot allocate a picture: " + avError(rc);
    return "";
}

std::string VideoWriter::Encoding::openSound() {
    const AVCodec* codec = avcodec_find_encoder_by_name("aac");
    if (!codec) return "this libavcodec has no AAC encoder";
    sound = std::make_unique<EncodedStream>(format, codec);
    AVCodecContext* c = sound->context();
    c->sample_fmt = codec->sample_fmts ? codec->sample_fmts[0] : AV_SAMPLE_FMT_FLTP;
    c->sample_rate = kVideoSampleRate;
    av_channel_layout_default(&c->ch_layout, kVideoChannels);
    c->bit_rate = 160000;
    c->time_base = AVRational{1, kVideoSampleRate}; // pts counts samples
    if (std::string err = sound->open(""); !err.empty()) return err;

    AVChannelLayout stereo = AV_CHANNEL_LAYOUT_STEREO; // FFmpeg 5.1 takes it non-const
    int rc = swr_alloc_set_opts2(&resampler, &c->ch_layout, c->sample_fmt, kVideoSampleRate,
                                 &stereo, AV_SAMPLE_FMT_FLT, kVideoSampleRate, 0, nullptr);
    if (rc >= 0) rc = swr_init(resampler);
    if (rc < 0) return "cannot set up the sound converter: " + avError(rc);
    pending = av_audio_fifo_alloc(c->sample_fmt, kVideoChannels, c->frame_size + kPullChunk);
    converted.reset(av_frame_alloc());
    soundFrame.reset(av_frame_alloc());
    if (!pending || !converted || !soundFrame) return "out of memory for the sound";
    for (AVFrame* f : {converted.get(), soundFrame.get()}) {
        f->format = c->sample_fmt;
        f->sample_rate = kVideoSampleRate;
        av_channel_layout_copy(&f->ch_layout, &c->ch_layout);
        f->nb_samples = f == converted.get() ? kPullChunk : c->frame_size;
        if ((rc = av_frame_get_buffer(f, 0)) < 0) return "cannot allocate sound: " + avError(rc);
    }
    pulled.resize(std::size_t(kPullChunk) * kVideoChannels);
    return "";
}

// ---- pictures -------------------------------------------------------------------------
bool VideoWriter::addFrame(const Image& image) {
    Encoding& e = *enc_;
    if (!e.error.empty() || e.finished) return false;
    if (image.width != e.def.width || image.height != e.def.height)
        return e.fail("a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                      " picture for a " + std::to_string(e.def.width) + "x" +
                      std::to_string(e.def.height) + " video");
    // The sound up to this frame's time first, so the container interleaves in order.
    if (std::string err = e.pullAudio(audioFramesBefore(e.frames, e.def.fps)); !err.empty())
        return e.fail(err);
    AVFrame* f = e.pictureFrame.get();
    if (const int rc = av_frame_make_writable(f); rc < 0)
        return e.fail("cannot allocate a picture: " + avError(rc));
    const std::uint8_t* rows[1] = {image.rgba.data()};
    const int stride[1] = {image.width * 4};
    sws_scale(e.scaler, rows, stride, 0, image.height, f->data, f->linesize);
    f->pts = e.frames;
    if (std::string err = e.picture->encode(f); !err.empty()) return e.fail(err);
    ++e.frames;
    return true;
}

// ---- sound ----------------------------------------------------------------------------
std::string VideoWriter::Encoding::pullAudio(long long until) {
    if (!sound) {
        audioPulled = std::max(audioPulled, until);
        return "";
    }
    while (audioPulled < until) {
        const int n = static_cast<int>(std::min<long long>(until - audioPulled, kPullChunk));
        if (def.source)
            def.source(pulled.data(), static_cast<std::size_t>(n));
        else
            std::fill_n(pulled.begin(), n * kVideoChannels, 0.0f); // a silent track
        audioPulled += n;
        const std::uint8_t* in[1] = {reinterpret_cast<const std::uint8_t*>(pulled.data())};
        const int got = swr_convert(resampler, converted->data, kPullChunk, in, n);
        if (got < 0) return "cannot convert the sound: " + avError(got);
        if (av_audio_fifo_write(pending, reinterpret_cast<void**>(converted->data), got) < got)
            return "out of memory for the sound";
        if (std::string err = encodeSound(false); !err.empty()) return err;
    }
    return "";
}

std::string VideoWriter::Encoding::encodeSound(bool last) {
    const int frameSize = sound->context()->frame_size;
    while (av_audio_fifo_size(pending) >= frameSize || (last && av_audio_fifo_size(pending) > 0)) {
        const int n = std::min(av_audio_fifo_size(pending), frameSize);
        if (const int rc = av_frame_make_writable(soundFrame.get()); rc < 0)
            return "cannot allocate sound: " + avError(rc);
        soundFrame->nb_samples = n; // the last one may be short: the encoder pads it
        av_audio_fifo_read(pending, reinterpret_cast<void**>(soundFrame->data), n);
        soundFrame->pts = audioEncoded;
        audioEncoded += n;
        if (std::string err = sound->encode(soundFrame.get()); !err.empty()) return err;
    }
    return "";
}

// ---- finish ---------------------------------------------------------------------------
bool VideoWriter::finish() {
    Encoding& e = *enc_;
    if (!e.error.empty() || e.finished) return false;
    std::string err = e.pullAudio(audioFramesBefore(e.frames, e.def.fps));
    if (err.empty() && e.sound) err = e.encodeSound(true);
    if (err.empty() && e.sound) err = e.sound->encode(nullptr);
    if (err.empty()) err = e.picture->encode(nullptr);
    if (err.empty())
        if (const int rc = av_write_trailer(e.format); rc < 0)
            err = "cannot write the index: " + avError(rc);
    if (err.empty())
        if (const int rc = avio_closep(&e.format->pb); rc < 0)
            err = "cannot write '" + e.temp + "': " + avError(rc);
    e.fileOpen = e.fileOpen && !err.empty(); // closed: the destructor must not close again
    if (err.empty()) {
        std::error_code ec;
        std::filesystem::rename(e.temp, e.def.file, ec);
        if (ec) {
            std::filesystem::remove(e.temp, ec);
            err = "cannot rename '" + e.temp + "' into place: " + ec.message();
        }
    }
    if (!err.empty()) return e.fail(err);
    e.finished = true;
    return true;
}

} // namespace ui
