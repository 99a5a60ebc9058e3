// The match being played in the game screen: the session under its fixed-step clock, the
// player's aim (mouse, keys, controller), the time controls (pause, one tick, slow and
// fast), and what the screen says about it (a refused command, a branch, a new best).
// Every change to the match goes through submit(): a Command, as from a script.
#pragma once

#include "game/session.h"
#include "physics/clock.h"
#include "ui/game/aim_input.h"
#include "ui/game/game_menus.h"
#include "ui/game/player_files.h"
#include "ui/game/tick_budget.h"
#include "ui/play/physics_panel.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ui {

class PadInput;

/// The options of a live match of `level`: the computer's difficulty and seed, and the
/// file the session records into at each turn's end ("" = not recorded). A save that
/// fails at a turn's end does not stop the match: the first failure is said on the
/// terminal and in `status` (which must outlive the session), once.
game::SessionOptions liveSessionOptions(PlayerFiles& files, const game::Level& level,
                                        const std::string& recordFile, std::string& status);

class LivePlay {
  public:
    /// `tickBudgetSeconds`: wall time a frame may spend on ticks (tick_budget.h).
    explicit LivePlay(std::optional<double> tickBudgetSeconds) : tickBudget_(tickBudgetSeconds) {}

    /// Plays `session` from its current tick (a new match, or a replay taken over).
    void start(std::unique_ptr<game::Session> session);
    /// No match in play (a replay, the editor or the menus alone on screen).
    void stop();
    bool active() const { return session_ != nullptr; }
    game::Session& session() { return *session_; }
    const game::Session& session() const { return *session_; }
    const game::Session* sessionOrNull() const { return session_.get(); }
    game::Match& match() { return session_->match(); }
    const game::Match& match() const { return session_->match(); }
    /// A person is on turn (not the computer) in a match not over.
    bool humanTurn() const;
    /// Whose turn it is, said at its start in a duel ("" otherwise).
    std::string turnBanner(const game::Match& m) const;

    /// Submits `command`; a refused one stays on the HUD a while (notice()). Returns why
    /// it was refused, "" when taken.
    std::string submit(const game::Command& command);
    /// Submits each; returns the last refusal, "" when all were taken.
    std::string submit(const std::vector<game::Command>& commands);

    /// Once a frame: held arrow keys (when `keysFree`: no menu, no text field) and the
    /// controller's stick and triggers move the aim; let go, it settles as commands.
    void pollHeldInput(double wallSeconds, bool keysFree, PadInput& pad);
    /// Runs the ticks the clock hands out for `wallSeconds` (none while `menuPause`),
    /// `onTick` after each, within the tick budget; the frame's figures into `stats`.
    void simulate(double wallSeconds, bool menuPause, const std::function<void()>& onTick,
                  FrameStats& stats);
    /// Plays `seconds` at once, `onTick` after each tick (--warmup).
    void warmUp(double seconds, const std::function<void()>& onTick);

    /// Back to `tick` (earlier than now), playing on from there as a branch.
    void rewindTo(std::uint64_t tick);
    /// The game in play branched (a replay taken over at `tick`): `note` says from what.
    void markBranch(std::string note, std::uint64_t tick);
    const std::string& branchNote() const { return branchNote_; }

    /// True once, when the match has ended and its result is not yet recorded.
    bool takeFinish();
    /// The result being recorded was the level's best: the banner says so.
    void setNewBest(bool newBest) { newBest_ = newBest; }
    /// A match already over is not recorded again (a replay taken over at its end).
    void markRecorded() { resultRecorded_ = true; }
    bool resultRecorded() const { return resultRecorded_; }

    /// The line at the top of the picture ("PAUSED ...", "SLOW MOTION ...", "BRANCH
    /// ...", "the computer is aiming...", "new best ..."), "" for none.
    std::string banner() const;
    /// The refused command the HUD shows now ("spawn: ..."), "" for none.
    std::string notice() const { return noticeSeconds_ > 0.0 ? notice_ : std::string(); }
    /// Shows `text` on the HUD a while, as a refusal is (a key with nothing to do here):
    /// `seconds` of wall time, a few by default.
    void say(std::string text, double seconds = 3.0);
    /// The notice fades with wall time.
    void fadeNotice(double wallSeconds);

    AimInput& aim() { return aim_; }
    const AimInput& aim() const { return aim_; }
    TimeControls& time() { return time_; }
    RewindControl& rewind() { return rewind_; }
    bool clockPaused() const { return clock_.paused(); }
    /// Wall time a frame may spend on ticks (tick_budget.h; none: no limit).
    std::optional<double> tickBudget() const { return tickBudget_; }

  private:
    std::unique_ptr<game::Session> session_;
    phys::FixedClock clock_;
    std::optional<double> tickBudget_; ///< wall s a frame may spend on ticks (tick_budget.h)
    SlowMotion slowMotion_;            ///< the budget cut a frame lately
    TimeControls time_;
    AimInput aim_;
    RewindControl rewind_;
    /// Where the game in play branched from (a replay taken over, a rewind), "" if not.
    std::string branchNote_;
    std::uint64_t branchTick_ = 0;
    /// Whose turn it is and the tick it began: a duel says "Your turn" for its first seconds.
    int turnPlayer_ = -1;
    std::uint64_t turnStartTick_ = 0;
    bool resultRecorded_ = false;
    bool newBest_ = false;
    /// What the match refused last (a spawn outside the world, say), shown on the HUD
    /// for noticeSeconds_ more of wall time: else the press seems to do nothing.
    std::string notice_;
    double noticeSeconds_ = 0.0;
};

} // namespace ui
