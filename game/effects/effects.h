// What a shot looks like beyond the physics that scores it: debris and dust thrown by a
// blast, smoke drifting with the wind, the flash, the crust of a crater and the soil it
// scattered, splinters off blocks hit hard or toppled, and splashes where a shell enters
// the water. A view of the match (docs/architecture.md, "Layers": sound, effects and the
// camera are views of the match's events): Effects reads the match and its events after each tick and never
// writes it, so a replay's hashes are the same with effects running or not.
//
// Debris, dust, splinters and spray are particles of the project's own particle layer, in
// a phys::World of their own with gravity alone and no collisions: every one of them is
// on the closed form p(t) = p0 + v0 t + g t^2 / 2 (exact and O(1), the model pass's
// kBallistic), and a piece that reaches the ground settles there as scattered soil or is
// gone. Smoke is not ballistic: it relaxes to the wind with a time constant and rises.
// Every random draw comes from a generator seeded by the level's seed, so the same match
// gives the same effects, frame for frame.
//
// Section index
//   EffectsDef   switches and sizes, with units
//   pieces       Piece kinds, Smoke, Flash, CraterMark, Speck
//   Effects      observe() after each tick, then read the state to draw it
#pragma once

#include "game/effects/shot_feedback.h"
#include "game/effects/water_entry.h"
#include "game/match.h"
#include "physics/world.h"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace game {

struct EffectsDef {
    bool debris = true;                ///< blast debris, dust, splinters, spray
    bool smoke = true;                 ///< smoke puffs that drift with the wind
    int debrisPerBlast = 72;           ///< pieces thrown by a blast of the reference radius
    double referenceBlastRadius = 3.0; ///< m: blasts scale their debris count by r / this
    double debrisSeconds = 3.0;        ///< s, a piece in the air longer than this is gone
    double smokeSeconds = 4.0;         ///< s, a puff's life
    double smokeRelaxSeconds = 0.8;    ///< s, time constant of a puff's approach to the wind
    double smokeRiseMps = 1.5;         ///< m/s, a puff's buoyant rise
    double flashSeconds = 0.18;        ///< s, the flash's life
    std::size_t maxSpecks = 600;       ///< scattered soil kept on the ground (oldest go first)
    std::size_t maxPieces = 2000;      ///< pieces in the air at once (new ones wait their turn)
};

/// What a piece in the air is (how it is drawn).
enum class PieceKind : std::uint8_t { Soil, Dust, Splinter, Spray };

struct Smoke {
    phys::Vec2 position, velocity; ///< m, m/s
    double age = 0.0;              ///< s
    double radius = 1.0;           ///< m, grows with age
};

struct Flash {
    phys::Vec2 where;
    double radius = 1.0; ///< m
    double age = 0.0;    ///< s
};

/// A crater carved by a blast: the view darkens the crust along its edge.
struct CraterMark {
    phys::Vec2 center;
    double radius = 1.0; ///< m
};

/// A piece of soil that came down on the ground and stays there.
struct Speck {
    phys::Vec2 where;
    double size = 0.1; ///< m
};

/// A splash ring where the shell entered the water.
struct Ripple {
    phys::Vec2 where;
    double age = 0.0;      ///< s
    double strength = 1.0; ///< entry speed / 20 m/s
};

class Effects {
  public:
    explicit Effects(const EffectsDef& def = {});

    /// Call after every tick of `match` (or every few): turns the new events into effects
    /// and advances everything by the ticks since the last call. A match whose tick went
    /// back (a rewind) starts afresh.
    void observe(const Match& match);
    /// Forgets everything (a new match).
    void reset();

    const EffectsDef& def() const { return def_; }
    /// The pieces in the air: a particle set on the closed form (positions, radii).
    const phys::ParticleSet& pieces() const { return world_.particles; }
    PieceKind kind(phys::ParticleId id) const { return kinds_[id]; }
    /// A piece's colour tint index into the material it came from (0 earth, 1 wood,
    /// 2 stone, 3 steel, 4 water).
    std::uint8_t tint(phys::ParticleId id) const { return tints_[id]; }
    /// Seconds since the piece was thrown.
    double pieceAge(phys::ParticleId id) const;
    const std::vector<Smoke>& smoke() const { return smoke_; }
    const std::vector<Flash>& flashes() const { return flashes_; }
    const std::vector<CraterMark>& craters() const { return craters_; }
    const std::vector<Speck>& specks() const { return specks_; }
    const std::vector<Ripple>& ripples() const { return ripples_; }
    const ShotFeedback& feedback() const { return feedback_; }
    /// Blast energy to shake the screen by, 0..1, decaying over half a second.
    double shake() const { return shake_; }
    /// Pieces thrown since the last reset (for tests and the bench).
    std::size_t thrown() const { return thrown_; }
    std::size_t thrown(PieceKind kind) const { return thrownOf_[static_cast<std::size_t>(kind)]; }
    /// The last tick's profile of the effects' own world (which model moved each piece).
    const phys::StepProfile& profile() const { return world_.profile(); }
    /// The time of the effects' own world (s since the reset).
    double time() const { return world_.time(); }
    /// Throws a blast's debris, dust, smoke and flash at `at` (observe() does this for
    /// every Burst; tests and the bench call it directly).
    void blast(phys::Vec2 at, double radius, double impulse, std::uint8_t tint);

  private:
    void throwPiece(phys::Vec2 at, phys::Vec2 velocity, double radius, PieceKind kind,
                    std::uint8_t tint);
    void splinters(phys::Vec2 at, double speed, std::uint8_t tint, int count);
    void splash(phys::Vec2 at, double speed);
    void settle(const Match& match);
    /// One tick of everything: pieces, smoke, flashes, ripples, shake, notes.
    void advance(const Match& match, double dt);
    double unit();

    EffectsDef def_;
    phys::World world_;
    std::vector<PieceKind> kinds_;
    std::vector<std::uint8_t> tints_;
    std::vector<double> born_;
    std::vector<Smoke> smoke_;
    std::vector<Flash> flashes_;
    std::vector<CraterMark> craters_;
    std::vector<Speck> specks_;
    std::vector<Ripple> ripples_;
    ShotFeedback feedback_;
    std::mt19937_64 rng_;
    std::size_t seenEvents_ = 0;
    std::uint64_t lastTick_ = 0;
    bool started_ = false;
    double shake_ = 0.0;
    std::size_t thrown_ = 0;
    std::size_t thrownOf_[4] = {};
    std::string firedAmmo_; ///< what the last shot fired (a blast's impulse)
    WaterEntryWatch waterEntry_; ///< the shell's crossings of the water line: splashes
};

} // namespace game
