// The match's sound track rendered offline, tick by tick (`artillery run --audio F.wav`):
// after each tick the synthesizer hears the match, and the track is rendered up to the
// first sample of the next tick, so every voice starts on its tick's sample exactly and
// the same run gives the same file, byte for byte.
#pragma once

#include "game/audio/synthesizer.h"
#include "game/headless.h"

#include <string>
#include <vector>

namespace game::audio {

class SoundTrack final : public FrameSink {
  public:
    explicit SoundTrack(const SynthesizerDef& def = {}) : synth_(def) {}
    /// Hears tick `match.tick()` and renders up to its first sample.
    void frame(const Match& match) override;
    /// Interleaved stereo float samples at kSampleRate.
    const std::vector<float>& samples() const { return samples_; }
    std::size_t frames() const { return samples_.size() / 2; }
    double seconds() const { return static_cast<double>(frames()) / kSampleRate; }
    /// Writes the track as 16-bit PCM WAV, atomically. Throws std::runtime_error.
    void write(const std::string& file) const;
    const Synthesizer& synthesizer() const { return synth_; }

  private:
    Synthesizer synth_;
    std::vector<float> samples_;
};

/// "" when `file` can take a sound track (a .wav name in a folder that exists), else why.
std::string checkWavFile(const std::string& file);

} // namespace game::audio
