// Watching and branching in the game screen: a recorded game in the replay viewer (from
// `--replay FILE` or the Replays list), the live game's last shot again (Z), taking a
// replay over as a new live game from the moment watched ("take over": a new replay
// branches from there). Rewinding the live game itself is LivePlay::rewindTo.
#pragma once

#include "game/level.h"
#include "ui/game/live_play.h"
#include "ui/game/match_view.h"
#include "ui/game/player_files.h"
#include "ui/game/replay_view.h"

#include <memory>
#include <string>

namespace ui {

class ReplayControl {
  public:
    /// The replay on screen, if any.
    ReplayViewer* viewer() { return viewer_.get(); }
    const ReplayViewer* viewer() const { return viewer_.get(); }
    bool watching() const { return viewer_ != nullptr; }
    /// Watching the live game's last shot (the game in `play` waits behind it).
    bool instant(const LivePlay& play) const { return viewer_ && viewer_->instant() && play.active(); }

    /// Watches `file`, a replay of `level` (game::levelForReplay, hotseat applied).
    void watch(const std::string& file, const game::Level& level, game::Replay replay);
    void close() { viewer_.reset(); }
    /// The live game's last shot again: its recording so far, watched from half a second
    /// before the shot, while the game waits; at the end (or Z, Esc) play goes on where it
    /// stood (backToLive). False when no shot has been fired, or one is still flying.
    bool watchLastShot(LivePlay& play);
    /// Leaves the replay for the live game: watched to its end, the replay stands where
    /// the game does, trails and all; left sooner, `view` starts again from the game.
    void backToLive(const LivePlay& play, MatchView& view);
    /// Plays on from the moment watched as a live game in `play`, recording a new file
    /// per branch in the replays folder (the replay watched stays as it was); `level` is
    /// the level played. Says where in `status` when the branch cannot be saved.
    void takeOver(LivePlay& play, PlayerFiles& files, const game::Level& level,
                  std::string& status);

  private:
    std::unique_ptr<ReplayViewer> viewer_;
};

} // namespace ui
