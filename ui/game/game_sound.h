// The game screen's sound: the synthesizer hears the match on screen (a live one after
// every tick, a replay once a frame) and the sound card plays it. Nothing without a card
// (headless, or a machine with none: the game plays silent and says why once).
#pragma once

#include "game/audio/synthesizer.h"
#include "game/match.h"
#include "ui/platform/audio_device.h"
#include "ui/render/camera.h"

#include <memory>
#include <string>

namespace ui {

class GameSound {
  public:
    /// `window`: a real window (headless screens open no device).
    explicit GameSound(bool window);

    /// A device is open and plays.
    bool hearing() const;
    /// Why the game plays silent ("" when it plays, or opened no device).
    std::string silentWhy() const { return audio_ ? audio_->why() : std::string(); }
    /// After a tick of `m`: its new events become voices, panned across what `view` shows.
    void hearTick(const game::Match& m, const Camera& view);
    /// Once a frame: what to hear of the screen now, then the frame's samples to the card.
    /// `replay` is the match of a replay being watched (heard once a frame; `replayStopped`
    /// while it plays no tick), `live` whether a live match is on screen, `paused` whether
    /// its clock is stopped (the shell hangs still: its whistle too).
    void hearFrame(const game::audio::SoundMix& mix, const game::Match* replay, bool replayStopped,
                   bool live, bool paused, const Camera& view);
    /// A button, box or slider pressed.
    void click();

  private:
    /// The sound card (window only; silent when there is none) and what it plays: voices
    /// start as the match's events are heard, a frame at a time.
    std::unique_ptr<AudioDevice> audio_;
    game::audio::Synthesizer sound_{game::audio::SynthesizerDef{.live = true}};
};

} // namespace ui
