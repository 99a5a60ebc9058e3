// Conserved quantities and a state hash: what tests, the guard and the stats panel read.
// Below them, what the debug view draws (the "Draw" controls): net forces, the
// closed-form reference of integrated flights, contacts, the broad-phase grid's occupied
// cells and the model each particle is in, computed here so the picture is testable
// without a renderer (ui/render/world_view.h draws them through DebugDraw).
//
// Section index
//   conserved     energy, momentum, stateHash
//   debug view    ParticleModel, netForces, ClosedFormGhosts, ContactMark, OccupiedCells
#pragma once

#include "physics/ballistics.h"
#include "physics/forces.h"
#include "physics/particles.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace phys {

struct EnergyReport {
    double kinetic = 0.0;   ///< sum 1/2 m |v|^2, J
    double potential = 0.0; ///< gravitational, -m g.p (zero at the origin), J
    double elastic = 0.0;   ///< sum 1/2 k (L - L0)^2 over unbroken springs, J
    double total() const { return kinetic + potential + elastic; }
};

/// Energy of the moving (non-fixed) particles and springs.
EnergyReport energy(const ParticleSet& set, const std::vector<Spring>& springs,
                    const ForceDef& forces);
/// Total linear momentum sum m v of the moving particles, kg m/s.
Vec2 momentum(const ParticleSet& set);

/// FNV-1a 64-bit hash over the exact bits of every alive particle's state and flags.
/// Equal hashes after equal ticks is how determinism is tested.
std::uint64_t stateHash(const ParticleSet& set, std::uint64_t seed = 0xcbf29ce484222325ull);
/// Continues an FNV-1a hash over raw bytes.
std::uint64_t hashBytes(std::uint64_t h, const void* data, std::size_t size);

// ---- debug view ------------------------------------------------------------------------

class World;
class RigidWorld;
struct CollisionDef;

/// Which model moves a particle (the order StepProfile counts them in: fixed first, then
/// asleep, then the closed form; the rest is integrated).
enum class ParticleModel { ClosedForm, Integrated, Sleeping, Fixed };
ParticleModel modelOf(std::uint32_t flags, double invMass);

/// The net force of the force generators on every slot at the current state, N: uniform
/// gravity m g, air drag relative to the wind, buoyancy and water drag, springs and point
/// gravity. Contacts act as impulses and rods and cables as projections, not as forces, so
/// neither is in it: a particle resting on the ground shows its weight. Dead and fixed
/// slots get 0. `out` gets one entry per slot.
void netForces(const World& world, std::vector<Vec2>& out);

/// The closed-form reference of every particle the integrator moves through free flight
/// (alive, free, awake, under gravity, not on the closed form, not on a spring or rod):
/// where p0 + v0 t + g t^2/2 from its launch state puts it, so the integrator's error is
/// the distance between the two. Call observe() after every tick.
///
/// The launch state is the state observe() first sees the particle in flight: a new
/// particle after its first tick; one handed from the closed form to the integrator, the
/// parabola it was on (World keeps its launch state); one that bounced (a contact of the
/// tick), woke up, or whose velocity jumped by more than its forces explain (a blast, a
/// body's impulse), its state then. A change of gravity forgets every launch.
class ClosedFormGhosts {
  public:
    struct Launch {
        Vec2 position;    ///< m
        Vec2 velocity;    ///< m/s
        double time = 0;  ///< world time, s
    };
    void observe(const World& world);
    void clear();
    /// The launch state of particle i, if it is followed.
    std::optional<Launch> launch(ParticleId i) const;
    /// Where the closed form puts particle i at world time t, if it is followed.
    std::optional<BallisticState> at(ParticleId i, double t) const;
    /// The gravity the launches are under, m/s^2.
    Vec2 gravity() const { return gravity_; }

  private:
    std::vector<Launch> launch_;
    std::vector<std::uint8_t> on_;     ///< per slot: followed
    std::vector<std::uint32_t> flags_; ///< per slot, at the last observe
    std::vector<Vec2> velocity_, acceleration_; ///< per slot, at the last observe
    std::vector<std::uint8_t> scratch_;         ///< tethered or touched this tick
    std::vector<Vec2> forces_;
    Vec2 gravity_;
    double time_ = 0.0;
};

/// A contact point and its normal, for drawing.
struct ContactMark {
    enum class Kind {
        Particle,     ///< particle on a static shape or on another particle (World::contacts)
        ParticleBody, ///< particle touching a Box2D body (what the coupling exchanges at)
        Bodies,       ///< two Box2D bodies (b2World's touching contacts)
    } kind = Kind::Particle;
    Vec2 point;   ///< m
    Vec2 normal;  ///< unit: into the particle; for two bodies, into the one that is not static
    bool resting = false; ///< particle contacts: resting (no bounce)
};
/// Contacts of the last tick: the particle contacts World::step resolved (at the contact
/// point on particle a's surface), then, with `rigid`, every awake particle's contacts
/// with bodies now (RigidWorld::circleContacts, as the coupling finds them) and Box2D's
/// touching contacts (RigidWorld::contacts). `out` is cleared first.
void contactMarks(const World& world, const RigidWorld* rigid, std::vector<ContactMark>& out);

/// Cells of the broad phase's uniform grid that hold particles. Cell (x, y) covers
/// [x s, (x + 1) s) x [y s, (y + 1) s) for the cell size s.
struct GridCell {
    std::int64_t x = 0, y = 0;
    int particles = 0; ///< whose box reaches into it
    bool operator==(const GridCell&) const = default;
};
struct OccupiedCells {
    double cellSize = 0.0;        ///< s, m
    std::vector<GridCell> cells;  ///< sorted by x, then y
};
/// The grid's cell size: CollisionDef::gridCellSize, or when that is 0 its documented rule,
/// twice the mean extent ((w + h)/2) of the moving particles' boxes, here the boxes of the
/// particles where they are (radius + toiTolerance around the centre); 1 m with nothing
/// moving. The broad phase applies the rule to boxes swept over the step and fattened for
/// its pair cache, so its automatic cells are somewhat larger in motion.
double gridCellSize(const ParticleSet& set, const CollisionDef& def);
/// The cells the boxes of the collidable particles (alive, not kNoCollide) cover; a box
/// spanning more cells than the grid takes (UniformGrid::kMaxCellsPerBox) is kept out of
/// it, as the broad phase does. `out.cells` is cleared first.
void occupiedCells(const ParticleSet& set, const CollisionDef& def, OccupiedCells& out);

} // namespace phys
