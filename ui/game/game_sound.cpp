#include "ui/game/game_sound.h"

#include <iostream>

namespace ui {

GameSound::GameSound(bool window) {
    if (!window) return;
    audio_ = std::make_unique<AudioDevice>();
    if (audio_->silent()) std::cerr << "artillery: playing silent (" << audio_->why() << ")\n";
}

bool GameSound::hearing() const { return audio_ && !audio_->silent(); }

void GameSound::hearTick(const game::Match& m, const Camera& view) {
    if (!hearing()) return;
    // Panned across what the camera shows.
    sound_.setView({view.visibleMin().x, view.visibleMax().x});
    sound_.observe(m);
}

void GameSound::hearFrame(const game::audio::SoundMix& mix, const game::Match* replay,
                          bool replayStopped, bool live, bool paused, const Camera& view) {
    if (!hearing()) return;
    sound_.setMix(mix);
    // A live match was heard tick by tick (hearTick); a replay is heard once a frame.
    // Stopped time (paused, a menu open) silences the whistle: the shell hangs still.
    if (replay) {
        if (replayStopped)
            sound_.stillWhistles();
        else
            hearTick(*replay, view);
    } else if (!live) {
        sound_.forgetMatch();
    } else if (paused) {
        sound_.stillWhistles();
    }
    audio_->feed(sound_);
}

void GameSound::click() {
    if (hearing()) sound_.click();
}

} // namespace ui
