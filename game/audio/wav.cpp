#include "game/audio/wav.h"

#include "game/files/text_file.h"

#include <algorithm>
#include <cmath>

namespace game::audio {

namespace {

void put16(std::string& out, std::uint16_t v) {
    out.push_back(static_cast<char>(v & 0xff));
    out.push_back(static_cast<char>(v >> 8));
}

void put32(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

std::uint32_t get32(const std::string& b, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i)
        v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
    return v;
}

std::uint16_t get16(const std::string& b, std::size_t at) {
    return static_cast<std::uint16_t>(static_cast<unsigned char>(b[at]) |
                                      static_cast<unsigned char>(b[at + 1]) << 8);
}

} // namespace

std::int16_t toPcm16(float x) {
    const double clamped = std::clamp(static_cast<double>(x), -1.0, 1.0);
    return static_cast<std::int16_t>(std::lround(clamped * 32767.0));
}

std::string wavBytes(const std::vector<float>& interleaved, int channels, int sampleRate) {
    const auto data = static_cast<std::uint32_t>(interleaved.size() * 2);
    const auto blockAlign = static_cast<std::uint16_t>(channels * 2);
    std::string out;
    out.reserve(44 + data);
    out += "RIFF";
    put32(out, 36 + data); // the rest of the file after this field
    out += "WAVEfmt ";
    put32(out, 16); // the PCM fmt chunk's size
    put16(out, 1);  // format tag: PCM
    put16(out, static_cast<std::uint16_t>(channels));
    put32(out, static_cast<std::uint32_t>(sampleRate));
    put32(out, static_cast<std::uint32_t>(sampleRate) * blockAlign); // bytes per second
    put16(out, blockAlign);
    put16(out, 16);
    out += "data";
    put32(out, data);
    for (const float x : interleaved)
        put16(out, static_cast<std::uint16_t>(toPcm16(x)));
    return out;
}

void writeWav(const std::string& file, const std::vector<float>& interleaved, int channels,
              int sampleRate) {
    writeFileAtomically(file, wavBytes(interleaved, channels, sampleRate));
}

std::optional<WavSound> parseWav(const std::string& b, std::string& why) {
    if (b.size() < 12 || b.compare(0, 4, "RIFF") != 0 || b.compare(8, 4, "WAVE") != 0) {
        why = "not a RIFF/WAVE file";
        return std::nullopt;
    }
    if (get32(b, 4) != b.size() - 8) {
        why = "the RIFF size says " + std::to_string(get32(b, 4)) + " bytes, the file has " +
              std::to_string(b.size() - 8);
        return std::nullopt;
    }
    WavSound s;
    bool format = false;
    for (std::size_t at = 12; at + 8 <= b.size();) {
        const std::string id = b.substr(at, 4);
        const std::uint32_t size = get32(b, at + 4);
        const std::size_t body = at + 8;
        if (body + size > b.size()) {
            why = "the chunk \"" + id + "\" runs past the end of the file";
            return std::nullopt;
        }
        if (id == "fmt ") {
            if (size < 16 || get16(b, body) != 1) {
                why = "the format is not PCM";
                return std::nullopt;
            }
            s.channels = get16(b, body + 2);
            s.sampleRate = static_cast<int>(get32(b, body + 4));
            s.bitsPerSample = get16(b, body + 14);
            if (s.bitsPerSample != 16 || s.channels < 1 || get16(b, body + 12) != s.channels * 2 ||
                get32(b, body + 8) != static_cast<std::uint32_t>(s.sampleRate * s.channels * 2)) {
                why = "the fmt chunk is not consistent 16-bit PCM";
                return std::nullopt;
            }
            format = true;
        } else if (id == "data") {
            if (!format) {
                why = "the data chunk comes before the fmt chunk";
                return std::nullopt;
            }
            s.pcm.resize(size / 2);
            for (std::size_t i = 0; i < s.pcm.size(); ++i)
                s.pcm[i] = static_cast<std::int16_t>(get16(b, body + 2 * i));
            return s;
        }
        at = body + size + (size & 1); // chunks are padded to even sizes
    }
    why = "no data chunk";
    return std::nullopt;
}

} // namespace game::audio
