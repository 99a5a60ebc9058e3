// Feedback on every shot, from the match's events and the shell's path: where it came
// down and by how much it missed ("missed by 3.2 m, long"), the points it scored as
// pop-ups, and a marker where it hit. A view of the match: it reads, never writes.
//
// Long or short is judged along the line of fire: the landing point is beyond the
// nearest target (seen from the cannon) or before it. The distance is the shot's closest
// miss as the match measured it (ShotOver's value: the closest the shell passed to a
// target's rim); when the match has none (targets that are blocks or blobs), the distance
// from the landing point to the nearest such target's outline.
#pragma once

#include "game/effects/exact_path.h"
#include "physics/vec2.h"

#include <optional>

#include <cstdint>
#include <string>
#include <vector>

namespace game {

class Match;
struct GameEvent;

/// The text a miss shows: "missed by 3.2 m, long" (one decimal; "short" when it came
/// down before the target).
std::string missText(double missMetres, bool longShot);

struct ShotNote {
    /// Miss: how far from the target; Exact: how far from the exact path (at its landing).
    enum class Kind { Miss, Points, Hit, Exact } kind = Kind::Miss;
    phys::Vec2 where; ///< m
    std::string text;
    double age = 0.0;  ///< s
    double life = 1.5; ///< s, shown this long
};

/// A target the view knows of: a point and how far its outline reaches from it (m).
struct TargetMark {
    phys::Vec2 where;
    double reach = 0.0;
};

/// The targets still standing, or the enemy cannons in a duel: what a miss is measured to.
std::vector<TargetMark> standingTargets(const Match& match);

class ShotFeedback {
  public:
    /// Takes one event of the match (in order).
    void event(const Match& match, const GameEvent& e);
    /// After each tick: follows the shell and ages the notes by `dt` seconds.
    void tick(const Match& match, double dt);
    void reset();

    const std::vector<ShotNote>& notes() const { return notes_; }
    /// Where the last shot came down (its last position in flight, or its burst).
    const std::vector<phys::Vec2>& landings() const { return landings_; }
    /// The last shot's exact path, when an integrator flew it where a closed form exists.
    const std::optional<ExactPath>& exactPath() const { return exact_; }

  private:
    void landed(const Match& match, double closestMiss);

    std::vector<ShotNote> notes_;
    std::vector<phys::Vec2> landings_;
    phys::Vec2 shellAt_;
    bool inFlight_ = false;
    bool scored_ = false;
    int shooter_ = 0;
    std::vector<TargetMark> aimedAt_; ///< the targets standing when the shot was fired
    std::string model_;               ///< what flies the shot (the `fired` event's model)
    std::optional<ExactPath> exact_;
};

} // namespace game
