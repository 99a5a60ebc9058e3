// The measuring tools' figures, after PhET's Projectile Motion: a probe on a shot's path
// (its time, position, speed, kinetic and potential energy at a point of it), a tape
// measure between two points (distance and angle), and a stopwatch that starts with the
// shot. A view of the match: it records the shells it sees after each tick and never
// writes the match, so no hash changes with the tools in use.
#pragma once

#include "physics/vec2.h"

#include <optional>
#include <vector>

namespace game {

class Match;

/// The shell at one tick of its flight.
struct ShotSample {
    double t = 0.0; ///< s since it was fired
    phys::Vec2 position, velocity;
};

/// One shot's path, a sample a tick from the muzzle on.
struct ShotRecord {
    int shot = 0;          ///< Match::shotsFired() when it flew
    double mass = 0.0;     ///< kg
    double gravity = 0.0;  ///< |g|, m/s^2
    std::vector<ShotSample> samples;
    bool flying = false;   ///< the shell is still in the air
};

/// Records the shells of a match, the last kMeasuredShots of them.
class ShotRecorder {
  public:
    static constexpr std::size_t kMeasuredShots = 4;
    /// After every tick (a match whose clock went back starts afresh).
    void observe(const Match& match);
    void reset() { *this = ShotRecorder(); }
    const std::vector<ShotRecord>& shots() const { return shots_; }

  private:
    std::vector<ShotRecord> shots_;
    double lastTime_ = -1.0;
};

/// What the probe reads at a point of a path. Potential energy is m |g| y, from y = 0 of
/// the level.
struct ProbeReading {
    double t = 0.0; ///< s since the shot
    phys::Vec2 position, velocity;
    double speed = 0.0;     ///< m/s
    double kinetic = 0.0;   ///< 1/2 m v^2, J
    double potential = 0.0; ///< m |g| y, J
};

/// The sample of any recorded path nearest to `at`, if one lies within `reach` (m).
std::optional<ProbeReading> probe(const std::vector<ShotRecord>& shots, phys::Vec2 at, double reach);

struct TapeReading {
    double distance = 0.0; ///< m
    double angleDeg = 0.0; ///< of the line from `from` to `to`, counter-clockwise from +x
};
TapeReading tape(phys::Vec2 from, phys::Vec2 to);

/// The stopwatch: the last shot's time of flight, running while it flies; none before a
/// shot.
std::optional<double> stopwatch(const std::vector<ShotRecord>& shots);

} // namespace game
