// The computer's turn as a player sees it. It thinks for a moment, picks its weapon, then
// swings its barrel and its power bar from where they are to its aim over about a second
// (a stream of aim and power commands, eased in and out) and fires. Every step is an
// ordinary command at its tick, so the recording replays the sweep and the shot alike,
// and the session and the network lockstep, which both drive it, play the same turn.
#pragma once

#include "game/ai.h"

#include <deque>
#include <optional>

namespace game {

/// How long the sweep from the current aim to the chosen one lasts (s), and the time
/// between its steps (s): 30 steps a second, smooth at any frame rate a window draws.
inline constexpr double kAimSweepSeconds = 1.0;
inline constexpr double kAimStepSeconds = 1.0 / 30.0;

/// The turn `turn` (takeTurn's select, aim, power, fire, all at `tick`) played out as a
/// sweep for `cannon`: its selects at `tick`, then aim and power commands moving from
/// the cannon's current angle and speed to the turn's, the last of them exactly the
/// turn's, and the fire kAimSweepSeconds after `tick` (to the nearest tick of `dt` s).
/// A turn without a fire (end_turn) is returned as it is.
std::vector<Command> aimSweep(const CannonState& cannon, const std::vector<Command>& turn,
                              std::uint64_t tick, double dt);

/// The computer's turns tick by tick: a pause to think (`thinkTicks`), then its turn as a
/// sweep (aimSweep of ComputerPlayer::takeTurn, a moving target led for the moment of
/// the shot), each command when its tick comes.
class ComputerTurns {
  public:
    ComputerTurns(Difficulty d, std::uint64_t seed, std::uint64_t thinkTicks)
        : player_(d, seed), thinkTicks_(thinkTicks) {}
    /// The commands due at `match`'s current tick while `computersTurn`; when it is not
    /// (a person's turn, a shell in flight, the match over) any plan is forgotten.
    std::vector<Command> due(const Match& match, bool computersTurn);
    /// True from the moment the computer has planned its turn until its last command.
    bool aiming() const { return !plan_.empty(); }

  private:
    ComputerPlayer player_;
    std::uint64_t thinkTicks_;
    std::optional<std::uint64_t> planAt_;
    std::deque<Command> plan_;
};

} // namespace game
