// The sound card: an SDL2 audio device playing what the match's synthesizer renders
// (game/audio/synthesizer.h), stereo float at 48 kHz. The game tops the device's queue
// up once a frame to a short latency, so the sound follows the match within a frame or
// two and nothing waits on a lock. With no device (no sound server, no card, or
// SDL_AUDIODRIVER naming a driver that is not there) the game plays silent and says
// why, once.
#pragma once

#include "game/audio/synthesizer.h"

#include <cstdint>
#include <string>

namespace ui {

class AudioDevice {
  public:
    /// Opens the default output device. On failure the device is silent and why() says
    /// what SDL reported; nothing is printed here.
    AudioDevice();
    ~AudioDevice();
    AudioDevice(const AudioDevice&) = delete;
    AudioDevice& operator=(const AudioDevice&) = delete;

    bool silent() const { return device_ == 0; }
    /// Why the device is silent ("" when it plays).
    const std::string& why() const { return why_; }
    /// Renders from `synth` until the queue holds `latencySeconds` of sound. A frame
    /// that comes late finds the queue short and fills it; one that comes early adds
    /// nothing.
    void feed(game::audio::Synthesizer& synth, double latencySeconds = 0.05);

  private:
    std::uint32_t device_ = 0; ///< SDL_AudioDeviceID; 0 = none
    std::string why_;
};

} // namespace ui
