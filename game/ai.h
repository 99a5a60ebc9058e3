// The computer player. It aims with the firing solution when that is exact (uniform
// gravity only: no drag, no wind, no water), and otherwise by shooting trial shells
// through the same simulation as the game (Match::previewTrajectory) and homing in on
// the angle whose path passes closest to the target. Difficulty sets how much aiming
// error it then adds, drawn from its own seeded generator, so a match with the computer
// is as deterministic as any other.
#pragma once

#include "game/command.h"
#include "game/match.h"

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace game {

enum class Difficulty { Easy, Normal, Hard };
const char* difficultyName(Difficulty d);
std::optional<Difficulty> difficultyFromName(const std::string& name);

/// Standard deviations of the error the computer adds: angle (degrees) and relative speed.
struct AimError {
    double angleDeg;
    double speedFraction;
};
AimError aimError(Difficulty d);

struct AimSolution {
    double angleDeg = 45.0;
    double speedMps = 30.0;
    double missM = INFINITY; ///< closest approach of the chosen path to the target (0 = exact)
    bool exact = false;      ///< from the closed-form firing solution
    int trials = 0;          ///< trial shots simulated
    long trialTicks = 0; ///< ticks of flight they simulated: kMaxTrialTicks and two trials at most
    double flightSeconds = 0.0; ///< from the muzzle to the closest approach, s
};

/// Ticks of trial flight one aim may simulate. The computer plans within one tick of
/// play, so this bounds how long that tick takes: the most any shipped level's aim needs
/// is 435,421 (09_tunnelling, 0.22 s in Release), and a level where no path comes
/// near (a 20 km world without gravity, found by the level fuzzer) needed 1.7 million.
/// Past it a trial counts as a miss and is not flown, so the search ends with the best
/// aim found so far.
inline constexpr long kMaxTrialTicks = 500'000;

/// Best aim from the current cannon at `target`, without error. Exact when the match is
/// ballistic-only; otherwise trial shots, of `projectile` (an index into the cannon's
/// list) or else of the selected one.
AimSolution aimAt(const Match& match, phys::Vec2 target,
                  std::optional<std::size_t> projectile = {});

/// The moving target (a disc on a path) at `target`, if the point is one; else null.
const TargetState* movingTargetAt(const Match& match, phys::Vec2 target);

/// aimAt for a shot fired `delaySeconds` from now (0: now): a moving target is led, aimed
/// at where it will be when the shell gets there (the flight time of the aim at where it
/// is now, then of the aim at that point). The computer's turn and the window's hint aim
/// by it.
AimSolution aimToFireNow(const Match& match, phys::Vec2 target,
                         std::optional<std::size_t> projectile = {}, double delaySeconds = 0.0);

class ComputerPlayer {
  public:
    explicit ComputerPlayer(Difficulty d, std::uint64_t seed) : difficulty_(d), rng_(seed) {}
    /// Commands for the current turn (select, aim, power, fire, or end_turn), all stamped
    /// at `tick`, for a shot fired `delaySeconds` after it (a moving target is led for then).
    std::vector<Command> takeTurn(const Match& match, std::uint64_t tick, double delaySeconds = 0.0);
    Difficulty difficulty() const { return difficulty_; }

  private:
    double gaussian();
    Difficulty difficulty_;
    std::mt19937_64 rng_;
};

/// Where the computer aims: the nearest enemy cannon in a duel, else the nearest target
/// still standing: a disc not yet hit, a target block or target blob not yet knocked off.
std::optional<phys::Vec2> chooseTarget(const Match& match);

} // namespace game
