// The physics lab heard: each shot once, each landing of the shell (not of its drag-free
// twin) once, the shell's whistle while it flies; after a reset too.
#include "game/audio/synthesizer.h"
#include "ui/demo/demo_scene.h"
#include "ui/demo/demo_sound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace {

using game::audio::VoiceKind;

/// Ticks the scene for `seconds`, the sound hearing it every second tick (a 60 Hz frame)
/// and rendering a frame's samples.
void play(ui::DemoScene& scene, ui::DemoSound& sound, game::audio::Synthesizer& synth,
          double seconds) {
    std::vector<float> frame(2 * 800);
    const int ticks = static_cast<int>(seconds / scene.world.def().tickSeconds);
    for (int t = 1; t <= ticks; ++t) {
        scene.tick();
        if (t % 2 == 0) {
            sound.hear(scene, synth, 10.0, false);
            synth.render(frame.data(), 800);
        }
    }
}

std::size_t landingsOfTheShell(const ui::DemoScene& scene) {
    std::size_t n = 0;
    for (const ui::Landing& l : scene.landings())
        n += l.vacuum ? 0 : 1;
    return n;
}

} // namespace

TEST(DemoSound, EachShotAndEachLandingOfTheShellIsHeardOnce) {
    ui::DemoScene scene; // air drag on: each shot has a drag-free twin
    ui::DemoSound sound;
    game::audio::Synthesizer synth{game::audio::SynthesizerDef{.live = true}};
    synth.setView({-5.0, 65.0});
    play(scene, sound, synth, 10.0);
    ASSERT_EQ(scene.shotsFired(), 4u);   // at 0.1, 2.6, 5.1 and 7.6 s
    ASSERT_EQ(scene.landingsMade(), 6u); // three shells and their twins
    EXPECT_EQ(synth.started(VoiceKind::Report), 4u);
    EXPECT_EQ(landingsOfTheShell(scene), 3u);
    EXPECT_EQ(synth.started(VoiceKind::Impact), 3u) << "the twin is a reference line: silent";
    for (const ui::Landing& l : scene.landings())
        EXPECT_GT(l.speed, 15.0) << "a shell fired at 24 m/s comes down fast";
    EXPECT_EQ(synth.started(VoiceKind::Whistle), 4u) << "one whistle a shell";
    EXPECT_GT(synth.voices(), 0u);

    // A reset: the counts go on, and nothing is heard twice.
    scene.reset();
    play(scene, sound, synth, 1.0);
    EXPECT_EQ(synth.started(VoiceKind::Report), 5u);
    EXPECT_EQ(synth.started(VoiceKind::Impact), 3u);
}

// Paused, the shell hangs in the air: its whistle fades out, and comes back with time.
TEST(DemoSound, APausedLabIsSilent) {
    ui::DemoScene scene;
    ui::DemoSound sound;
    game::audio::Synthesizer synth{game::audio::SynthesizerDef{.live = true}};
    synth.setView({-5.0, 65.0});
    play(scene, sound, synth, 1.5); // the first shell is in flight, its report over
    ASSERT_EQ(synth.started(VoiceKind::Whistle), 1u);
    std::vector<float> frame(2 * 800);
    for (int f = 0; f < 60; ++f) { // a second of paused frames
        sound.hear(scene, synth, 10.0, true);
        synth.render(frame.data(), 800);
    }
    EXPECT_TRUE(std::all_of(frame.begin(), frame.end(), [](float x) { return x == 0.0f; }));
    EXPECT_EQ(synth.voices(), 0u);
    play(scene, sound, synth, 0.1);
    EXPECT_EQ(synth.started(VoiceKind::Whistle), 2u) << "going on, the shell whistles anew";
}
