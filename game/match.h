// A match: one level played under its rules. The match owns the particle world and the
// rigid world built from the level, takes Commands at ticks (aim, power, select, fire,
// end_turn, set) and advances one fixed tick at a time, reporting what happened as
// events. Everything that changes the world goes through apply(), so a recorded list
// of commands replays the match to the last bit.
//
// Section index
//   set-up     Match(level), the world built from the level (terrain, obstacles,
//              blocks, ropes, blobs)
//   commands   apply(): aim, power, select, fire, end_turn, set (match_commands.cpp)
//   tick       step(): the physics, what it toppled, the fragments, the shell
//   state      cannons, targets, wind, score, stars, events, hash
//   sandbox    sandbox(), spawn, grab, drag, release (match_sandbox.cpp)
#pragma once

#include "game/ammo.h"
#include "game/command.h"
#include "game/level.h"
#include "game/shell_flight.h"
#include "game/terrain.h"
#include "game/verdict.h"
#include "physics/coupling.h"
#include "physics/guard.h"
#include "physics/rigid/rigid_world.h"
#include "physics/world.h"

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace game {

enum class EventKind {
    Fired,       ///< a shell left a cannon (value: muzzle speed)
    Bounce,      ///< the shell hit something and bounced (value: closing speed)
    Burst,       ///< an explosive shell burst (where: centre)
    Crater,      ///< the ground was carved (value: radius)
    TargetHit,   ///< a target was hit (value: points scored)
    Toppled,     ///< a target block or blob was knocked off its place (value: points)
    CannonHit,   ///< a duel cannon was hit (player: whose cannon; value: hit points left)
    ShotOver,    ///< the shell came to rest, burst or left the world (value: closest miss, m)
    TurnOver,    ///< the turn passed (player: whose turn it is now; value: new wind, m/s)
    MatchOver,   ///< the match ended (player: winner, -1 for none/draw; value: score)
    SettingChanged, ///< a `set` command took effect (text: name = value)
    Refused,     ///< a command was refused (text: why)
    Unstable,    ///< the guard removed particles that blew up (value: how many; text: the cause)
    Landed,      ///< the shell's first contact with anything (where: its centre then; value:
                 ///< closing speed; text: "shape", "body" or "particle"; closedFormErrorM)
    Verdict,     ///< what a shot did, once (player: who fired; value: its points, 0 in a duel;
                 ///< text: "hit +150", "missed by 4.0 m, short"; game/verdict.h)
};
const char* eventName(EventKind k);

struct GameEvent {
    std::uint64_t tick = 0;
    EventKind kind = EventKind::Fired;
    int player = 0;
    phys::Vec2 where;
    double value = 0.0;
    std::string text;
    /// Fired: what flies the shell, "closed-form" or an integrator (game/shot_model.h).
    std::string model;
    /// Landed: how far beyond the exact path's landing on the same surface the shell
    /// landed, m (game/landing.h); none when no closed form exists.
    std::optional<double> closedFormErrorM;
};

struct CannonState {
    Cannon def;
    double angleDeg = 45.0;
    double speedMps = 30.0;
    std::size_t projectile = 0; ///< index into def.projectiles
    std::vector<int> ammoLeft;  ///< shots left of each projectile; -1 = unlimited
    int hitPoints = 3;
    int shotsLeft = 0;
    int score = 0;
};

struct TargetState {
    Target def;
    phys::Vec2 position;
    bool hit = false;
    /// Closest the shell has come while passing through it (m); scored once it recedes.
    double closestInside = INFINITY;
};

/// Where a target is `t` seconds into the match: back and forth along its path at its
/// speed (by arc length), or at its position when it has no path. The match moves its
/// targets by it, and the computer leads a moving one by it.
phys::Vec2 targetPositionAt(const Target& target, double t);

struct BlockState {
    Block def;
    phys::BodyId body;
    bool toppled = false;
};

struct BlobState {
    Blob def;
    phys::ParticleId center = phys::kNoParticle;
    std::vector<phys::ParticleId> ring; ///< the outline, counter-clockwise
    bool toppled = false;
};

/// A rope as built: its definition and the particles at its two ends (the links run
/// between them), so the scene can be read back as a level (game/editor/sandbox_to_level.h).
struct RopeState {
    Rope def;
    phys::ParticleId first = phys::kNoParticle;
    phys::ParticleId last = phys::kNoParticle;
};

/// A cloth as built: its particles row by row from the top-left one, `columns` to a row,
/// and the spacing they were laid at, so it can be drawn as a sheet between them rather
/// than as dots (the simulation knows only particles and springs).
struct ClothState {
    std::vector<phys::ParticleId> particles;
    int columns = 0;
    double spacing = 0.0; ///< m between neighbours at rest
};

/// What the sandbox's hand holds: a block (pulled by a critically damped spring force
/// toward the pointer) or a particle (on a spring to the pointer).
struct GrabState {
    enum class Kind { None, Particle, Body } kind = Kind::None;
    phys::ParticleId particle = phys::kNoParticle;
    phys::BodyId body;
    phys::Vec2 local;  ///< the grabbed point in the body's frame
    phys::Vec2 target; ///< where the hand is, m
    std::size_t spring = 0; ///< index of the hand's spring in world().springs (particles)
};

/// Hit points of a duel cannon, and how close a shell must pass to hit it (m).
inline constexpr int kCannonHitPoints = 3;
inline constexpr double kCannonRadius = 1.5;
/// The learning aids an `assist` command names (bits of Match::assisted()), and the most
/// stars a result can earn with any of them in view.
inline constexpr int kAssistPreview = 1;
inline constexpr int kAssistHint = 2;
inline constexpr int kAssistedMaxStars = 2;
/// A shell still flying after this long is over (s).
inline constexpr double kMaxFlightSeconds = 30.0;

class Match {
  public:
    explicit Match(const Level& level);

    /// Applies a command at the current tick. Returns "" when it took effect, else why
    /// it was refused (also reported as a Refused event); a refused command changes
    /// nothing.
    std::string apply(const Command& command);
    /// Advances one tick (and gives the last shot's verdict once it has settled).
    void step();

    // --- state ---------------------------------------------------------------------
    const Level& level() const { return level_; }
    const phys::World& world() const { return world_; }
    const phys::RigidWorld& rigid() const { return *rigid_; }
    const Heightfield& terrain() const { return terrain_; }
    std::uint64_t tick() const { return world_.tick(); }
    double time() const { return world_.time(); }
    int currentPlayer() const { return current_; }
    const std::vector<CannonState>& cannons() const { return cannons_; }
    const CannonState& cannon() const { return cannons_[static_cast<std::size_t>(current_)]; }
    const std::vector<TargetState>& targets() const { return targets_; }
    const std::vector<BlockState>& blocks() const { return blocks_; }
    const std::vector<BlobState>& blobs() const { return blobs_; }
    /// The level's ropes and the ones spawned in the sandbox, in the order made.
    const std::vector<RopeState>& ropes() const { return ropes_; }
    /// The cloths spawned in the sandbox, in the order made. Not hashed: their particles are.
    const std::vector<ClothState>& cloths() const { return cloths_; }
    /// The particle-body coupling: its events are the last tick's hits of particles on
    /// blocks (read by the sound; nothing may change it from outside).
    const phys::ParticleBodyCoupling& coupling() const { return coupling_; }
    double wind() const { return world_.def().forces.wind.x; }
    /// The shell in flight, if any.
    std::optional<phys::ParticleId> shell() const;
    /// What the shell in flight is doing (its weapon's state: fragments, impacts, tunnel).
    const ShellFlight& flight() const { return flight_; }
    /// The ammunition of the shell in flight (or of the last one).
    const Ammo& shellAmmo() const { return shellAmmo_; }
    bool over() const { return over_; }
    /// Winner of a finished duel (cannon index), -1 for a draw or not over.
    int winner() const { return winner_; }
    /// The learning aids used so far (kAssistPreview | kAssistHint), 0 for none.
    int assisted() const { return assisted_; }
    /// Practice: total score and stars (0..3; 0 until every target is down; at most
    /// kAssistedMaxStars once assisted).
    int score() const;
    int stars() const;
    int maxScore() const;
    /// Every target disc hit and every target block and blob knocked down (true for a
    /// level with none).
    bool allTargetsDown() const;
    const std::vector<GameEvent>& events() const { return events_; }
    /// Hash of everything that evolves: particles, bodies, cannons, targets, wind, turn.
    std::uint64_t hash() const;
    /// The game part alone: cannons, targets, structures, turn, wind, terrain.
    std::uint64_t gameHash() const;
    /// Shots fired so far by everyone.
    int shotsFired() const { return shotsFired_; }
    /// The player has set something moving (a shot, a spawn, a grab): before it the
    /// level's own settling is not an event (its sound is not heard). Not hashed.
    bool stirred() const { return stirred_; }
    /// True when only uniform gravity acts on a shell (no drag, no wind, no water): the
    /// firing solution is exact.
    bool ballisticOnly() const;
    /// True when a shell's path is the closed form p0 + v0 t + g t^2/2: no drag and no
    /// water. Wind acts on a shell only through drag (on v - wind, phys::ForceDef), so wind
    /// without drag leaves the path exact. The `landed` event's closed_form_error_m and
    /// the compare's reference go by this; the firing solutions by ballisticOnly.
    bool closedFormExact() const;

    /// Points a shell fired now from the current cannon would pass through, computed by
    /// the same physics (integrator, tick, drag, wind, terrain and obstacles), up to the
    /// first contact or `seconds`. Bodies, ropes and blobs are left out of the preview.
    /// `stopPastX`, when finite, ends the preview once the shell is past that x going
    /// away from the cannon and descending (the computer's trial shots need no more).
    /// `projectile` (an index into the cannon's list) previews that one instead of the
    /// selected one: the computer aims with what it is about to select. The first `bounces`
    /// ticks with a contact are flown on through; the next one ends it (the computer's
    /// bank and skip shots).
    std::vector<phys::Vec2> previewTrajectory(double angleDeg, double speedMps,
                                              double seconds = 8.0,
                                              double stopPastX = INFINITY,
                                              std::optional<std::size_t> projectile = {},
                                              int bounces = 0) const;
    /// Muzzle point of the current cannon for a given aim (1.5 m along the barrel).
    phys::Vec2 muzzle(double angleDeg) const;
    /// The ammunition selected on the current cannon.
    Ammo selectedAmmo() const;
    /// The ammunition of the current cannon's projectile `index` (none past its list).
    Ammo ammoAt(std::size_t index) const;

    /// What the `set` command changes: the world's settings and its material table.
    LiveSettings liveSettings() const { return {world_.def(), world_.materials}; }
    /// What the material controls show: the projectiles the cannons fire (every preset
    /// in a sandbox), the materials of those and of the particles alive now, and the
    /// materials of the static shapes; each once.
    MaterialsInPlay materialsInPlay() const;

    // --- sandbox --------------------------------------------------------------------
    /// True when the level is a sandbox, or a `sandbox` command made it one: no shot
    /// budget, no score, and spawn, grab, drag and release are allowed.
    bool sandbox() const { return level_.mode == Mode::Sandbox; }
    const GrabState& grab() const { return grab_; }

    /// Test hook of the network desync test (match_tamper.cpp): changes the shell's
    /// velocity by `dv` outside any command, as a tampered client would. False when no
    /// shell is in flight.
    bool perturbShellForTest(phys::Vec2 dv);

  private:
    phys::BodyId addBlock(const Block& b);
    void addRope(const Rope& r);
    void addBlob(const Blob& b);
    std::string spawn(const Command& cmd);
    void addCloth(phys::Vec2 topLeft, double size);
    std::string grabAt(phys::Vec2 at);
    void dragTo(phys::Vec2 at);
    void release();
    /// Each tick: the hand's force on a grabbed block.
    void pullGrabbed();

    void buildWorld();
    void rebuildStaticShapes();
    void fire();
    /// The shell's first contact this tick (it is at `shellNow`): a Landed event with its
    /// closed-form error (game/landing.cpp).
    void reportLanding(phys::Vec2 shellNow);
    /// The tick's rules: particles, coupling, rigid bodies, targets, the shell.
    void stepRules();
    /// Reports the open shot's verdict now, if it has one.
    void closeVerdict();
    void endShot(double closestMiss);
    void nextTurn();
    void finish();
    void emit(EventKind kind, int player, phys::Vec2 where, double value, std::string text = {});
    /// Records the event and lets the shot's judge see it.
    void emit(GameEvent e);
    void updateTargets();
    // The commands (match_commands.cpp): each refused with one line, as a Refused event.
    std::string refuse(const Command& cmd, std::string why);
    std::string select(const Command& cmd);
    std::string set(const Command& cmd);
    std::string sandboxTool(const Command& cmd);
    // The phases of step(), in order.
    /// The particles, the coupling and the rigid bodies; false when the guard removed the
    /// shell (the shot is over).
    bool stepPhysics();
    /// Target blocks and blobs knocked off their place score for whoever fired last
    /// (match_scoring.cpp).
    void scoreToppled();
    /// With no shell in flight, a practice game ends: won once its targets are all down,
    /// or, out of shots, once what the last shot set moving has come to rest.
    void finishWhenDone();
    /// The shell's tick: its passes, a duel hit, its contacts, its weapon, its end.
    void stepShell();
    void followTargetPasses(phys::Vec2 p, double r);
    /// True when the shell hit an enemy cannon (the shot has ended).
    bool hitEnemyCannon(phys::Vec2 p, double r);
    struct ShellTouch {
        bool touched = false; ///< the shell touched anything this tick
        bool impact = false;  ///< at a closing speed over 1 m/s
    };
    ShellTouch shellContacts();
    /// Out of the world, at rest, flown too long or not finite.
    bool shellIsDone(phys::Vec2 p) const;
    /// Scores targets the shell has passed through and is now leaving (or all, at the end).
    void scorePasses(bool shotEnding);
    /// An explosive shell bursts at `at`; `spared` (a cannon index) was already hit directly.
    /// `piece` is the particle that bursts (default: the shell).
    void burst(phys::Vec2 at, int spared = -1, phys::ParticleId piece = phys::kNoParticle);
    // Weapon behaviours (match_weapons.cpp): fuse, bounce count, airburst, apex split,
    // tunnel, stick. True when the shell's shot has ended.
    bool stepWeapon(phys::Vec2 p, bool touched, bool impact);
    /// Bursts at `at` and ends the shot; true (the shot has ended).
    bool burstAndEnd(phys::Vec2 at);
    /// The digger's tunnel: begun at its first touch, carved on each tick until its length.
    void startTunnel(phys::Vec2 p);
    bool stepTunnel();
    /// Whether the shell must not be ended for resting (a fuse or a stuck charge waits).
    bool shellHeld() const;
    void splitShell();
    void stepFragments();
    /// The shell has ended; a fragment still flying takes its place. True if one did.
    bool promoteFragment();
    double drawWind();

    Level level_;
    phys::World world_;
    std::unique_ptr<phys::RigidWorld> rigid_;
    phys::ParticleBodyCoupling coupling_;
    Heightfield terrain_;
    phys::BodyId rigidTerrain_;
    std::vector<CannonState> cannons_;
    std::vector<TargetState> targets_;
    std::vector<BlockState> blocks_;
    std::vector<BlobState> blobs_;
    std::vector<RopeState> ropes_;
    std::vector<ClothState> cloths_;
    std::vector<GameEvent> events_;
    std::mt19937_64 rng_;
    int current_ = 0;
    bool over_ = false;
    int winner_ = -1;
    int shotsFired_ = 0;
    bool stirred_ = false; ///< stirred()
    // The shell in flight.
    phys::ParticleId shell_ = phys::kNoParticle;
    std::uint64_t shellFiredTick_ = 0;
    double closestMiss_ = 0.0;
    Ammo shellAmmo_;
    ShellFlight flight_;
    GrabState grab_;
    int assisted_ = 0;
    ShotJudge judge_;
};

/// Applies every command whose tick is the match's current tick, then steps; repeats
/// until `ticks` ticks have run. Commands must be in tick order. Returns the number of
/// commands applied.
std::size_t runCommands(Match& match, const std::vector<Command>& commands, std::uint64_t ticks,
                        std::size_t next = 0);

} // namespace game
