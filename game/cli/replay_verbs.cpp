// artillery run and artillery replay verify: headless simulation and replay checking.
#include "game/cli/verbs.h"

#include "game/audio/sound_track.h"
#include "game/files/json_reader.h"
#include "game/headless.h"

#include <nlohmann/json.hpp>

#include <cstdio>
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
                         {"final_hash", hex(v.finalHash)}};
        if (!v.ok) j["diverged"] = v.diverged;
        out << j.dump() << "\n";
    } else if (v.ok) {
        out << "ok: " << file << " re-simulates bit for bit (" << v.ticks << " ticks, "
            << v.checkpoints << " checkpoints, final hash " << hex(v.finalHash) << ")\n";
    } else {
        out << "DIVERGED: " << file << " first differs at tick " << *v.firstDivergentTick
            << " in " << v.diverged << " (checked " << v.checkpoints << " checkpoints)\n";
    }
    return v.ok ? kOk : kCheckFailed;
}

int runRun(const Args& args, std::ostream& out) { return runHeadlessVerb(args, out, nullptr); }

int runHeadlessVerb(const Args& args, std::ostream& out, const FrameSinkFactory* sinks,
                    const VideoSinkFactory* videos) {
    args.text("<positional>");
    const auto replayFile = args.text("replay");
    const auto commandsFile = args.text("commands");
    const bool hasTicks = args.has("ticks");
    const long long ticks = args.integer("ticks", 0, 1, static_cast<long long>(kMaxRunTicks));
    const auto png = args.text("png");
    const long long every = args.integer("every", 60, 1, 1000000);
    const auto video = args.text("video");
    const long long fps = args.integer("fps", 30, 1, 60);
    const bool audio = !args.flag("no-audio");
    const std::string size = args.text("size", "1280x720");
    const auto record = args.text("record");
    const auto audioFile = args.text("audio");
    const std::string difficulty = args.text("difficulty", "normal");
    const bool hud = !args.flag("no-hud");
    const bool autoplay = args.flag("autoplay");
    const bool json = args.flag("json");
    args.rejectUnknown();
    if (args.positionals().size() != 1) args.fail("name one level file");
    if (replayFile && commandsFile) args.fail("give --replay or --commands, not both");
    if (replayFile && autoplay) args.fail("--autoplay plays new turns; a --replay already has its turns");
    if (!difficultyFromName(difficulty)) args.fail("--difficulty expects easy, normal or hard, got '" + difficulty + "'");
    int width = 0, height = 0;
    if (std::sscanf(size.c_str(), "%dx%d", &width, &height) != 2 || width < 16 || height < 16 ||
        width > 8192 || height > 8192)
        args.fail("--size expects WxH between 16x16 and 8192x8192, got '" + size + "'");
    if (png && !sinks) args.fail("--png needs the renderer, which this build of the verb lacks");
    if (png && video) args.fail("give --png or --video, not both");
    if (!video && (args.has("fps") || !audio))
        args.fail("--fps and --no-audio describe a video; add --video FILE");
    if (video && !videos)
        args.fail("--video needs the renderer, which this build of the verb lacks");
    if (audioFile)
        if (const std::string why = audio::checkWavFile(*audioFile); !why.empty()) args.fail(why);

    HeadlessOptions o;
    o.session.difficulty = *difficultyFromName(difficulty);
    o.session.autoplay = autoplay;
    Level level;
    try {
        level = loadLevel(args.positionals()[0]);
        if (replayFile) {
            const Replay r = loadReplay(*replayFile);
            if (r.levelHash != level.contentHash)
                throw LoadError(*replayFile, "$.level.content_hash",
                                "this replay was recorded on another level or another version of it "
                                "(replay: " + r.levelHash + ", " + args.positionals()[0] + ": " +
                                    level.contentHash + ")");
            o.commands = r.commands;
            o.session.hotseat = true; // the computer's turns are in the recording
            o.session.difficulty = *difficultyFromName(r.difficulty);
            o.session.cpuSeed = r.cpuSeed;
            if (!hasTicks) o.ticks = r.ticks;
        }
        if (commandsFile) o.commands = loadCommands(*commandsFile);
    } catch (const LoadError& e) {
        throw UsageError(e.what());
    }
    if (hasTicks) o.ticks = static_cast<std::uint64_t>(ticks);
    if (record) o.session.recordFile = *record;
    std::unique_ptr<FrameSink> sink;
    if (png) {
        std::string why;
        sink = (*sinks)(*png, width, height, hud, why);
        if (!sink) args.fail("cannot render: " + why);
        o.sink = sink.get();
        o.every = static_cast<std::uint64_t>(every);
    }
    audio::SoundTrack soundTrack;
    if (audioFile) o.listeners.push_back(&soundTrack);
    // The video's sound: a synthesizer of its own, heard after every tick and pulled by
    // the encoder in step with the pictures.
    audio::Synthesizer videoSound;
    std::unique_ptr<VideoSink> videoSink;
    if (video) {
        VideoRequest request;
        request.file = *video;
        request.width = width;
        request.height = height;
        request.fps = static_cast<int>(fps);
        request.hud = hud;
        request.audio = audio;
        if (audio) {
            request.afterTick = [&videoSound](const Match& m) { videoSound.observe(m); };
            request.sound = [&videoSound](float* interleaved, std::size_t frames) {
                videoSound.render(interleaved, frames);
            };
        }
        std::string why;
        videoSink = (*videos)(request, why);
        if (!videoSink) args.fail(why);
        o.sink = videoSink.get();
        o.every = 1; // the sink keeps the video's clock and draws when a frame is due
    }
    const HeadlessSummary s = runHeadless(level, o);
    if (videoSink)
        if (const std::string why = videoSink->finish(); !why.empty()) throw UsageError(why);
    if (audioFile) {
        try {
            soundTrack.write(*audioFile);
        } catch (const std::exception& e) {
            throw UsageError(e.what());
        }
    }
    if (json) {
        nlohmann::json j{{"ticks", s.ticks},     {"final_hash", hex(s.finalHash)}, {"score", s.score},
                         {"shots", s.shots},     {"over", s.over},                 {"winner", s.winner},
                         {"events", eventsJson(s.events)}, {"sim_ms", s.simMs},   {"render_ms", s.renderMs}};
        if (videoSink)
            j["video"] = {{"file", *video},
                          {"codec", videoSink->codec()},
                          {"frames", videoSink->frames()},
                          {"seconds", videoSink->seconds()}};
        if (audioFile)
            j["audio"] = {{"file", *audioFile},
                          {"frames", soundTrack.frames()},
                          {"seconds", soundTrack.seconds()}};
        out << j.dump() << "\n";
        return kOk;
    }
    char line[200];
    std::snprintf(
        line, sizeof line, "%s: %llu ticks (%.1f s simulated) in %.1f ms%s\n", level.name.c_str(),
        static_cast<unsigned long long>(s.ticks), static_cast<double>(s.ticks) * (1.0 / 120.0),
        s.simMs,
        png || video
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
    if (record) out << "recorded " << *record << "\n";
    if (png) out << "frames in " << *png << "\n";
    if (audioFile) {
        std::snprintf(line, sizeof line, "sound in %s (16-bit PCM WAV, stereo 48 kHz, %.2f s)\n",
                      audioFile->c_str(), soundTrack.seconds());
        out << line;
    }
    if (videoSink) {
        std::snprintf(line, sizeof line, "video in %s (%s, %lld frames, %.2f s)\n", video->c_str(),
                      videoSink->codec(), videoSink->frames(), videoSink->seconds());
        out << line;
    }
    return kOk;
}

} // namespace game::cli
