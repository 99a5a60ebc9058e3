#include "ui/platform/audio_device.h"

#include <SDL.h>

#include <vector>

namespace ui {

AudioDevice::AudioDevice() {
    if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
        why_ = std::string("no audio: ") + SDL_GetError();
        return;
    }
    SDL_AudioSpec want{};
    want.freq = game::audio::kSampleRate;
    want.format = AUDIO_F32SYS;
    want.channels = 2;
    want.samples = 512; // ~11 ms a buffer
    SDL_AudioSpec have{};
    device_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0); // SDL converts if it must
    if (device_ == 0) {
        why_ = std::string("no audio device: ") + SDL_GetError();
        SDL_QuitSubSystem(SDL_INIT_AUDIO);
        return;
    }
    SDL_PauseAudioDevice(device_, 0);
}

AudioDevice::~AudioDevice() {
    if (device_ == 0) return;
    SDL_CloseAudioDevice(device_);
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

void AudioDevice::feed(game::audio::Synthesizer& synth, double latencySeconds) {
    if (device_ == 0) return;
    constexpr std::uint32_t kFrameBytes = 2 * sizeof(float);
    const auto queued = static_cast<long long>(SDL_GetQueuedAudioSize(device_) / kFrameBytes);
    const auto wanted = static_cast<long long>(latencySeconds * game::audio::kSampleRate);
    if (queued >= wanted) return;
    std::vector<float> samples(static_cast<std::size_t>(2 * (wanted - queued)));
    synth.render(samples.data(), samples.size() / 2);
    SDL_QueueAudio(device_, samples.data(),
                   static_cast<std::uint32_t>(samples.size() * sizeof(float)));
}

} // namespace ui
