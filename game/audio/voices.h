// The sounds themselves: each voice is synthesized sample by sample from a few numbers
// the physics gave it (a speed, a material, a blast's energy), with no recorded assets.
// A voice's samples depend only on its parameters and its own noise generator (seeded
// from the event's tick and kind), so the same event always sounds the same, however
// the samples are pulled.
//
// Section index
//   Timbre       what a struck thing is made of, from the material's name
//   VoiceKind    report, whistle, impact, blast, splash, crack, chime, click
//   Voice        parameters, state, next() (one mono sample)
//   makers       one function per sound, from its physics
#pragma once

#include "game/generate/seeded_random.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace game::audio {

inline constexpr int kSampleRate = 48000; ///< frames per second (stereo: two samples each)

/// What a struck thing is made of: it sets the modes that ring and how long.
enum class Timbre : std::uint8_t { Earth, Wood, Stone, Steel, Soft, Water };
const char* timbreName(Timbre t);
/// From a material's name: "steel", "wood", "stone", "earth", rubber balls are soft ...
Timbre timbreOf(const std::string& material);

enum class VoiceKind : std::uint8_t { Report, Whistle, Impact, Blast, Splash, Crack, Chime, Click };
inline constexpr std::size_t kVoiceKinds = 8; ///< the kinds above

/// Which volume slider a voice answers to.
enum class Bus : std::uint8_t { Effects, Ui };

/// A change of the whistle's pitch, loudness and place, from the shell at one tick.
struct WhistleKey {
    std::int64_t sample = 0; ///< when it takes effect
    double pitchHz = 0.0;
    double gain = 0.0;
    double pan = 0.0;
    bool last = false; ///< the shell is gone: fade out and end
};

/// Three damped modes of a struck body: f_i (Hz), and the decay time of the first (s);
/// higher modes die faster, tau_i = tau / i (Rayleigh damping's rough shape).
struct Modes {
    double hz[3] = {0.0, 0.0, 0.0};
    double weight[3] = {1.0, 0.5, 0.25};
    double decaySeconds = 0.1;
    double noiseCutoffHz = 1000.0; ///< the click's colour (one-pole low-pass)
};

struct Voice {
    VoiceKind kind = VoiceKind::Impact;
    Bus bus = Bus::Effects;
    std::uint64_t id = 0;    ///< the track's name for it (the whistle is found by it)
    std::int64_t start = 0;  ///< first sample, on the track's clock
    std::int64_t length = 0; ///< samples; the voice ends after them
    double gain = 0.0;       ///< peak amplitude, 0..1
    double pan = 0.0;        ///< -1 left .. +1 right
    // What to play (the meaning depends on the kind).
    Modes modes;
    double pitchHz = 0.0; ///< report: the thump's start; chime: the first note
    double decaySeconds = 0.1;
    int notes = 1;                ///< chime: notes in its arpeggio
    double step = 1.0;            ///< chime: frequency ratio from one note to the next
    std::vector<WhistleKey> keys; ///< whistle: pending changes, in time order
    // State.
    generate::SeededRandom noise{0};
    std::int64_t age = 0; ///< samples played
    double phase[3] = {0.0, 0.0, 0.0};
    double low = 0.0, low2 = 0.0, band = 0.0;
    double nowHz = 0.0, nowGain = 0.0, targetHz = 0.0, targetGain = 0.0;
    bool ending = false;

    /// The next sample (mono, before panning and the mix) and one sample older.
    double next();
    bool done() const { return age >= length; }

private:
    double white(); ///< white noise in [-1, 1)
    // One sample of each kind at age `t` seconds.
    double sampleReport(double t);
    double sampleWhistle();
    double sampleImpact(double t);
    double sampleBlast(double t);
    double sampleSplash(double t);
    double sampleCrack(double t);
    double sampleChime(double t);
    double sampleClick(double t);
};

// ---- makers: one per sound, from its physics ------------------------------------------
/// The cannon's report: a burst of noise (the muzzle blast) over a falling thump; both
/// louder and longer with the muzzle speed.
Voice report(double muzzleSpeedMps);
/// A shell's whistle; its keys set pitch and loudness as it flies.
Voice whistle();
/// Something struck: modes of `timbre`, amplitude from the closing speed, and the ring's
/// length from the restitution (an elastic bounce rings, a dead one thuds).
Voice impact(Timbre timbre, double closingSpeedMps, double restitution);
/// A burst: a low boom and its rumble, by the blast's energy (impulse x radius, N s m).
Voice blast(double impulseNs, double radiusM);
/// A shell entering the water: a plop and the spray's hiss, by the entry speed.
Voice splash(double entrySpeedMps);
/// A crack: something tearing.
Voice crack(double strength);
/// A chime of `notes` rising notes (a target hit: 2; stars: one per star).
Voice chime(double firstHz, int notes, double step, double gain);
/// A UI click.
Voice click();

} // namespace game::audio
