#include "game/audio/sound_track.h"

#include "game/audio/wav.h"

#include <filesystem>

namespace game::audio {

void SoundTrack::frame(const Match& match) {
    synth_.observe(match);
    const std::int64_t until = synth_.sampleOfTick(match.tick());
    if (until <= synth_.cursor()) return;
    const auto frames = static_cast<std::size_t>(until - synth_.cursor());
    const std::size_t at = samples_.size();
    samples_.resize(at + 2 * frames);
    synth_.render(samples_.data() + at, frames);
}

void SoundTrack::write(const std::string& file) const {
    writeWav(file, samples_, 2, kSampleRate);
}

std::string checkWavFile(const std::string& file) {
    namespace fs = std::filesystem;
    if (file.empty()) return "--audio expects a file name ending in .wav, got ''";
    const fs::path path(file);
    if (path.extension() != ".wav")
        return "--audio writes 16-bit PCM WAV; the file name must end in .wav, got '" + file + "'";
    const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return "cannot write '" + file + "': the folder '" + folder.string() + "' does not exist";
    return "";
}

} // namespace game::audio
