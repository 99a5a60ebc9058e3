// Match::previewTrajectory: a shell fired now, flown by the same physics in a copy of the
// particle world (the preview, the computer's trial shots).
#include "game/match.h"

#include "game/settings.h"
#include "game/weapons.h"
#include "physics/projectiles.h"

#include <cmath>
#include <numbers>

namespace game {

using namespace phys;

namespace {
constexpr double kDegToRad = std::numbers::pi / 180.0;
} // namespace

std::vector<Vec2> Match::previewTrajectory(double angleDeg, double speedMps, double seconds,
                                           double stopPastX,
                                           std::optional<std::size_t> projectile,
                                           int bounces) const {
    World w(world_.def());
    w.setProfiling(false); // stepped up to 2,400 times for one look ahead
    w.shapes = world_.shapes;
    // The materials as they are now (a live restitution setting), and the shell's own
    // material as fire() gives it: a bouncer's e = 0.9, not its rubber body's 0.828.
    w.materials = world_.materials;
    const double a = angleDeg * kDegToRad;
    const Ammo ammo = ammoAt(projectile.value_or(cannon().projectile));
    ParticleDef pd = particleDef(ammo.preset, muzzle(angleDeg),
                                 {speedMps * std::cos(a), speedMps * std::sin(a)});
    pd.material = ammo.weapon ? weaponMaterial(w.materials, ammo)
                              : projectileMaterial(w.materials, ammo.preset);
    const ParticleId id = w.particles.add(pd);
    std::vector<Vec2> out{pd.position};
    const long steps = std::lround(seconds / w.def().tickSeconds);
    for (long i = 0; i < steps; ++i) {
        w.step();
        const Vec2 p = w.particles.position(id);
        out.push_back(p);
        // Without downward gravity nothing brings a shell back: past the top of the world,
        // or past the target, it is gone (else a trial at g = 0 would fly all `seconds`).
        const bool noFall = !(w.def().forces.gravity.y < 0.0);
        if (!w.contacts().empty() && bounces-- == 0) break;
        if (p.x < level_.worldMin.x || p.x > level_.worldMax.x ||
            p.y < level_.worldMin.y || (noFall && p.y > level_.worldMax.y))
            break;
        const double away = pd.velocity.x >= 0.0 ? p.x - stopPastX : stopPastX - p.x;
        if (std::isfinite(stopPastX) && away > 0.0 && (w.particles.vy[id] < 0.0 || noFall)) break;
    }
    return out;
}

} // namespace game
