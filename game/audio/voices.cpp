#include "game/audio/voices.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace game::audio {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kDt = 1.0 / kSampleRate; // s per sample

/// One-pole low-pass coefficient for a cutoff fc: a = 1 - e^(-2 pi fc / fs), so that
/// y += a (x - y) halves the power at fc (the impulse-invariant RC filter).
double lowPass(double cutoffHz) {
    return 1.0 - std::exp(-kTwoPi * cutoffHz * kDt);
}

std::int64_t samples(double seconds) {
    return static_cast<std::int64_t>(std::ceil(seconds * kSampleRate));
}

/// 1 - e^(-x / scale): a loudness that rises with x and saturates (no voice overshoots).
double saturating(double x, double scale) {
    return 1.0 - std::exp(-std::max(0.0, x) / scale);
}

/// The modes of a struck body of each timbre: a wooden beam's low, fast-dying modes; a
/// stone's brighter, shorter click; steel's inharmonic, long ring (the ratios of a free
/// bar, 1 : 2.76 : 5.40); the ground's dull thud.
Modes modesOf(Timbre t) {
    switch (t) {
    case Timbre::Wood:
        return {{210.0, 540.0, 1150.0}, {1.0, 0.6, 0.3}, 0.07, 1800.0};
    case Timbre::Stone:
        return {{420.0, 1130.0, 2350.0}, {1.0, 0.7, 0.5}, 0.045, 4500.0};
    case Timbre::Steel:
        return {{780.0, 2153.0, 4212.0}, {1.0, 0.6, 0.4}, 0.45, 6000.0};
    case Timbre::Soft:
        return {{140.0, 310.0, 620.0}, {1.0, 0.3, 0.1}, 0.03, 700.0};
    case Timbre::Water:
        return {{300.0, 650.0, 1300.0}, {0.6, 0.3, 0.1}, 0.04, 3000.0};
    case Timbre::Earth:
        break;
    }
    return {{70.0, 130.0, 240.0}, {1.0, 0.5, 0.25}, 0.06, 450.0};
}

} // namespace

const char* timbreName(Timbre t) {
    switch (t) {
    case Timbre::Earth:
        return "earth";
    case Timbre::Wood:
        return "wood";
    case Timbre::Stone:
        return "stone";
    case Timbre::Steel:
        return "steel";
    case Timbre::Soft:
        return "soft";
    case Timbre::Water:
        return "water";
    }
    return "earth";
}

Timbre timbreOf(const std::string& m) {
    auto has = [&](const char* word) { return m.find(word) != std::string::npos; };
    if (has("steel") || has("iron") || has("bearing")) return Timbre::Steel;
    if (has("wood")) return Timbre::Wood;
    if (has("stone") || has("glass") || has("marble") || has("billiard") || has("concrete"))
        return Timbre::Stone;
    if (has("rubber") || has("tennis") || has("golf") || has("ball") || has("plastic") ||
        has("jelly"))
        return Timbre::Soft;
    if (has("water")) return Timbre::Water;
    return Timbre::Earth;
}

// The next sample: the voice's age in seconds, then the kind's own synthesis.
double Voice::next() {
    const double t = static_cast<double>(age) * kDt;
    ++age;
    switch (kind) {
    case VoiceKind::Report: return sampleReport(t);
    case VoiceKind::Whistle: return sampleWhistle();
    case VoiceKind::Impact: return sampleImpact(t);
    case VoiceKind::Blast: return sampleBlast(t);
    case VoiceKind::Splash: return sampleSplash(t);
    case VoiceKind::Crack: return sampleCrack(t);
    case VoiceKind::Chime: return sampleChime(t);
    case VoiceKind::Click: return sampleClick(t);
    }
    return 0.0;
}

double Voice::white() { return 2.0 * noise.unit() - 1.0; }

double Voice::sampleReport(double t) {
    // Muzzle blast: low-passed noise (x3 restores the power the filter takes out of
    // white noise, var = a / (2 - a)) with the report's decay.
    low += lowPass(2500.0) * (white() - low);
    const double burst = 3.0 * low * std::exp(-t / decaySeconds);
    // Thump: a sine falling from pitchHz to 40 Hz over ~40 ms, dying 3x slower.
    const double hz = 40.0 + (pitchHz - 40.0) * std::exp(-t / 0.04);
    phase[0] += kTwoPi * hz * kDt;
    const double thump = std::sin(phase[0]) * std::exp(-t / (3.0 * decaySeconds));
    return gain * (0.6 * burst + 0.7 * thump);
}

