// The physics lab's sound: its shots, the shell's whistle and where it lands, told to
// the game's synthesizer (game/audio/synthesizer.h) after each frame's ticks, as the
// synthesizer hears a match. It reads the scene and never writes it.
//
// The drag-free twin that flies beside the shell when air acts is a reference line,
// not a second shell: it makes no sound. The spring chain is silent too.
#pragma once

#include "game/audio/synthesizer.h"
#include "ui/demo/demo_scene.h"

#include <cstdint>
#include <vector>

namespace ui {

class DemoSound {
  public:
    /// What happened in `scene` since the last call: a report for each shot, a thud for
    /// each landing of a shell, and the whistle of each shell in flight (a shot leaves
    /// before the last one lands), heard from the middle of the view at height
    /// `listenerY` (m). While time is `stopped` (paused) nothing flies: no whistle.
    void hear(const DemoScene& scene, game::audio::Synthesizer& synth, double listenerY,
              bool stopped);

  private:
    std::uint64_t shotsHeard_ = 0, landingsHeard_ = 0;
    std::vector<game::audio::KeyedShell> flying_; ///< the shells in flight (scratch)
};

} // namespace ui
