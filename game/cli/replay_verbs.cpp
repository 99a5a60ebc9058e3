// artillery run and artillery replay verify: headless simulation and replay checking.
#include "game/cli/verbs.h"

#include "game/audio/sound_track.h"
#include "game/files/json_reader.h"
#include "game/headless.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <memory>
#include <optional>
#include <ostream>

namespace game::cli {

namespace {

nlohmann::json eventsJson(const std::vector<GameEvent>& events) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& e : events) {
        nlohmann::json j{{"tick", e.tick}, {"kind", eventName(e.kind)}, {"player", e.player}};
        if (e.where != phys::Vec2{}) j["where"] = {e.where.x, e.where.y};
        j["value"] = e.value;
        if (!e.text.empty()) j["text"] = e.text;
        if (!e.model.empty()) j["model"] = e.model;
        if (e.closedFormErrorM) j["closed_form_error_m"] = *e.closedFormErrorM;
        out.push_back(j);
    }
    return out;
}

} // namespace

int runReplayVerify(const Args& args, std::ostream& out) {
    args.text("<positional>");
    const bool json = args.flag("json");
    args.rejectUnknown();
    const auto& pos = args.positionals();
    if (pos.size() != 2 || pos[0] != "verify")
        args.fail("usage is: artillery replay verify FILE [--json]");
    const std::string file = pos[1];
    Replay r;
    Level level;
    try {
        r = loadReplay(file);
        level = levelForReplay(file, r);
    } catch (const LoadError& e) {
        throw UsageError(e.what());
    }
    const VerifyResult v = verifyReplay(level, r);
    if (json) {
        nlohmann::json j{{"ok", v.ok},
                         {"ticks", v.ticks},
                         {"checkpoints", v.checkpoints},
                         {"first_divergent_tick", v.firstDivergentTick ? nlohmann::json(*v.firstDivergentTick)
                                                                      : nlohmann::json(nullptr)},
                         {"final_hash", hex(v.finalHash)},
                         {"warnings", v.ignored}};
        if (!v.ok) j["diverged"] = v.diverged;
        out << j.dump() << "\n";
    } else if (v.ok) {
        out << "ok: " << file << " re-simulates bit for bit (" << v.ticks << " ticks, "
            << v.checkpoints << " checkpoints, final hash " << hex(v.finalHash) << ")\n";
    } else {
        out << "DIVERGED: " << file << " first differs at tick " << *v.firstDivergentTick
            << " in " << v.diverged << " (checked " << v.checkpoints << " checkpoints)\n";
    }
    // A command the match refused changed nothing: the replay may verify, but it does
    // not do what it seems to say (a weapon the level lacks, a fire out of turn).
    if (!json)
        for (const std::string& w : v.ignored)
            out << "warning: " << file << ": " << w << "\n";
    return v.ok ? kOk : kCheckFailed;
}

int runRun(const Args& args, std::ostream& out) { return runHeadlessVerb(args, out, nullptr); }

