// The sound track: a view of the match that never changes it (the golden replays' hashes),
// sample-exact to the ticks, deterministic to the byte, and loud where the physics is:
// energy right after a shot and at its impact, none before, more for a faster shot or a
// harder impact, on the side of the view where it happened, and never past full scale.
#include "game/audio/sound_track.h"
#include "game/audio/synthesizer.h"
#include "game/audio/wav.h"
#include "game/files/text_file.h"
#include "game/replay.h"

#include "shots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace game;
using namespace game::audio;
namespace fs = std::filesystem;

namespace {
const fs::path kSource = ARTILLERY_SOURCE_DIR;
using shots::cmd;
using shots::level;
using shots::shoot;

/// Steps the match `ticks` times with the track hearing each tick.
void run(Match& m, SoundTrack& track, int ticks) {
    for (int i = 0; i < ticks; ++i) {
        m.step();
        track.frame(m);
    }
}

/// Root mean square of one channel (0 left, 1 right; -1 both) over frames [from, to).
double rms(const std::vector<float>& s, std::int64_t from, std::int64_t to, int channel = -1) {
    const auto frames = static_cast<std::int64_t>(s.size() / 2);
    from = std::clamp<std::int64_t>(from, 0, frames);
    to = std::clamp<std::int64_t>(to, from, frames);
    double sum = 0.0;
    std::int64_t n = 0;
    for (std::int64_t i = from; i < to; ++i)
        for (int c = 0; c < 2; ++c)
            if (channel < 0 || channel == c) {
                const double x = s[static_cast<std::size_t>(2 * i + c)];
                sum += x * x;
                ++n;
            }
    return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

constexpr std::int64_t kTenthSecond = kSampleRate / 10;

std::uint64_t firstTickOf(const std::vector<GameEvent>& events, EventKind kind) {
    for (const GameEvent& e : events)
        if (e.kind == kind) return e.tick;
    return 0;
}

/// A shot from the first cannon of Earth basics after a second of waiting; the track of
/// `seconds` in all.
SoundTrack shotTrack(double speedMps, double seconds = 6.0,
                     std::vector<GameEvent>* events = nullptr) {
    Match m(level("01_earth_basics.json"));
    SoundTrack track;
    run(m, track, 120);
    shoot(m, 45.0, speedMps);
    run(m, track, static_cast<int>(seconds * 120.0) - 120);
    if (events) *events = m.events();
    return track;
}

double peak(const std::vector<float>& s) {
    double p = 0.0;
    for (const float x : s)
        p = std::max(p, static_cast<double>(std::abs(x)));
    return p;
}
} // namespace

// Golden replays with shots, blasts, toppling blocks, splashes and a duel: with the
// synthesizer hearing and rendering every tick, every hash is the recorded one.
TEST(Sound, NeverChangesAGoldenReplaysHashes) {
    for (const char* name : {"01_earth_basics", "05_castle", "08_water", "10_duel"}) {
        SCOPED_TRACE(name);
        const std::string file =
            (kSource / "tests/replays" / (std::string(name) + ".replay.json")).string();
        const Replay r = loadReplay(file);
        Match m(levelForReplay(file, r));
        SoundTrack track;
        std::size_t next = 0, cp = 0, matched = 0;
        while (m.tick() < r.ticks) {
            while (next < r.commands.size() && r.commands[next].tick <= m.tick())
                m.apply(r.commands[next++]);
            m.step();
            track.frame(m);
            while (cp < r.checkpoints.size() && r.checkpoints[cp].tick == m.tick()) {
                ASSERT_EQ(m.hash(), r.checkpoints[cp].hash) << "at tick " << m.tick();
                ++cp;
                ++matched;
            }
        }
        EXPECT_EQ(matched, r.checkpoints.size());
        EXPECT_EQ(hex(m.hash()), hex(r.finalHash));
        EXPECT_GT(rms(track.samples(), 0, static_cast<std::int64_t>(track.frames())), 0.0);
    }
}

// Each kind of shot is heard: the castle's blocks struck and falling, the harbour's splash,
// the targets' chimes, the shells' whistles and blasts.
TEST(Sound, GoldenReplaysSoundTheirEvents) {
    struct Expect {
        const char* name;
        VoiceKind kind;
    };
    for (const Expect e :
         {Expect{"05_castle", VoiceKind::Report}, Expect{"05_castle", VoiceKind::Impact},
          Expect{"05_castle", VoiceKind::Whistle}, Expect{"08_water", VoiceKind::Splash},
          Expect{"01_earth_basics", VoiceKind::Chime}, Expect{"10_duel", VoiceKind::Blast}}) {
        SCOPED_TRACE(std::string(e.name) + " voice " + std::to_string(static_cast<int>(e.kind)));
        const std::string file =
            (kSource / "tests/replays" / (std::string(e.name) + ".replay.json")).string();
        const Replay r = loadReplay(file);
        Match m(levelForReplay(file, r));
        SoundTrack track;
        std::size_t next = 0;
        while (m.tick() < r.ticks) {
            while (next < r.commands.size() && r.commands[next].tick <= m.tick())
                m.apply(r.commands[next++]);
            m.step();
            track.frame(m);
        }
        EXPECT_GT(track.synthesizer().started(e.kind), 0u);
    }
}

// Tick t starts at sample floor(t * 48000 / f): 400 a tick at 120 Hz, and at 144 Hz
// (333.33 a tick) a second of ticks is 48000 samples exactly, also after the rate changed.
TEST(Sound, TicksLandOnExactSamples) {
    Match m(level("01_earth_basics.json"));
    SoundTrack track;
    run(m, track, 120);
    EXPECT_EQ(track.frames(), 48000u);
    EXPECT_EQ(track.synthesizer().sampleOfTick(1), 400);
    Command set = cmd(CommandKind::Set, 0.0, "tick_hz");
    set.value = 144.0;
    ASSERT_EQ(m.apply(set), "");
    run(m, track, 1);
    EXPECT_EQ(track.frames(), 48000u + 333u); // floor(48000 / 144)
    run(m, track, 143);
    EXPECT_EQ(track.frames(), 96000u);
    run(m, track, 144 * 10);
    EXPECT_EQ(track.frames(), 96000u + 480000u);
}

// The report sounds in the tenth of a second after the Fired tick; before it, nothing;
// the impact's tenth of a second is louder than the whistle's just before it.
TEST(Sound, AShotIsHeardWhenItIsFiredAndWhereItLands) {
    std::vector<GameEvent> events;
    const SoundTrack track = shotTrack(35.0, 8.0, &events);
    const std::uint64_t fired = firstTickOf(events, EventKind::Fired);
    ASSERT_EQ(fired, 120u);
    const std::int64_t at = track.synthesizer().sampleOfTick(fired);
    EXPECT_EQ(at, 48000);
    const auto& s = track.samples();
    EXPECT_EQ(rms(s, 0, at), 0.0) << "nothing happens before the shot";
    EXPECT_GT(rms(s, at, at + kTenthSecond), 0.05);
    // The first contact of the shell: the end of its flight.
    std::uint64_t landed = 0;
    for (const GameEvent& e : events)
        if (e.kind == EventKind::Bounce || e.kind == EventKind::Burst ||
            e.kind == EventKind::ShotOver) {
            landed = e.tick;
            break;
        }
    ASSERT_GT(landed, fired + 120) << "a shot at 35 m/s flies for seconds";
    const std::int64_t hit = track.synthesizer().sampleOfTick(landed);
    const double impact = rms(s, hit, hit + kTenthSecond / 2);
    const double flight = rms(s, hit - kTenthSecond, hit - kTenthSecond / 2);
    EXPECT_GT(impact, 0.02);
    EXPECT_GT(impact, 2.0 * flight);
}

// A level where nothing moves renders exact zeros.
TEST(Sound, NothingHappeningIsExactSilence) {
    Match m(level("01_earth_basics.json"));
    SoundTrack track;
    run(m, track, 600);
    ASSERT_EQ(track.frames(), 600u * 400u);
    EXPECT_TRUE(std::all_of(track.samples().begin(), track.samples().end(),
                            [](float x) { return x == 0.0f; }));
}

// The castle's blocks settle as the level opens, some hard enough to ring were they
// struck: nothing has happened yet, so nothing is heard, to the last sample.
TEST(Sound, ALevelSettlingAsItOpensIsSilent) {
    Match m(level("05_castle.json"));
    SoundTrack track;
    run(m, track, 240);
    EXPECT_FALSE(m.stirred());
    EXPECT_TRUE(std::all_of(track.samples().begin(), track.samples().end(),
                            [](float x) { return x == 0.0f; }));
    // The first shot stirs it: its report is heard.
    for (const Command& c : {cmd(CommandKind::Aim, 20.0), cmd(CommandKind::Power, 48.0), cmd(CommandKind::Fire)})
        ASSERT_EQ(m.apply(c), "");
    EXPECT_TRUE(m.stirred());
    const std::size_t before = track.frames();
    run(m, track, 60);
    EXPECT_GT(rms(track.samples(), static_cast<std::int64_t>(before), static_cast<std::int64_t>(track.frames())), 0.01);
}

// The same run gives the same file, byte for byte.
TEST(Sound, TheSameRunGivesTheSameBytes) {
    const SoundTrack a = shotTrack(40.0, 4.0);
    const SoundTrack b = shotTrack(40.0, 4.0);
    const std::string wa = wavBytes(a.samples(), 2, kSampleRate);
    EXPECT_EQ(wa, wavBytes(b.samples(), 2, kSampleRate));
    EXPECT_GT(rms(a.samples(), 0, static_cast<std::int64_t>(a.frames())), 0.0);
}

// A faster shot is a louder report; a harder impact a louder click.
TEST(Sound, LoudnessRisesWithMuzzleSpeedAndClosingSpeed) {
    const SoundTrack slow = shotTrack(20.0, 1.5);
    const SoundTrack fast = shotTrack(50.0, 1.5);
    const std::int64_t at = 48000;
    EXPECT_GT(rms(fast.samples(), at, at + kTenthSecond),
              1.3 * rms(slow.samples(), at, at + kTenthSecond));
    auto energy = [](Voice v) {
        double sum = 0.0;
        while (!v.done()) {
            const double x = v.next();
            sum += x * x;
        }
        return sum;
    };
    EXPECT_GT(energy(impact(Timbre::Wood, 20.0, 0.3)),
              2.0 * energy(impact(Timbre::Wood, 5.0, 0.3)));
    EXPECT_GT(energy(blast(150.0, 3.0)), energy(blast(50.0, 1.5)));
    EXPECT_GT(energy(splash(25.0)), energy(splash(5.0)));
}

// Steel rings long and bright, earth thuds: more energy late, more zero crossings; a
// more elastic bounce rings longer.
TEST(Sound, MaterialsSoundDifferent) {
    auto tail = [](Voice v) { // energy after the first 0.1 s
        double sum = 0.0;
        for (std::int64_t i = 0; !v.done(); ++i) {
            const double x = v.next();
            if (i > kTenthSecond) sum += x * x;
        }
        return sum;
    };
    auto crossings = [](Voice v) {
        int n = 0;
        double last = 0.0;
        for (int i = 0; i < kTenthSecond / 5 && !v.done(); ++i) {
            const double x = v.next();
            n += (x > 0.0) != (last > 0.0);
            last = x;
        }
        return n;
    };
    EXPECT_GT(tail(impact(Timbre::Steel, 10.0, 0.5)),
              10.0 * tail(impact(Timbre::Earth, 10.0, 0.5)));
    EXPECT_GT(crossings(impact(Timbre::Stone, 10.0, 0.5)),
              2 * crossings(impact(Timbre::Earth, 10.0, 0.5)));
    EXPECT_GT(tail(impact(Timbre::Steel, 10.0, 0.9)), 1.5 * tail(impact(Timbre::Steel, 10.0, 0.2)));
    EXPECT_EQ(timbreOf("steel-ball"), Timbre::Steel);
    EXPECT_EQ(timbreOf("wood"), Timbre::Wood);
    EXPECT_EQ(timbreOf("tennis-ball"), Timbre::Soft);
    EXPECT_EQ(timbreOf("earth"), Timbre::Earth);
}

// The cannon stands at x = 15 m of a 240 m wide level: its report is on the left; seen
// from a view whose middle is left of the cannon, it is on the right.
TEST(Sound, EventsArePannedWhereTheyAreInTheView) {
    const SoundTrack track = shotTrack(35.0, 1.5);
    const std::int64_t at = 48000;
    EXPECT_GT(rms(track.samples(), at, at + kTenthSecond, 0),
              2.0 * rms(track.samples(), at, at + kTenthSecond, 1));

    Match m(level("01_earth_basics.json"));
    Synthesizer synth;
    synth.setView({-20.0, 20.0});
    shoot(m, 45.0, 35.0);
    m.step();
    synth.observe(m);
    std::vector<float> s(2 * kTenthSecond);
    synth.render(s.data(), kTenthSecond);
    EXPECT_GT(rms(s, 0, kTenthSecond, 1), 2.0 * rms(s, 0, kTenthSecond, 0));
}

// Forty steel balls dropped together on the sandbox's floor land in the same ticks: the
// voice limit and the limiter keep every sample within the ceiling, and it is loud.
TEST(Sound, ManyImpactsAtOnceNeverClip) {
    Match m(level("11_sandbox.json"));
    for (int i = 0; i < 40; ++i) {
        Command c = cmd(CommandKind::Spawn, 0.0, "steel-ball");
        c.at = {40.0 + 1.0 * i, 12.0};
        ASSERT_EQ(m.apply(c), "") << i;
    }
    SoundTrack track;
    run(m, track, 360);
    EXPECT_GT(track.synthesizer().started(VoiceKind::Impact), 40u);
    const double p = peak(track.samples());
    EXPECT_LE(p, SynthesizerDef{}.limiterCeiling + 1e-6);
    EXPECT_GT(p, 0.5);
}

// Mute and the volumes scale the mix; the UI bus answers to its own slider.
TEST(Sound, MixVolumesAndMute) {
    auto clickPeak = [](SoundMix mix) {
        Synthesizer synth;
        synth.setMix(mix);
        synth.click();
        std::vector<float> s(2 * 2000);
        synth.render(s.data(), 2000);
        return peak(s);
    };
    const double full = clickPeak({1.0, 1.0, 1.0, false});
    EXPECT_GT(full, 0.1);
    EXPECT_NEAR(clickPeak({0.5, 1.0, 1.0, false}), 0.5 * full, 1e-6);
    EXPECT_NEAR(clickPeak({1.0, 0.0, 0.5, false}), 0.5 * full, 1e-6);
    EXPECT_EQ(clickPeak({1.0, 1.0, 1.0, true}), 0.0);
}

// The WAV header says what the file holds; a damaged one is refused.
TEST(Sound, WavFilesReadBackAsWritten) {
    const std::vector<float> samples{0.0f, 1.0f, -1.0f, 0.5f, 2.0f, -3.0f};
    const std::string bytes = wavBytes(samples, 2, kSampleRate);
    ASSERT_EQ(bytes.size(), 44u + 12u);
    std::string why;
    const auto wav = parseWav(bytes, why);
    ASSERT_TRUE(wav) << why;
    EXPECT_EQ(wav->channels, 2);
    EXPECT_EQ(wav->sampleRate, 48000);
    EXPECT_EQ(wav->bitsPerSample, 16);
    EXPECT_EQ(wav->frames(), 3u);
    EXPECT_EQ(wav->pcm, (std::vector<std::int16_t>{0, 32767, -32767, 16384, 32767, -32767}));
    EXPECT_FALSE(parseWav(bytes.substr(0, 50), why));
    EXPECT_NE(why.find("RIFF size"), std::string::npos) << why;
    EXPECT_FALSE(parseWav("RIFX" + bytes.substr(4), why));

    const fs::path file = fs::temp_directory_path() / "artillery_sound_test.wav";
    writeWav(file.string(), samples, 2, kSampleRate);
    EXPECT_EQ(readFile(file.string()), bytes);
    fs::remove(file);
}

TEST(Sound, WavNamesAreCheckedBeforeTheRun) {
    EXPECT_NE(checkWavFile("").find("expects a file name"), std::string::npos);
    EXPECT_NE(checkWavFile("track.mp3").find("must end in .wav"), std::string::npos);
    EXPECT_NE(checkWavFile("/nonexistent-folder/t.wav").find("does not exist"), std::string::npos);
    EXPECT_EQ(checkWavFile((fs::temp_directory_path() / "t.wav").string()), "");
}

// Live (the window looks every frame, also while paused): a tick's contacts are heard once,
// however often the match is looked at before the next tick.
TEST(Sound, APausedMatchIsHeardOnce) {
    Match m(level("11_sandbox.json"));
    Command c = cmd(CommandKind::Spawn, 0.0, "steel-ball");
    c.at = {40.0, 6.0};
    ASSERT_EQ(m.apply(c), "");
    Synthesizer synth(SynthesizerDef{.live = true});
    for (int i = 0; i < 240 && synth.started(VoiceKind::Impact) == 0; ++i) {
        m.step();
        synth.observe(m);
    }
    const std::size_t heard = synth.started(VoiceKind::Impact);
    ASSERT_GT(heard, 0u) << "the ball lands within 2 s";
    for (int frame = 0; frame < 10; ++frame)
        synth.observe(m);
    EXPECT_EQ(synth.started(VoiceKind::Impact), heard);
}

// Time standing still (paused, a menu open) silences the whistle: the shell hangs in the
// air. When time goes on, the shell whistles again.
TEST(Sound, TheWhistleFallsSilentWhileTimeStandsStill) {
    Match m(level("01_earth_basics.json"));
    shoot(m, 45.0, 40.0);
    Synthesizer synth(SynthesizerDef{.live = true});
    std::vector<float> s(2 * kTenthSecond);
    auto play = [&](int tenths, bool still) {
        for (int k = 0; k < tenths; ++k) {
            if (still) {
                synth.stillWhistles();
            } else {
                for (int t = 0; t < 12; ++t) { // a tenth of a second at 120 Hz
                    m.step();
                    synth.observe(m);
                }
            }
            synth.render(s.data(), kTenthSecond);
        }
    };
    play(15, false);
    ASSERT_TRUE(m.shell()) << "a shot at 40 m/s flies for seconds";
    ASSERT_EQ(synth.started(VoiceKind::Whistle), 1u);
    EXPECT_GT(rms(s, 0, kTenthSecond), 0.0) << "in flight, the shell whistles";
    play(10, true);
    EXPECT_EQ(rms(s, 0, kTenthSecond), 0.0) << "stopped, it has faded out";
    play(2, false);
    EXPECT_EQ(synth.started(VoiceKind::Whistle), 2u) << "going on, it whistles anew";
    EXPECT_GT(rms(s, 0, kTenthSecond), 0.0);
}

// A ball dropped on a block is heard the tick it strikes it (the coupling's impulse), as
// the block's material.
TEST(Sound, ABallStrikingABlockIsHeard) {
    Match m(level("11_sandbox.json"));
    Command block = cmd(CommandKind::Spawn, 2.0, "block");
    block.at = {60.0, 3.0};
    ASSERT_EQ(m.apply(block), "");
    Synthesizer synth;
    for (int i = 0; i < 240; ++i) { // the block settles on the floor
        m.step();
        synth.observe(m);
    }
    Command ball = cmd(CommandKind::Spawn, 0.0, "golf-ball");
    ball.at = {60.0, 12.0};
    ASSERT_EQ(m.apply(ball), "");
    int struck = 0;
    for (int i = 0; i < 240 && struck == 0; ++i) {
        const std::size_t before = synth.started(VoiceKind::Impact);
        m.step();
        synth.observe(m);
        for (const phys::BodyContactEvent& e : m.coupling().events())
            if (e.closingSpeed > 1.5) {
                struck = static_cast<int>(m.tick());
                EXPECT_GT(synth.started(VoiceKind::Impact), before) << "at tick " << m.tick();
            }
    }
    EXPECT_GT(struck, 0) << "the ball falls onto the block within 2 s";
}

// A scene that is not a match (the physics lab) tells the synthesizer what happens: a
// shot is a report at once, louder for a faster shell; a landing a thud, none below the
// impact threshold; a shell in flight a whistle whose pitch follows it, faded out when
// none is told.
TEST(Sound, ASceneThatIsNotAMatchIsHeardAsItTells) {
    auto heard = [](auto tell) {
        Synthesizer synth{SynthesizerDef{.live = true}};
        synth.setView({0.0, 60.0});
        tell(synth);
        std::vector<float> s(2 * kTenthSecond * 5);
        synth.render(s.data(), s.size() / 2);
        return std::pair{rms(s, 0, kTenthSecond), s};
    };
    const auto [slow, slowTrack] = heard([](Synthesizer& s) { s.hearShot({0.0, 1.0}, 20.0); });
    const auto [fast, fastTrack] = heard([](Synthesizer& s) { s.hearShot({0.0, 1.0}, 60.0); });
    EXPECT_GT(slow, 0.02);
    EXPECT_GT(fast, slow);

    const auto [thud, thudTrack] = heard([](Synthesizer& s) {
        s.hearLanding({40.0, 0.2}, 20.0, Timbre::Earth);
    });
    EXPECT_GT(thud, 0.01);
    EXPECT_GT(rms(thudTrack, 0, kTenthSecond, 1), rms(thudTrack, 0, kTenthSecond, 0))
        << "at 40 of 0..60 m it is right of the middle";
    const auto [soft, softTrack] = heard([](Synthesizer& s) {
        s.hearLanding({40.0, 0.2}, 1.0, Timbre::Earth);
    });
    EXPECT_EQ(soft, 0.0) << "1 m/s is below the impact threshold";

    Synthesizer synth{SynthesizerDef{.live = true}};
    synth.setView({0.0, 60.0});
    using Shells = std::vector<KeyedShell>;
    synth.hearShellsInFlight(Shells{{7, ShellSound{{10.0, 10.0}, {40.0, 10.0}}}}, 20.0);
    EXPECT_EQ(synth.started(VoiceKind::Whistle), 1u);
    std::vector<float> s(2 * kTenthSecond);
    synth.render(s.data(), kTenthSecond);
    EXPECT_GT(rms(s, kTenthSecond / 2, kTenthSecond), 0.0);
    synth.hearShellsInFlight(Shells{{7, ShellSound{{14.0, 11.0}, {40.0, 9.0}}}}, 20.0);
    EXPECT_EQ(synth.started(VoiceKind::Whistle), 1u) << "the same whistle follows the shell";
    synth.hearShellsInFlight(Shells{{7, ShellSound{{18.0, 11.8}, {40.0, 8.0}}},
                                    {9, ShellSound{{1.0, 2.0}, {30.0, 30.0}}}},
                             20.0);
    EXPECT_EQ(synth.started(VoiceKind::Whistle), 2u) << "a second shell: a second whistle";
    EXPECT_EQ(synth.voices(), 2u);
    synth.hearShellsInFlight({}, 20.0);
    for (int k = 0; k < 10; ++k)
        synth.render(s.data(), kTenthSecond);
    EXPECT_EQ(rms(s, 0, kTenthSecond), 0.0) << "no shell: the whistle has faded out";
    EXPECT_EQ(synth.voices(), 0u);
}
