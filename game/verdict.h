// One verdict per shot: what the shot did, in a line, decided once from its outcome (the
// targets it hit, the blocks and blobs it knocked down, a cannon hit, else its nearest
// miss) when the shot is over and what it set moving has come to rest, or at the next
// shot or the match's end, whichever comes first. The match reports it as a Verdict event
// (value: the points the shot earned, 0 in a duel); the screen shows that text and no
// other, so the screen and `artillery run --json` say the same. A sandbox has no
// targets and no score: its shots get no verdict. A shot flown by an integrator where the
// closed form is exact adds how far it landed from the exact path, in the same words
// (exactPathText): "missed by 0.5 m, over; explicit Euler, 30 Hz: 0.69 m long of the
// exact path; energy +1.5 %".
//
// A miss is measured from the shell's path to the outline of each target still standing
// (a disc's rim, a block's box, a blob's circle; the enemy cannons in a duel): the
// closest it came. Its side is called as artillery observers call a round, for that
// nearest target: "over" when the path crossed the target's line above it, "under" when
// below it (a disc in the air), "short" when the shell came down before reaching it.
#pragma once

#include "physics/vec2.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace game {

class Match;
struct GameEvent;

/// "missed by 3.2 m, long" (one decimal); an empty side gives "missed by 3.2 m".
std::string missText(double missMetres, const std::string& side);

/// The side of a miss from how the path crossed the target's vertical line: +1 above it
/// ("over"), -1 below it ("under"), 0 not at all ("short").
std::string missSide(int crossed);

/// What a shot did, as the verdict's text reads it.
struct ShotTally {
    int player = 0;
    int points = 0;
    int discsHit = 0;
    int toppled = 0;
    std::vector<int> cannonsHit; ///< cannon indices, once each
    double miss = INFINITY;      ///< m, the closest the shell came to a standing target
    std::string side;            ///< of that miss: "short", "over", "under"
    phys::Vec2 landing;          ///< the shell's last place
};

/// The verdict's text: "hit +150", "toppled 2 +200", "hit and toppled 2 +350",
/// "hit the computer's cannon", "missed by 4.0 m, short"; `cannonNames` names each
/// cannon for a hit on it.
std::string verdictText(const ShotTally& t, bool duel, const std::vector<std::string>& cannonNames);

/// The longest a shot's verdict (and, out of shots, a practice game's end) waits for what
/// the shot set moving to come to rest, s: a rope that swings a crate may never quite stop.
inline constexpr double kSettleSeconds = 4.0;

/// Nothing that could still fall over is moving: every block and target blob at rest
/// (below 5 cm/s and 0.05 rad/s).
bool structuresAtRest(const Match& m);

/// Follows the shot in flight through the match's events and ticks, and gives its verdict
/// once. Plain data: a copied match judges on from where it was.
class ShotJudge {
  public:
    /// Each event the match emits, as it emits it.
    void observe(const Match& m, const GameEvent& e);
    /// After each tick: the verdict, when the shot is over and has settled.
    std::optional<GameEvent> afterTick(const Match& m);
    /// The verdict of a shot still open, now (the next shot, the match's end).
    std::optional<GameEvent> close(const Match& m);

  private:
    void sample(const Match& m, phys::Vec2 p);
    GameEvent verdict(const Match& m);

    std::vector<signed char> crossed_; ///< by target id: missSide's crossing, once
    std::size_t nearest_ = 0;          ///< the target id of the closest miss
    bool open_ = false;
    bool shotOver_ = false;
    std::uint64_t overTick_ = 0;
    ShotTally tally_;
    std::string model_;      ///< what flies the shot (the `fired` event's model)
    std::string comparison_; ///< its landing against the exact path (game/exact_path.h)
};

} // namespace game