double Voice::sampleWhistle() {
    const std::int64_t now = start + age - 1;
    while (!keys.empty() && keys.front().sample <= now) {
        const WhistleKey k = keys.front();
        keys.erase(keys.begin());
        targetHz = k.pitchHz;
        targetGain = k.last ? 0.0 : k.gain;
        pan = k.pan;
        if (nowHz == 0.0) nowHz = targetHz;
        if (k.last && !ending) {
            ending = true;
            length = age + samples(0.12);
        }
    }
    // Pitch and loudness glide to the shell's over 15 ms (no zipper steps per tick).
    const double glide = lowPass(1.0 / (kTwoPi * 0.015));
    nowHz += glide * (targetHz - nowHz);
    nowGain += glide * (targetGain - nowGain);
    phase[0] += kTwoPi * nowHz * kDt;
    // Breath: slow noise (30 Hz) wobbles the tone's loudness like air past a shell.
    low += lowPass(30.0) * (white() - low);
    return nowGain * std::sin(phase[0]) * (1.0 + 2.0 * low);
}

double Voice::sampleImpact(double t) {
    double ring = 0.0;
    for (int i = 0; i < 3; ++i)
        ring += modes.weight[i] * std::sin(kTwoPi * modes.hz[i] * t) *
                std::exp(-t * (i + 1) / modes.decaySeconds);
    low += lowPass(modes.noiseCutoffHz) * (white() - low);
    const double click = 3.0 * low * std::exp(-t / 0.004);
    return gain * (0.55 * ring + 0.6 * click);
}

double Voice::sampleBlast(double t) {
    const double hz = 28.0 + 50.0 * std::exp(-t / 0.15);
    phase[0] += kTwoPi * hz * kDt;
    const double boom = std::sin(phase[0]) * std::exp(-t / decaySeconds);
    // Rumble: noise through two poles at 150 Hz, longer than the boom.
    low += lowPass(150.0) * (white() - low);
    low2 += lowPass(150.0) * (low - low2);
    const double rumble = 8.0 * low2 * std::exp(-t / (1.5 * decaySeconds));
    band += lowPass(4000.0) * (white() - band);
    const double crackle = 2.0 * band * std::exp(-t / 0.02);
    return gain * (0.6 * boom + 0.5 * rumble + 0.4 * crackle);
}

double Voice::sampleSplash(double t) {
    // Plop: the cavity's bubble, a chirp rising from 400 Hz as it closes (~30 ms).
    const double hz = 400.0 + 900.0 * (1.0 - std::exp(-t / 0.03));
    phase[0] += kTwoPi * hz * kDt;
    const double plop = std::sin(phase[0]) * std::exp(-t / 0.03);
    // Spray: noise between 800 Hz and 5 kHz (difference of two low-passes), its
    // loudness broken up by droplets (noise at 40 Hz), rising in 20 ms, dying slowly.
    const double w = white();
    low += lowPass(5000.0) * (w - low);
    low2 += lowPass(800.0) * (w - low2);
    band += lowPass(40.0) * (white() - band);
    const double envelope = (1.0 - std::exp(-t / 0.02)) * std::exp(-t / decaySeconds);
    const double spray = 2.5 * (low - low2) * envelope * std::clamp(0.6 + 6.0 * band, 0.0, 1.5);
    return gain * (0.5 * plop + 0.7 * spray);
}

double Voice::sampleCrack(double t) {
    const double w = white();
    low += lowPass(1000.0) * (w - low); // white minus its low part: a bright snap
    const double snap = (w - low) * std::exp(-t / 0.012);
    const double ring = std::sin(kTwoPi * 1800.0 * t) * std::exp(-t / 0.03);
    return gain * (0.7 * snap + 0.4 * ring);
}

