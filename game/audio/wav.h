// WAV files: RIFF/WAVE with one "fmt " chunk (PCM, format tag 1) and one "data" chunk of
// little-endian signed 16-bit samples, channels interleaved (Microsoft's Multimedia
// Programming Interface and Data Specifications 1.0, 1991). The sound track is written
// as stereo at 48 kHz, atomically (temp file + rename) like every file the game writes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace game::audio {

/// What a WAV file holds.
struct WavSound {
    int channels = 2;
    int sampleRate = 48000; ///< frames per second
    int bitsPerSample = 16;
    std::vector<std::int16_t> pcm; ///< interleaved
    std::size_t frames() const {
        return channels > 0 ? pcm.size() / static_cast<std::size_t>(channels) : 0;
    }
};

/// A float sample in [-1, 1] as 16-bit PCM: round(x * 32767), clamped.
std::int16_t toPcm16(float x);
/// The bytes of a 16-bit PCM WAV of `interleaved` float samples.
std::string wavBytes(const std::vector<float>& interleaved, int channels, int sampleRate);
/// Writes them atomically. Throws std::runtime_error naming the file on failure.
void writeWav(const std::string& file, const std::vector<float>& interleaved, int channels,
              int sampleRate);
/// Parses the bytes of a 16-bit PCM WAV; nullopt and `why` when they are not one.
std::optional<WavSound> parseWav(const std::string& bytes, std::string& why);

} // namespace game::audio
