// Feedback on every shot, from the match's events and the shell's path: the shot's
// verdict as the match gave it ("hit +150", "missed by 3.2 m, short": game/verdict.h),
// a marker where a missing shot came down, and a marker where it hit. A view of the
// match: it reads, never writes, and judges nothing itself.
#pragma once

#include "game/exact_path.h"
#include "physics/vec2.h"

#include <optional>

#include <cstdint>
#include <string>
#include <vector>

namespace game {

class Match;
struct GameEvent;

struct ShotNote {
    /// Miss: a marker where a shot that scored nothing came down; Verdict: the shot's
    /// verdict (its text), until the next shot; Hit: a marker where it scored; Exact: the
    /// exact path beside an integrator's shot, to its landing (how far apart they came
    /// down is the verdict's, in its words).
    enum class Kind { Miss, Hit, Verdict, Exact } kind = Kind::Miss;
    phys::Vec2 where; ///< m
    std::string text;
    double age = 0.0;  ///< s
    double life = 1.5; ///< s, shown this long
};

class ShotFeedback {
  public:
    /// Takes one event of the match (in order).
    void event(const Match& match, const GameEvent& e);
    /// After each tick: follows the shell and ages its markers and verdict by `dt` seconds.
    void tick(const Match& match, double dt);
    void reset();

    const std::vector<ShotNote>& notes() const { return notes_; }
    /// The last shot's verdict while it is shown ("" when none is).
    std::string verdict() const;
    /// Where the last shot came down (its last position in flight, or its burst).
    const std::vector<phys::Vec2>& landings() const { return landings_; }
    /// The last shot's exact path, when an integrator flew it where a closed form exists.
    const std::optional<ExactPath>& exactPath() const { return exact_; }

  private:
    std::vector<ShotNote> notes_;
    std::vector<phys::Vec2> landings_;
    phys::Vec2 shellAt_;
    bool inFlight_ = false;
    bool scored_ = false;
    std::string model_; ///< what flies the shot (the `fired` event's model)
    std::optional<ExactPath> exact_;
};

} // namespace game
