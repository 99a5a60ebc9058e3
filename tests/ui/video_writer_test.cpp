// Videos written by ui::VideoWriter and `run --video`'s frame sink, decoded back with
// libavformat and libavcodec: the stream's codec, size and frame count, the duration,
// and a sine tone put in that comes back out at its frequency (counted by its upward zero
// crossings, to 1 %) on the right channel. Bad names and folders fail with one message
// and leave no file; the match's hash is the same with a video being written as without;
// the replay viewer's export (the run verb in a child) carries the match's sound track.
#include "game/headless.h"
#include "game/level.h"
#include "game/replay.h"
#include "ui/video/video_export.h"
#include "ui/video/video_frames.h"
#include "ui/video/video_writer.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string sourceDir() {
    return fs::path(__FILE__).parent_path().parent_path().parent_path().string();
}

/// A folder of this process's own for the videos, removed when the tests end.
struct ScratchFolder {
    fs::path dir = fs::temp_directory_path() /
                   ("artillery_video_test_" + std::to_string(static_cast<long long>(getpid())));
    ScratchFolder() { fs::create_directories(dir); }
    ~ScratchFolder() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

std::string scratch(const std::string& name) {
    static const ScratchFolder folder;
    return (folder.dir / name).string();
}

/// What a decoder finds in a file.
struct Decoded {
    int videoStreams = 0;
    int audioStreams = 0;
    std::string codec;
    int width = 0;
    int height = 0;
    long long frames = 0;
    double seconds = 0.0; ///< the container's duration
    int sampleRate = 0;
    int channels = 0;
    std::vector<float> left, right;
};

Decoded decode(const std::string& file) {
    Decoded d;
    AVFormatContext* fmt = nullptr;
    if (avformat_open_input(&fmt, file.c_str(), nullptr, nullptr) < 0) {
        ADD_FAILURE() << "cannot open " << file;
        return d;
    }
    avformat_find_stream_info(fmt, nullptr);
    d.seconds = fmt->duration > 0 ? static_cast<double>(fmt->duration) / AV_TIME_BASE : 0.0;
    std::vector<AVCodecContext*> decoders(fmt->nb_streams, nullptr);
    for (unsigned i = 0; i < fmt->nb_streams; ++i) {
        const AVCodecParameters* par = fmt->streams[i]->codecpar;
        if (par->codec_type == AVMEDIA_TYPE_VIDEO) {
            ++d.videoStreams;
            d.codec = avcodec_get_name(par->codec_id);
            d.width = par->width;
            d.height = par->height;
        } else if (par->codec_type == AVMEDIA_TYPE_AUDIO) {
            ++d.audioStreams;
            d.sampleRate = par->sample_rate;
            d.channels = par->ch_layout.nb_channels;
        } else {
            continue;
        }
        AVCodecContext* c = avcodec_alloc_context3(avcodec_find_decoder(par->codec_id));
        avcodec_parameters_to_context(c, par);
        c->pkt_timebase = fmt->streams[i]->time_base;
        EXPECT_EQ(avcodec_open2(c, c->codec, nullptr), 0);
        decoders[i] = c;
    }
    AVPacket* pkt = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    auto drain = [&](AVCodecContext* c) {
        while (avcodec_receive_frame(c, frame) == 0) {
            if (c->codec_type == AVMEDIA_TYPE_VIDEO) {
                ++d.frames;
            } else {
                EXPECT_EQ(frame->format, AV_SAMPLE_FMT_FLTP); // the AAC decoder's output
                const float* l = reinterpret_cast<const float*>(frame->data[0]);
                const float* r = reinterpret_cast<const float*>(frame->data[1]);
                d.left.insert(d.left.end(), l, l + frame->nb_samples);
                d.right.insert(d.right.end(), r, r + frame->nb_samples);
            }
            av_frame_unref(frame);
        }
    };
    while (av_read_frame(fmt, pkt) >= 0) {
        if (AVCodecContext* c = decoders[pkt->stream_index]) {
            avcodec_send_packet(c, pkt);
            drain(c);
        }
        av_packet_unref(pkt);
    }
    for (AVCodecContext* c : decoders) {
        if (!c) continue;
        avcodec_send_packet(c, nullptr);
        drain(c);
        avcodec_free_context(&c);
    }
    av_frame_free(&frame);
    av_packet_free(&pkt);
    avformat_close_input(&fmt);
    return d;
}

/// The frequency of a tone from its upward zero crossings between `from` and `to`
/// seconds: whole periods between the first and last crossing over the time between
/// them, each crossing placed by linear interpolation between its two samples.
double toneFrequency(const std::vector<float>& s, double from, double to) {
    const auto i0 = static_cast<std::size_t>(from * ui::kVideoSampleRate);
    const auto i1 = std::min(s.size(), static_cast<std::size_t>(to * ui::kVideoSampleRate));
    double first = -1.0, last = -1.0;
    int crossings = 0;
    for (std::size_t i = i0 + 1; i < i1; ++i) {
        if (s[i - 1] < 0.0f && s[i] >= 0.0f) {
            const double t =
                (static_cast<double>(i - 1) + s[i - 1] / (s[i - 1] - s[i])) / ui::kVideoSampleRate;
            if (first < 0.0) first = t;
            last = t;
            ++crossings;
        }
    }
    if (crossings < 2) return 0.0;
    return (crossings - 1) / (last - first);
}

/// A 440 Hz tone on the left and 660 Hz on the right, samples counted from the start.
struct Tone {
    long long n = 0;
    void operator()(float* out, std::size_t frames) {
        for (std::size_t i = 0; i < frames; ++i, ++n) {
            const double t = static_cast<double>(n) / ui::kVideoSampleRate;
            out[2 * i] = static_cast<float>(0.5 * std::sin(2.0 * std::numbers::pi * 440.0 * t));
            out[2 * i + 1] = static_cast<float>(0.5 * std::sin(2.0 * std::numbers::pi * 660.0 * t));
        }
    }
};

/// A picture that changes every frame: a bar sweeping across a gradient.
ui::Image testPicture(int w, int h, int k) {
    ui::Image img;
    img.width = w;
    img.height = h;
    img.rgba.resize(std::size_t(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = &img.rgba[(std::size_t(y) * w + x) * 4];
            const bool bar = (x - 3 * k) % w >= 0 && (x - 3 * k) % w < 8;
            p[0] = bar ? 255 : static_cast<std::uint8_t>(x * 255 / w);
            p[1] = bar ? 255 : static_cast<std::uint8_t>(y * 255 / h);
            p[2] = 96;
            p[3] = 255;
        }
    return img;
}

std::string writeVideo(ui::VideoDef def, int frames) {
    std::string why;
    auto writer = ui::VideoWriter::open(def, why);
    EXPECT_NE(writer, nullptr) << why;
    if (!writer) return "";
    for (int k = 0; k < frames; ++k)
        EXPECT_TRUE(writer->addFrame(testPicture(def.width, def.height, k))) << writer->error();
    EXPECT_TRUE(writer->finish()) << writer->error();
    EXPECT_EQ(writer->frames(), frames);
    EXPECT_DOUBLE_EQ(writer->seconds(), static_cast<double>(frames) / def.fps);
    // Audio is counted to the end of the last frame: exactly frames * 48000 / fps.
    EXPECT_EQ(writer->audioFrames(), ui::audioFramesBefore(frames, def.fps));
    return writer->codec();
}

bool haveH264() {
    return avcodec_find_encoder_by_name("libx264") != nullptr;
}

TEST(VideoWriter, Mp4HoldsThePicturesAndTheToneAtItsFrequency) {
    ui::VideoDef def;
    def.file = scratch("tone.mp4");
    def.width = 160;
    def.height = 90;
    def.fps = 30;
    def.source = Tone{};
    const std::string codec = writeVideo(def, 60); // 2 s
    EXPECT_EQ(codec, haveH264() ? "h264" : "mpeg4");
    EXPECT_FALSE(fs::exists(def.file + ".part"));

    const Decoded d = decode(def.file);
    EXPECT_EQ(d.videoStreams, 1);
    EXPECT_EQ(d.codec, codec);
    EXPECT_EQ(d.width, 160);
    EXPECT_EQ(d.height, 90);
    EXPECT_EQ(d.frames, 60);
    EXPECT_NEAR(d.seconds, 2.0, 1.0 / 30.0);
    ASSERT_EQ(d.audioStreams, 1);
    EXPECT_EQ(d.sampleRate, 48000);
    EXPECT_EQ(d.channels, 2);
    // 2 s of sound, give or take the encoder's last (padded) 1024-sample frame.
    EXPECT_NEAR(static_cast<double>(d.left.size()), 96000.0, 1024.0);
    EXPECT_NEAR(toneFrequency(d.left, 0.25, 1.75), 440.0, 4.4);
    EXPECT_NEAR(toneFrequency(d.right, 0.25, 1.75), 660.0, 6.6);
}

TEST(VideoWriter, Mpeg4IsTheFallbackCodec) {
    ui::VideoDef def;
    def.file = scratch("fallback.mp4");
    def.width = 128;
    def.height = 72;
    def.fps = 24;
    def.mpeg4 = true;
    def.source = Tone{};
    EXPECT_EQ(writeVideo(def, 24), "mpeg4");
    const Decoded d = decode(def.file);
    EXPECT_EQ(d.codec, "mpeg4");
    EXPECT_EQ(d.frames, 24);
    EXPECT_NEAR(d.seconds, 1.0, 1.0 / 24.0);
    EXPECT_NEAR(toneFrequency(d.left, 0.2, 0.8), 440.0, 4.4);
}

TEST(VideoWriter, WithoutASourceTheTrackIsSilentAndNoAudioLeavesItOut) {
    ui::VideoDef def;
    def.file = scratch("silent.mp4");
    def.width = 64;
    def.height = 48;
    def.fps = 10;
    writeVideo(def, 10);
    const Decoded silent = decode(def.file);
    ASSERT_EQ(silent.audioStreams, 1);
    ASSERT_GT(silent.left.size(), 40000u);
    float loudest = 0.0f;
    for (std::size_t i = 0; i < silent.left.size(); ++i)
        loudest = std::max({loudest, std::abs(silent.left[i]), std::abs(silent.right[i])});
    EXPECT_EQ(loudest, 0.0f);

    def.file = scratch("mute.mp4");
    def.audio = false;
    writeVideo(def, 10);
    const Decoded mute = decode(def.file);
    EXPECT_EQ(mute.videoStreams, 1);
    EXPECT_EQ(mute.audioStreams, 0);
    EXPECT_EQ(mute.frames, 10);
}

TEST(VideoWriter, GifHasEveryFrameAndNoSound) {
    ui::VideoDef def;
    def.file = scratch("sweep.gif");
    def.width = 65; // odd sizes are fine without yuv420p
    def.height = 47;
    def.fps = 10;
    def.source = Tone{};
    EXPECT_EQ(writeVideo(def, 12), "gif");
    const Decoded d = decode(def.file);
    EXPECT_EQ(d.videoStreams, 1);
    EXPECT_EQ(d.audioStreams, 0);
    EXPECT_EQ(d.codec, "gif");
    EXPECT_EQ(d.width, 65);
    EXPECT_EQ(d.height, 47);
    EXPECT_EQ(d.frames, 12);
}

TEST(VideoWriter, BadNamesSizesAndFoldersAreRefusedWithOneMessage) {
    std::string why;
    ui::VideoDef def;
    def.width = 64;
    def.height = 48;

    def.file = scratch("clip.avi");
    EXPECT_EQ(ui::VideoWriter::open(def, why), nullptr);
    EXPECT_NE(why.find("must end in .mp4 or .gif"), std::string::npos) << why;
    EXPECT_FALSE(fs::exists(def.file + ".part"));

    def.file = "/nonexistent-folder/for/sure/clip.mp4";
    EXPECT_EQ(ui::VideoWriter::open(def, why), nullptr);
    EXPECT_NE(why.find("cannot write"), std::string::npos) << why;

    def.file = scratch("odd.mp4");
    def.width = 65;
    EXPECT_EQ(ui::VideoWriter::open(def, why), nullptr);
    EXPECT_NE(why.find("even"), std::string::npos) << why;

    def.width = 64;
    def.fps = 61;
    EXPECT_EQ(ui::VideoWriter::open(def, why), nullptr);
    EXPECT_NE(why.find("1..60"), std::string::npos) << why;
    EXPECT_EQ(why.find('\n'), std::string::npos) << why;
}

TEST(VideoWriter, AnUnfinishedVideoLeavesNoFile) {
    ui::VideoDef def;
    def.file = scratch("dropped.mp4");
    def.width = 64;
    def.height = 48;
    std::string why;
    {
        auto writer = ui::VideoWriter::open(def, why);
        ASSERT_NE(writer, nullptr) << why;
        EXPECT_TRUE(fs::exists(def.file + ".part"));
        EXPECT_TRUE(writer->addFrame(testPicture(64, 48, 0)));
        EXPECT_FALSE(writer->addFrame(testPicture(32, 48, 1))); // the wrong size
        EXPECT_NE(writer->error().find("32x48"), std::string::npos) << writer->error();
        EXPECT_FALSE(writer->finish());
    }
    EXPECT_FALSE(fs::exists(def.file));
    EXPECT_FALSE(fs::exists(def.file + ".part"));
}

/// The castle replay's first second through `sink` (or none).
game::HeadlessSummary castleSecond(game::FrameSink* sink) {
    const std::string file = sourceDir() + "/tests/replays/05_castle.replay.json";
    const game::Replay r = game::loadReplay(file);
    const game::Level level = game::levelForReplay(file, r);
    game::HeadlessOptions o;
    o.commands = r.commands;
    o.session.hotseat = true;
    o.session.cpuSeed = r.cpuSeed;
    o.ticks = 120; // 1 s at 120 Hz
    o.sink = sink;
    o.every = 1;
    return game::runHeadless(level, o);
}

TEST(VideoFrameSink, DrawsAFrameEachTimeTheVideoClockPassesAndLeavesTheHashAlone) {
    game::cli::VideoRequest request;
    request.file = scratch("castle.mp4");
    request.width = 128;
    request.height = 72;
    request.fps = 30;
    int ticksSeen = 0;
    request.afterTick = [&](const game::Match&) { ++ticksSeen; };
    request.sound = Tone{};
    std::string why;
    auto sink = ui::VideoFrameSink::create(request, ui::HeadlessBackend::Auto, why);
    ASSERT_NE(sink, nullptr) << why;
    const game::HeadlessSummary with = castleSecond(sink.get());
    ASSERT_EQ(sink->finish(), "");
    const game::HeadlessSummary without = castleSecond(nullptr);
    EXPECT_EQ(with.finalHash, without.finalHash);
    EXPECT_EQ(ticksSeen, 120);
    // 1 s at 30 fps: frames at 0, 1/30, ..., 29/30 s (the one at 1 s would come after).
    EXPECT_EQ(sink->frames(), 30);
    EXPECT_DOUBLE_EQ(sink->seconds(), 1.0);
    const Decoded d = decode(request.file);
    EXPECT_EQ(d.frames, 30);
    EXPECT_EQ(d.width, 128);
    EXPECT_NEAR(d.seconds, 1.0, 1.0 / 30.0);
    EXPECT_NEAR(toneFrequency(d.left, 0.2, 0.8), 440.0, 4.4);
}

TEST(VideoFrameSink, FramesThatAreNotAWholeNumberOfTicksKeepTime) {
    game::cli::VideoRequest request;
    request.file = scratch("castle.gif");
    request.width = 64;
    request.height = 36;
    request.fps = 50; // 120 ticks per second of 1/120 s: 2.4 ticks a frame
    std::string why;
    auto sink = ui::VideoFrameSink::create(request, ui::HeadlessBackend::Auto, why);
    ASSERT_NE(sink, nullptr) << why;
    castleSecond(sink.get());
    ASSERT_EQ(sink->finish(), "");
    EXPECT_EQ(sink->frames(), 50); // ceil(1 s * 50 fps)
    EXPECT_EQ(decode(request.file).frames, 50);
}

/// Root mean square of a channel between two times (s) at 48 kHz.
double rms(const std::vector<float>& channel, double from, double to) {
    const auto a = std::min(channel.size(), static_cast<std::size_t>(from * 48000.0));
    const auto b = std::min(channel.size(), static_cast<std::size_t>(to * 48000.0));
    double sum = 0.0;
    for (std::size_t i = a; i < b; ++i) sum += static_cast<double>(channel[i]) * channel[i];
    return b > a ? std::sqrt(sum / static_cast<double>(b - a)) : 0.0;
}

/// Waits for the child process to end (a test's timeout stops a hung one).
ui::VideoExport::State waitFor(ui::VideoExport& e) {
    while (e.poll() == ui::VideoExport::State::Running)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return e.state();
}

TEST(VideoExport, WritesAReplayThroughTheRunVerbInAChildProcess) {
    // A two-second replay: the castle's golden commands for 240 ticks, recorded anew.
    const std::string golden = sourceDir() + "/tests/replays/05_castle.replay.json";
    const game::Replay r = game::loadReplay(golden);
    const std::string levelFile = fs::absolute(sourceDir() + "/levels/05_castle.json").string();
    const game::Level level = game::loadLevel(levelFile);
    const std::string replay = scratch("castle_second.replay.json");
    game::HeadlessOptions o;
    o.commands = r.commands;
    o.session.hotseat = true;
    o.session.cpuSeed = r.cpuSeed;
    o.session.recordFile = replay;
    o.ticks = 240;
    game::runHeadless(level, o);

    ui::VideoExport exporter;
    const std::string out = scratch("castle_second.mp4");
    ASSERT_TRUE(exporter.start(ARTILLERY_EXE, levelFile, replay, out, {"--size", "96x54"}))
        << exporter.message();
    ASSERT_EQ(waitFor(exporter), ui::VideoExport::State::Done) << exporter.message();
    EXPECT_NE(exporter.message().find("video in"), std::string::npos) << exporter.message();
    const Decoded d = decode(out);
    EXPECT_EQ(d.frames, 60);
    EXPECT_EQ(d.width, 96);
    EXPECT_EQ(d.audioStreams, 1);
    // The track is the match's sound: quiet at first, then the report and the whistle
    // from the shot at tick 180, 1.5 s, once the computer has aimed (windows clear of the
    // AAC encoder's 1024-sample delay).
    ASSERT_EQ(d.sampleRate, 48000);
    EXPECT_LT(rms(d.left, 0.0, 0.25), 0.005); // the blocks settle in silence
    EXPECT_GT(rms(d.left, 1.5, 1.75), 0.03);
    EXPECT_GT(rms(d.right, 1.5, 1.75), 0.005);

    const std::string bad = scratch("castle_second.avi");
    ASSERT_TRUE(exporter.start(ARTILLERY_EXE, levelFile, replay, bad));
    ASSERT_EQ(waitFor(exporter), ui::VideoExport::State::Failed);
    EXPECT_NE(exporter.message().find("must end in .mp4 or .gif"), std::string::npos)
        << exporter.message();
    EXPECT_FALSE(fs::exists(bad));
}

} // namespace
