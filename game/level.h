// A level: the terrain, the cannons, the targets and the things to knock down, plus
// the physics it is played under. Loaded from JSON (format in levels/README.md); the
// loader checks everything and either returns a whole Level or throws one LoadError
// naming the file, the JSON path and what was expected. Nothing is half-loaded.
#pragma once

#include "physics/vec2.h"

#include <cstdint>
#include <string>
#include <vector>

namespace game {

using phys::Vec2;

enum class Mode { Practice, Duel, Sandbox };
const char* modeName(Mode m);

/// The physics a level is played under; every field can be changed live in the game.
struct LevelPhysics {
    double gravity = 9.81;        ///< m/s^2, downward
    double airDensity = 1.225;    ///< kg/m^3
    bool drag = true;             ///< quadratic air drag on projectiles
    double windMin = 0.0;         ///< m/s, horizontal; each turn draws wind in [min, max]
    double windMax = 0.0;         ///< m/s
    bool water = false;           ///< a water body below waterLevel
    double waterLevel = 0.0;      ///< m

    bool operator==(const LevelPhysics&) const = default;
};

/// Ground as a heightfield polyline, left to right; blasts carve craters in it when
/// destructible.
struct Terrain {
    std::vector<Vec2> points; ///< strictly increasing x
    bool destructible = true;
    std::string material = "ground";

    bool operator==(const Terrain&) const = default;
};

/// A static obstacle: an open polyline (wall, ramp) or a closed convex polygon, or a circle.
struct Obstacle {
    enum class Shape { Polyline, Polygon, Circle } shape = Shape::Polyline;
    std::vector<Vec2> points; ///< polyline vertices, or convex polygon counter-clockwise
    Vec2 center;              ///< circle
    double radius = 0.0;      ///< circle, m
    std::string material = "steel";

    bool operator==(const Obstacle&) const = default;
};

struct Cannon {
    Vec2 position;
    double angleDeg = 45.0;      ///< initial aim, counter-clockwise from +x
    double speedMps = 30.0;      ///< initial muzzle speed
    double maxSpeedMps = 60.0;   ///< power at full charge
    std::string player = "1";    ///< who fires it: "1", "2" (duel) or "cpu"
    std::vector<std::string> projectiles; ///< preset or weapon names offered; first is selected
    /// Shots of each entry of `projectiles` ({"name", "count"}); -1 = unlimited (a bare name).
    std::vector<int> projectileCounts;

    bool operator==(const Cannon&) const = default;
};

struct Target {
    Vec2 position;               ///< start of the path for moving targets
    double radius = 1.0;         ///< m
    std::vector<Vec2> path;      ///< waypoints; empty = static
    double speedMps = 0.0;       ///< along the path, back and forth
    int points = 100;            ///< score for a hit

    bool operator==(const Target&) const = default;
};

/// A rigid block (Box2D body): structures to topple.
struct Block {
    Vec2 position;               ///< centre, m
    Vec2 size{1.0, 1.0};         ///< width, height, m
    double angleDeg = 0.0;
    std::string material = "wood";
    double density = 600.0;      ///< kg/m^3 (per unit depth of 1 m)
    bool target = false;         ///< counts as a target when knocked off its base

    bool operator==(const Block&) const = default;
};

/// A rope or rope bridge of particles joined by rods, pinned at its ends.
struct Rope {
    Vec2 from, to;
    int segments = 10;
    double sag = 0.0;            ///< extra length, fraction of the straight distance
    bool pinFrom = true, pinTo = true;
    double massPerSegment = 0.5; ///< kg
    /// The end tied to a block (index into Level::blocks) instead of pinned: the rope
    /// holds the block, or the block anchors the rope. -1 = none.
    int fromBlock = -1, toBlock = -1;

    bool operator==(const Rope&) const = default;
};

/// A soft blob: a ring of particles held by springs around a centre particle.
struct Blob {
    Vec2 center;
    double radius = 1.0;         ///< m
    int points = 12;
    double stiffness = 400.0;    ///< N/m
    double mass = 2.0;           ///< kg in all
    bool target = false;

    bool operator==(const Blob&) const = default;
};

struct Level {
    std::string file;            ///< where it was loaded from
    std::string contentHash;     ///< FNV-1a of the file's bytes (replays check it)
    int format = 1;
    std::string name;
    std::string description;
    Mode mode = Mode::Practice;
    Vec2 worldMin{0.0, 0.0}, worldMax{200.0, 100.0}; ///< playfield bounds, m
    LevelPhysics physics;
    Terrain terrain;
    std::vector<Obstacle> obstacles;
    std::vector<Cannon> cannons;
    std::vector<Target> targets;
    std::vector<Block> blocks;
    std::vector<Rope> ropes;
    std::vector<Blob> blobs;
    int shots = 5;               ///< shot budget per player (practice)
    std::uint64_t seed = 1;      ///< seeds the wind and the computer's aim
    std::string lesson;          ///< what the level shows, one line

    bool operator==(const Level&) const = default;
};

/// Current level file format.
inline constexpr int kLevelFormat = 1;

/// Parses level JSON text; `file` names it in errors. Throws LoadError.
Level parseLevel(const std::string& file, const std::string& text);
/// Reads and parses a level file. Throws LoadError.
Level loadLevel(const std::string& file);

} // namespace game
