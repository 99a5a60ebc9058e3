// The built-in demo scene, in physics terms only, until levels exist: a
// cannon that fires a shell every few seconds (with a drag-free reference shell beside
// it whenever air drag is on, so the cost of drag is visible), and a spring chain
// hanging from a gallows. There are no collisions yet: a shell that reaches the ground
// is retired and its landing point marked.
#pragma once

#include "physics/world.h"

#include <cstdint>
#include <vector>

namespace ui {

using phys::Vec2;

/// Definition of the demo, with defaults and units.
struct DemoDef {
    Vec2 cannonPivot{0.0, 1.1};       ///< barrel pivot, m
    double barrelLength = 2.4;        ///< m; shells leave at the muzzle
    double angleDeg = 52.0;           ///< elevation, degrees counter-clockwise from +x
    double muzzleSpeed = 24.0;        ///< m/s
    double fireInterval = 2.5;        ///< s of simulated time between shots
    double shellMass = 4.0;           ///< kg
    double shellRadius = 0.22;        ///< m
    double shellCd = 0.47;            ///< drag coefficient (smooth sphere)
    double groundY = 0.0;             ///< m; shells below it have landed
    double maxFlightSeconds = 20.0;   ///< s; shells older than this are retired anyway
    Vec2 chainAnchor{31.0, 15.0};     ///< top of the chain, m
    int chainLinks = 14;              ///< particles below the anchor
    double linkLength = 0.55;         ///< rest length of each spring, m
    double linkMass = 0.25;           ///< kg
    double bobMass = 1.5;             ///< kg, the last particle
    double linkStiffness = 600.0;     ///< N/m
    double linkDamping = 0.6;         ///< N s/m
    double chainStartAngleDeg = 55.0; ///< initial swing from the vertical, degrees
    int trailEveryTicks = 2;          ///< trail points are recorded every this many ticks
};

/// The world settings the demo opens with: 120 Hz, velocity Verlet, quadratic drag on.
phys::WorldDef demoWorldDef();

struct ShellTrack {
    phys::ParticleId id = phys::kNoParticle;
    bool vacuum = false;     ///< the drag-free reference shell
    double firedAt = 0.0;    ///< s
    std::vector<Vec2> trail; ///< m
};

struct Landing {
    Vec2 at;            ///< m
    double time = 0.0;  ///< s, when it landed
    double range = 0.0; ///< horizontal distance from the cannon (the ruler's 0), m
    double speed = 0.0; ///< m/s as it came down (its last tick's)
    bool vacuum = false;
    std::vector<Vec2> trail; ///< the whole flight, kept to fade out
};

class DemoScene {
  public:
    explicit DemoScene(const phys::WorldDef& worldDef = demoWorldDef(), const DemoDef& def = {});

    /// One fixed tick: fire when due, step the world, retire landed shells, record trails.
    void tick();
    /// Fires now (and restarts the interval).
    void fire();
    /// Back to the opening state, keeping the current world settings.
    void reset();

    phys::World world;
    const DemoDef& def() const { return def_; }
    Vec2 muzzle() const;
    const std::vector<ShellTrack>& shells() const { return shells_; }
    const std::vector<Landing>& landings() const { return landings_; }
    /// Seconds of simulated time until the next shot.
    double nextShotIn() const { return nextShot_ - world.time(); }
    /// Shots fired (a shell and, with air, its drag-free twin) and shells landed since the
    /// scene was made, resets included: what is new since a count was last looked at.
    std::uint64_t shotsFired() const { return shotsFired_; }
    std::uint64_t landingsMade() const { return landingsMade_; }

  private:
    void buildChain();
    void retireLandedShells();

    DemoDef def_;
    std::vector<ShellTrack> shells_;
    std::vector<Landing> landings_;
    double nextShot_ = 0.0;
    std::uint64_t shotsFired_ = 0, landingsMade_ = 0;
};

} // namespace ui
