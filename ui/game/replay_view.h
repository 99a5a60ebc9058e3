// The replay viewer's controls: a game::ReplayPlayer under its own
// fixed-step clock, with play / pause, one tick either way, speed x1/8 .. x16, a scrub
// slider over the whole recording (backwards too: a re-simulation from the start), the
// previous / next shot, "Take over", which the game screen answers by playing on from
// that tick as a new branch, and "Export video", which writes the replay as an MP4 beside
// the replays (a child `artillery run --video`). The game screen draws the match on its
// usual path (MatchView, drawMatchFrame); this file holds only the controls and the clock.
//
// Section index
//   ReplayRequests   what the panel or a key asked the game screen for
//   ReplayViewer     advance() per frame, panel(), key(), banner()
#pragma once

#include "game/replay_player.h"
#include "physics/clock.h"
#include "ui/game/match_view.h"
#include "ui/game/tick_budget.h"
#include "ui/video/video_export.h"

#include <SDL_keyboard.h>
#include <imgui.h>

#include <cstdint>
#include <optional>
#include <string>

namespace ui {

/// What the viewer asks of the game screen this frame.
struct ReplayRequests {
    bool takeOver = false; ///< play on from here, recording a branch
    bool close = false;    ///< back to the list of replays
    bool exportVideo = false; ///< write the replay as a video (exportVideo())
    bool backToGame = false;  ///< an instant replay: back to the live game (makeInstant())
};

/// Replay speeds the [ and ] keys step through (simulated seconds per wall second).
inline constexpr float kReplaySpeeds[] = {0.125f, 0.25f, 0.5f, 1.0f, 2.0f, 4.0f, 8.0f, 16.0f};

class ReplayViewer {
  public:
    /// `file` names the replay in the panel; `level` is the replay's (levelForReplay).
    ReplayViewer(std::string file, const game::Level& level, game::Replay replay);

    /// Feeds one frame's wall time: carries out a pending jump, then plays the ticks the
    /// clock hands out at the chosen speed (none while paused or while `held`, a menu
    /// being open). `view` observes every tick played and forgets its trails on a jump
    /// back. A frame spends at most `tickBudgetSeconds` of wall time on ticks
    /// (tick_budget.h; none: no limit).
    void advance(double wallSeconds, bool held, MatchView& view,
                 std::optional<double> tickBudgetSeconds = std::nullopt);
    /// Plays `seconds` at once, without drawing (--warmup).
    void warmUp(double seconds, MatchView& view);
    /// The "Replay" window, its top-left corner at `corner` (window points): what it is,
    /// the transport, the scrub bar, whether it plays as recorded, take over, export.
    ReplayRequests panel(ImVec2 corner);
    /// A key press (repeats included: held . or arrows keep stepping). Returns what it
    /// asks of the screen; keys it does not know are left to the screen.
    ReplayRequests key(const SDL_Keysym& key, bool repeat, bool& handled);
    /// Goes to `tick` at the next advance() (clamped to the recording).
    void requestSeek(std::uint64_t tick) { seek_ = tick; }
    /// The line on top of the picture: "REPLAY x2  12.3 s", "REPLAY paused", ..., with
    /// "SLOW MOTION ..." after it while the tick budget holds the replay back.
    std::string banner() const;

    /// No tick plays (paused, held by a menu, or at the end).
    bool stopped() const { return clock_.paused(); }
    const game::Match& match() const { return player_->match(); }
    const game::ReplayPlayer& player() const { return *player_; }
    const std::string& file() const { return file_; }
    /// Writes the whole replay as FOLDER/NAME.mp4 (the replay's own folder when `folder` is
    /// ""), in the background; the panel says where it went or why it failed.
    void exportVideo(const std::string& folder);
    /// The match as a live session from the current tick (the viewer is spent).
    game::Session takeOver(const game::SessionOptions& options);
    /// An instant replay of the live game (its recording so far, watched from `fromTick`):
    /// the panel offers the way back to the game in place of the list of replays and the
    /// export (the recording is not a file yet). Around `impactTick` (from a quarter of a
    /// second before to three quarters after) it plays at x1/4, unless the player picks a
    /// speed.
    void makeInstant(std::uint64_t fromTick, std::optional<std::uint64_t> impactTick = {});
    bool instant() const { return instant_; }

  private:
    void togglePlay();
    void transportRow();
    void verdictLine();
    void changeSpeed(int by);
    void jumpBy(double seconds);
    /// The panel's words about "Export video": running, where it went, or why not (in
    /// the tooltip). False, and nothing drawn, before any export.
    bool videoLine();
    /// The shot to go back to: within half a second of a shot's start, the one before
    /// it (so pressing again while playing keeps going back).
    std::optional<std::uint64_t> previousShot() const;
    double tickSeconds() const { return match().world().def().tickSeconds; }

    std::string file_;
    std::optional<game::ReplayPlayer> player_;
    phys::FixedClock clock_;
    bool paused_ = false;
    bool instant_ = false;
    SlowMotion heldBack_; ///< the tick budget cut a frame lately
    /// An instant replay's slow motion around the impact: ticks [first, second).
    std::optional<std::pair<std::uint64_t, std::uint64_t>> slowMotion_;
    bool speedPicked_ = false; ///< the player chose a speed: no slow motion then
    /// The speed the replay plays at now, an index into kReplaySpeeds: the slow
    /// motion's, or the one chosen.
    int speedNow() const;
    bool stepRequested_ = false;
    int speed_ = 3;                     ///< index into kReplaySpeeds (x1)
    std::optional<std::uint64_t> seek_; ///< a jump asked for, done at the next advance()
    VideoExport video_;                 ///< "Export video", running or done
};

} // namespace ui