namespace {

/// What `artillery run` was asked for, read and checked before anything is simulated.
struct RunRequest {
    std::string levelFile;
    std::optional<std::string> replayFile, commandsFile, png, video, record, audioFile;
    bool hasTicks = false;
    long long ticks = 0, every = 60, fps = 30;
    bool audio = true, hud = true, autoplay = false, json = false;
    std::string difficulty;
    int width = 0, height = 0;
};

RunRequest readRunOptions(const Args& args, const FrameSinkFactory* sinks,
                          const VideoSinkFactory* videos) {
    RunRequest q;
    args.text("<positional>");
    q.replayFile = args.text("replay");
    q.commandsFile = args.text("commands");
    q.hasTicks = args.has("ticks");
    q.ticks = args.integer("ticks", 0, 1, static_cast<long long>(kMaxRunTicks));
    q.png = args.text("png");
    q.every = args.integer("every", 60, 1, 1000000);
    q.video = args.text("video");
    q.fps = args.integer("fps", 30, 1, 60);
    q.audio = !args.flag("no-audio");
    const std::string size = args.text("size", "1280x720");
    q.record = args.text("record");
    q.audioFile = args.text("audio");
    q.difficulty = args.text("difficulty", "normal");
    q.hud = !args.flag("no-hud");
    q.autoplay = args.flag("autoplay");
    q.json = args.flag("json");
    args.rejectUnknown();
    if (args.positionals().size() != 1) args.fail("name one level file");
    q.levelFile = args.positionals()[0];
    if (q.replayFile && q.commandsFile) args.fail("give --replay or --commands, not both");
    if (q.replayFile && q.autoplay) args.fail("--autoplay plays new turns; a --replay already has its turns");
    if (!difficultyFromName(q.difficulty)) args.fail("--difficulty expects easy, normal or hard, got '" + q.difficulty + "'");
    if (std::sscanf(size.c_str(), "%dx%d", &q.width, &q.height) != 2 || q.width < 16 ||
        q.height < 16 || q.width > 8192 || q.height > 8192)
        args.fail("--size expects WxH between 16x16 and 8192x8192, got '" + size + "'");
    if (q.png && !sinks) args.fail("--png needs the renderer, which this build of the verb lacks");
    if (q.png && q.video) args.fail("give --png or --video, not both");
    if (!q.video && (args.has("fps") || !q.audio))
        args.fail("--fps and --no-audio describe a video; add --video FILE");
    if (q.video && !videos)
        args.fail("--video needs the renderer, which this build of the verb lacks");
    if (q.audioFile)
        if (const std::string why = audio::checkWavFile(*q.audioFile); !why.empty()) args.fail(why);
    return q;
}

/// Every file the run will write can be written: refused now, not after the simulation.
void checkRunOutputs(const Args& args, const RunRequest& q) {
    if (q.record) requireWritableFile(args, "record", *q.record);
    if (q.audioFile) requireWritableFile(args, "audio", *q.audioFile);
    if (q.video) requireWritableFile(args, "video", *q.video);
    if (q.png) requireWritableFolder(args, "png", *q.png, true);
}

/// The level, and the commands of the replay or script with the session they ask for.
HeadlessOptions loadRunInputs(const RunRequest& q, Level& level) {
    HeadlessOptions o;
    o.session.difficulty = *difficultyFromName(q.difficulty);
    o.session.autoplay = q.autoplay;
    try {
        level = loadLevel(q.levelFile);
        if (q.replayFile) {
            const Replay r = loadReplay(*q.replayFile);
            if (r.levelHash != level.contentHash)
                throw LoadError(*q.replayFile, "$.level.content_hash",
                                "this replay was recorded on another level or another version of it "
                                "(replay: " + r.levelHash + ", " + q.levelFile + ": " +
                                    level.contentHash + ")");
            o.commands = r.commands;
            o.session.hotseat = true; // the computer's turns are in the recording
            o.session.difficulty = *difficultyFromName(r.difficulty);
            o.session.cpuSeed = r.cpuSeed;
            if (!q.hasTicks) o.ticks = r.ticks;
        }
        if (q.commandsFile) o.commands = loadCommands(*q.commandsFile);
    } catch (const LoadError& e) {
        throw UsageError(e.what());
    }
    if (q.hasTicks) o.ticks = static_cast<std::uint64_t>(q.ticks);
    if (q.record) o.session.recordFile = *q.record;
    return o;
}

/// The video encoder for --video, with its own synthesizer for the sound track: heard
/// after every tick and pulled by the encoder in step with the pictures.
std::unique_ptr<VideoSink> openVideo(const Args& args, const RunRequest& q,
                                     const VideoSinkFactory& videos,
                                     audio::Synthesizer& videoSound) {
    VideoRequest request;
    request.file = *q.video;
    request.width = q.width;
    request.height = q.height;
    request.fps = static_cast<int>(q.fps);
    request.hud = q.hud;
    request.audio = q.audio;
    if (q.audio) {
        request.afterTick = [&videoSound](const Match& m) { videoSound.observe(m); };
        request.sound = [&videoSound](float* interleaved, std::size_t frames) {
            videoSound.render(interleaved, frames);
        };
    }
    std::string why;
    std::unique_ptr<VideoSink> sink = videos(request, why);
    if (!sink) args.fail(why);
    return sink;
}

void printRunJson(std::ostream& out, const RunRequest& q, const HeadlessSummary& s,
                  const VideoSink* video, const audio::SoundTrack& soundTrack) {
    nlohmann::json j{{"ticks", s.ticks},     {"final_hash", hex(s.finalHash)}, {"score", s.score},
                     {"shots", s.shots},     {"over", s.over},                 {"winner", s.winner},
                     {"events", eventsJson(s.events)}, {"sim_ms", s.simMs},   {"render_ms", s.renderMs}};
    if (video)
        j["video"] = {{"file", *q.video},
                      {"codec", video->codec()},
                      {"frames", video->frames()},
                      {"seconds", video->seconds()}};
    if (q.audioFile)
        j["audio"] = {{"file", *q.audioFile},
                      {"frames", soundTrack.frames()},
                      {"seconds", soundTrack.seconds()}};
    out << j.dump() << "\n";
}

void printRunText(std::ostream& out, const RunRequest& q, const Level& level,
                  const HeadlessSummary& s, const VideoSink* video,
                  const audio::SoundTrack& soundTrack) {
    char line[200];
    std::snprintf(
        line, sizeof line, "%s: %llu ticks (%.1f s simulated) in %.1f ms%s\n", level.name.c_str(),
        static_cast<unsigned long long>(s.ticks), static_cast<double>(s.ticks) * (1.0 / 120.0),
        s.simMs,
        q.png || q.video
            ? (", rendering " + std::to_string(static_cast<int>(s.renderMs)) + " ms").c_str()
            : "");
    out << line;
    for (const auto& e : s.events) {
        if (e.kind == EventKind::Refused || e.kind == EventKind::Bounce) continue;
        std::snprintf(line, sizeof line, "  tick %6llu  %-15s player %d  %g %s\n",
                      static_cast<unsigned long long>(e.tick), eventName(e.kind), e.player, e.value,
                      e.text.c_str());
        out << line;
    }
    std::snprintf(line, sizeof line, "score %d, %d shot(s), %s, final hash %s\n", s.score, s.shots,
                  s.over ? "match over" : "match still on", hex(s.finalHash).c_str());
    out << line;
    if (q.record) out << "recorded " << *q.record << "\n";
    if (q.png) out << "frames in " << *q.png << "\n";
    if (q.audioFile) {
        std::snprintf(line, sizeof line, "sound in %s (16-bit PCM WAV, stereo 48 kHz, %.2f s)\n",
                      q.audioFile->c_str(), soundTrack.seconds());
        out << line;
    }
    if (video) {
        std::snprintf(line, sizeof line, "video in %s (%s, %lld frames, %.2f s)\n", q.video->c_str(),
                      video->codec(), video->frames(), video->seconds());
        out << line;
    }
}

/// A write that fails once the run has started (the replay at a turn's end, a frame, the
/// sound track, the video) is a failure of the work, exit 3: the input was fine.
[[noreturn]] void failedWhileRunning(const std::string& what, const std::string& why) {
    throw WorkError("artillery run: " + what + ": " + why);
}

} // namespace

