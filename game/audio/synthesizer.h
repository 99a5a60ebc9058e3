// The match's sound track: a view of the match (docs/architecture.md, "Layers": sound,
// effects and the camera are views of the match's events) that turns what happened in each tick into voices
// and renders them as stereo float frames at 48 kHz. It reads the match after each tick
// and never writes it, so a match's hashes are the same with sound or without.
//
// What it listens to:
//   Fired            the report, by the muzzle speed
//   the shell        a whistle whose pitch follows its speed (and its Doppler shift
//                    toward the listener), louder as v^2; a splash where it enters water
//   contacts         every particle's impact above 1.5 m/s on the static world (terrain,
//                    walls), on another particle, or on a block (the coupling's hits), the
//                    six hardest of a tick: loudness from the closing speed, timbre from
//                    the materials, ring from the restitution (e = v_out / v_in)
//   blocks           a block's velocity jumping by more than gravity explains (struck,
//                    landing, knocked over): an impact of its material at |dv|
//   Burst            the blast, by its impulse x radius
//   TargetHit        a two-note chime; Toppled: a crack; CannonHit: steel ringing
//   MatchOver        the stars as a rising arpeggio (a lost duel: a falling one)
//
// Timing. Offline (the WAV, the video) a voice starts at its tick's sample: tick t starts
// at sample floor(t * 48000 * dt), computed in integers from the tick rate in mHz, so the
// track never drifts from the simulation. Live (the window, where ticks follow the wall
// clock in bursts per frame), a voice starts at the next sample to be played.
//
// Section index
//   SoundMix      master, effects and UI volume, mute
//   ViewFrame     what the listener sees (panning)
//   ShellSound    a shell in flight as its whistle hears it (KeyedShell: one of several)
//   Synthesizer   observe(match) after each tick, render(frames), click(); a scene that
//                 is not a match (the physics lab) tells it its shots, landings and shells
#pragma once

#include "game/audio/voices.h"
#include "game/effects/water_entry.h"
#include "game/match.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace game::audio {

/// The player's volumes (the Sound section of the settings panel).
struct SoundMix {
    double master = 0.8;  ///< 0..1, scales everything
    double effects = 1.0; ///< 0..1, the match's sounds
    double ui = 0.6;      ///< 0..1, clicks
    bool mute = false;
    bool operator==(const SoundMix&) const = default;
};

/// The horizontal span the listener sees, m: an event at `left` is panned hard left, at
/// `right` hard right (an equal-power pan law between).
struct ViewFrame {
    double left = 0.0;
    double right = 200.0;
};

/// A shell in flight, as its whistle follows it.
struct ShellSound {
    phys::Vec2 position, velocity; ///< m, m/s
    bool underwater = false;       ///< the air is gone: no whistle
};
/// A shell and what tells it from the others in flight (its particle, say).
struct KeyedShell {
    std::uint64_t key = 0;
    ShellSound shell;
};

struct SynthesizerDef {
    bool live = false;                   ///< voices start at the render cursor, not at their tick
    std::size_t maxVoices = 24;          ///< the quietest voice gives way beyond this
    double limiterCeiling = 0.9;         ///< the soft limiter keeps |sample| at or below this
    double limiterReleaseSeconds = 0.15; ///< how fast its gain recovers after a peak
    double impactSpeedMps = 1.5;         ///< contacts closing slower than this are silent
    std::size_t impactsPerTick = 6;      ///< the strongest contacts of a tick are heard
};

class Synthesizer {
  public:
    explicit Synthesizer(const SynthesizerDef& def = {});

    /// Call after every tick (or, live, after each frame's ticks): new events and the
    /// state of the shell and the blocks become voices. A match whose tick went back (a
    /// rewind, a new match) starts afresh; voices already sounding play out.
    void observe(const Match& match);
    /// Renders the next `frames` stereo frames (2 * frames floats, left then right).
    void render(float* interleaved, std::size_t frames);
    /// A UI click at the next sample.
    void click();
    /// Forgets the match (voices sounding play out).
    void forgetMatch();

    // A scene that is not a match (the physics lab) tells what happens as it happens;
    // each sounds at the next sample to play (a live synthesizer's clock).
    /// A shot leaving the muzzle at `muzzleSpeed` m/s: the report.
    void hearShot(phys::Vec2 muzzle, double muzzleSpeed);
    /// A shell coming down on `surface` at `speed` m/s (and staying there): a thud, or
    /// nothing below the impact threshold.
    void hearLanding(phys::Vec2 where, double speed, Timbre surface);
    /// The shells in flight, each frame: each has a whistle of its own while its key is
    /// told, which fades out when it no longer is. The listener is at the middle of the
    /// view, at height `listenerY`.
    void hearShellsInFlight(std::span<const KeyedShell> shells, double listenerY);
    /// Time stands still (paused, a menu open): nothing flies, so every whistle fades
    /// out; a shell heard again afterwards (observe, hearShellsInFlight) starts a new one.
    void stillWhistles();

    void setMix(const SoundMix& mix) { mix_ = mix; }
    const SoundMix& mix() const { return mix_; }
    /// The listener's view (live: the camera; offline: the level's bounds by default).
    void setView(const ViewFrame& view) {
        view_ = view;
        viewSet_ = true;
    }
    /// Samples rendered so far (the next frame's index).
    std::int64_t cursor() const { return cursor_; }
    /// The first sample of tick `tick` of the match observed (exact: see above).
    std::int64_t sampleOfTick(std::uint64_t tick) const;
    std::size_t voices() const { return voices_.size(); }
    /// Voices started since construction, of each kind (for tests).
    std::size_t started(VoiceKind kind) const { return started_[static_cast<std::size_t>(kind)]; }

  private:
    /// The sample a voice of tick `tick` starts at (live: the next one to play).
    std::int64_t atTick(std::uint64_t tick) const;
    void start(Voice v, std::uint64_t tick, phys::Vec2 where, std::uint64_t seedSalt);
    double panOf(phys::Vec2 where) const;
    void followClock(const Match& m);
    void hearEvents(const Match& m);
    void hearShell(const Match& m);
    /// Each whistle follows its shell from tick `tick` on; one not told fades out.
    void followWhistles(std::span<const KeyedShell> shells, std::uint64_t tick, double listenerY);
    void hearContacts(const Match& m);
    void hearBlocks(const Match& m);

    SynthesizerDef def_;
    SoundMix mix_;
    ViewFrame view_;
    bool viewSet_ = false;
    std::vector<Voice> voices_;
    std::int64_t cursor_ = 0;
    double limiterGain_ = 1.0;
    std::size_t started_[kVoiceKinds] = {};
    // The match as last seen.
    bool seen_ = false;
    std::uint64_t lastTick_ = 0;
    std::size_t seenEvents_ = 0;
    std::string firedAmmo_;
    // The clock: samples = base + (tick - baseTick) * 48000 * 1000 / mHz.
    std::uint64_t baseTick_ = 0;
    std::int64_t baseSample_ = 0;
    std::int64_t tickMilliHz_ = 0;
    // The shells' whistles (an index into voices_ is unstable: each found by its id).
    struct Whistling {
        std::uint64_t key;   ///< the shell's (KeyedShell::key)
        std::uint64_t voice; ///< Voice::id
    };
    std::vector<Whistling> whistles_;
    std::uint64_t toldEvents_ = 0; ///< shots and landings told: each one's noise differs
    WaterEntryWatch waterEntry_; ///< the shell's crossings of the water line: splashes
    // Blocks' velocities at the last look.
    std::vector<phys::Vec2> blockVelocity_;
    std::vector<bool> blockSeen_;
};

} // namespace game::audio