double Voice::sampleChime(double t) {
    // A bell's partials 1 : 2.76 : 5.40 for each note, notes 110 ms apart.
    double sum = 0.0;
    double hz = pitchHz;
    for (int k = 0; k < notes; ++k, hz *= step) {
        const double tk = t - 0.11 * k;
        if (tk < 0.0) break;
        const double env = std::exp(-tk / decaySeconds);
        sum += env * (std::sin(kTwoPi * hz * tk) + 0.4 * std::sin(kTwoPi * 2.76 * hz * tk) +
                      0.2 * std::sin(kTwoPi * 5.40 * hz * tk) * std::exp(-tk / 0.05));
    }
    return gain * 0.5 * sum;
}

double Voice::sampleClick(double t) {
    return gain * (std::sin(kTwoPi * 2600.0 * t) * std::exp(-t / 0.006) +
                   0.5 * white() * std::exp(-t / 0.0015));
}

// ---- makers ----------------------------------------------------------------------------
Voice report(double muzzleSpeedMps) {
    Voice v;
    v.kind = VoiceKind::Report;
    // Louder and longer for a faster shot: the charge's energy goes as v^2, the ear's
    // loudness roughly as its logarithm; saturate at a heavy gun's ~80 m/s.
    const double s = saturating(muzzleSpeedMps, 40.0);
    v.gain = 0.25 + 0.7 * s;
    v.decaySeconds = 0.03 + 0.07 * s;
    v.pitchHz = 90.0 + 60.0 * s;
    v.length = samples(15.0 * v.decaySeconds); // the thump (tau x 3) down to e^-5
    return v;
}

Voice whistle() {
    Voice v;
    v.kind = VoiceKind::Whistle;
    v.length = std::numeric_limits<std::int64_t>::max() / 4; // until the shell is gone
    return v;
}

Voice impact(Timbre timbre, double closingSpeedMps, double restitution) {
    Voice v;
    v.kind = VoiceKind::Impact;
    v.modes = modesOf(timbre);
    // Amplitude from the closing speed (the impulse's size, m dv); a thud at 1 m/s is
    // barely there, a shell at 30 m/s near full scale.
    v.gain = 0.9 * saturating(closingSpeedMps, 18.0);
    // An elastic contact gives the energy back and rings longer: decay x (0.5 + e).
    v.modes.decaySeconds *= 0.5 + std::clamp(restitution, 0.0, 1.0);
    v.modes.noiseCutoffHz *= 0.6 + 0.8 * saturating(closingSpeedMps, 15.0); // harder: brighter
    v.length = samples(std::max(0.04, 5.0 * v.modes.decaySeconds));
    return v;
}

Voice blast(double impulseNs, double radiusM) {
    Voice v;
    v.kind = VoiceKind::Blast;
    // Relative to a cannon shell's blast (150 N s over 3 m: 450 N s m), as the screen
    // shake measures it.
    const double energy = impulseNs * radiusM / 450.0;
    v.gain = 0.35 + 0.6 * saturating(energy, 1.0);
    v.decaySeconds = 0.3 + 0.5 * saturating(energy, 1.5);
    v.length = samples(7.5 * v.decaySeconds); // the rumble (tau x 1.5) down to e^-5
    return v;
}

Voice splash(double entrySpeedMps) {
    Voice v;
    v.kind = VoiceKind::Splash;
    v.gain = 0.3 + 0.6 * saturating(entrySpeedMps, 20.0);
    v.decaySeconds = 0.12 + 0.25 * saturating(entrySpeedMps, 20.0);
    v.length = samples(5.0 * v.decaySeconds);
    return v;
}

Voice crack(double strength) {
    Voice v;
    v.kind = VoiceKind::Crack;
    v.gain = 0.3 + 0.5 * std::clamp(strength, 0.0, 1.0);
    v.length = samples(0.15);
    return v;
}

Voice chime(double firstHz, int notes, double step, double gain) {
    Voice v;
    v.kind = VoiceKind::Chime;
    v.pitchHz = firstHz;
    v.notes = std::max(1, notes);
    v.step = step;
    v.gain = gain;
    v.decaySeconds = 0.35;
    v.length = samples(0.11 * v.notes + 2.0);
    return v;
}

Voice click() {
    Voice v;
    v.kind = VoiceKind::Click;
    v.bus = Bus::Ui;
    v.gain = 0.35;
    v.length = samples(0.04);
    return v;
}

} // namespace game::audio