int runHeadlessVerb(const Args& args, std::ostream& out, const FrameSinkFactory* sinks,
                    const VideoSinkFactory* videos) {
    const RunRequest q = readRunOptions(args, sinks, videos);
    checkRunOutputs(args, q);
    Level level;
    HeadlessOptions o = loadRunInputs(q, level);
    std::unique_ptr<FrameSink> sink;
    if (q.png) {
        std::string why;
        sink = (*sinks)(*q.png, q.width, q.height, q.hud, why);
        if (!sink) args.fail("cannot render: " + why);
        o.sink = sink.get();
        o.every = static_cast<std::uint64_t>(q.every);
    }
    audio::SoundTrack soundTrack;
    if (q.audioFile) o.listeners.push_back(&soundTrack);
    audio::Synthesizer videoSound;
    std::unique_ptr<VideoSink> videoSink;
    if (q.video) {
        videoSink = openVideo(args, q, *videos, videoSound);
        o.sink = videoSink.get();
        o.every = 1; // the sink keeps the video's clock and draws when a frame is due
    }
    HeadlessSummary s;
    try {
        s = runHeadless(level, o);
    } catch (const std::exception& e) {
        failedWhileRunning("the run stopped", e.what());
    }
    if (videoSink)
        if (const std::string why = videoSink->finish(); !why.empty())
            failedWhileRunning("the video was not written", why);
    if (q.audioFile) {
        try {
            soundTrack.write(*q.audioFile);
        } catch (const std::exception& e) {
            failedWhileRunning("the sound track was not written", e.what());
        }
    }
    if (q.json)
        printRunJson(out, q, s, videoSink.get(), soundTrack);
    else
        printRunText(out, q, level, s, videoSink.get(), soundTrack);
    return kOk;
}

} // namespace game::cli
