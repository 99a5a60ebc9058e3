// The sound card through SDL2: a driver that is not there leaves the game silent with
// the reason; SDL's dummy driver (a device that plays into nothing at real speed) takes
// what the synthesizer renders, up to the queue's latency and no more.
#include "game/audio/synthesizer.h"
#include "ui/platform/audio_device.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace {

/// Sets SDL_AUDIODRIVER for one scope.
struct AudioDriver {
    explicit AudioDriver(const char* name) { setenv("SDL_AUDIODRIVER", name, 1); }
    ~AudioDriver() { unsetenv("SDL_AUDIODRIVER"); }
};

} // namespace

TEST(AudioDevice, AMissingDriverPlaysSilentAndSaysWhy) {
    const AudioDriver driver("no-such-driver");
    ui::AudioDevice device;
    EXPECT_TRUE(device.silent());
    EXPECT_NE(device.why().find("no audio"), std::string::npos) << device.why();
    game::audio::Synthesizer synth;
    synth.click();
    device.feed(synth);
    EXPECT_EQ(synth.cursor(), 0) << "a silent device renders nothing";
}

TEST(AudioDevice, FeedsTheQueueUpToItsLatency) {
    const AudioDriver driver("dummy");
    ui::AudioDevice device;
    ASSERT_FALSE(device.silent()) << device.why();
    EXPECT_EQ(device.why(), "");
    game::audio::Synthesizer synth;
    synth.click();
    device.feed(synth, 0.05);
    EXPECT_EQ(synth.cursor(), 2400); // 50 ms at 48 kHz into an empty queue
    device.feed(synth, 0.05);
    EXPECT_LE(synth.cursor(), 2400 + 1200) << "a full queue takes only what was played";
}
