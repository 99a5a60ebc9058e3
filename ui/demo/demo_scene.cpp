#include "ui/demo/demo_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ui {

namespace {
constexpr double kDegrees = std::numbers::pi / 180.0;
constexpr std::size_t kLandingsKept = 6;
} // namespace

phys::WorldDef demoWorldDef() {
    phys::WorldDef def;
    def.tickSeconds = 1.0 / 120.0;
    def.integrator = phys::Integrator::VelocityVerlet;
    def.forces.drag = phys::DragModel::Quadratic;
    return def;
}

DemoScene::DemoScene(const phys::WorldDef& worldDef, const DemoDef& def)
    : world(worldDef), def_(def) {
    world.particles.reserve(64);
    buildChain();
    nextShot_ = 0.1; // the first shot leaves right after opening
}

void DemoScene::reset() {
    const phys::WorldDef settings = world.def();
    world = phys::World(settings);
    shells_.clear();
    landings_.clear();
    world.particles.reserve(64);
    buildChain();
    nextShot_ = 0.1;
}

Vec2 DemoScene::muzzle() const {
    const double a = def_.angleDeg * kDegrees;
    return def_.cannonPivot + Vec2{std::cos(a), std::sin(a)} * def_.barrelLength;
}

void DemoScene::buildChain() {
    // A fixed anchor particle and links hanging at an angle, so the chain swings from
    // the first tick (a pendulum of springs: stiff along each link, free to bend).
    phys::ParticleDef anchor;
    anchor.position = def_.chainAnchor;
    anchor.mass = 0.0;
    anchor.radius = 0.18;
    phys::ParticleId prev = world.particles.add(anchor);
    const double a = def_.chainStartAngleDeg * kDegrees;
    const Vec2 step = Vec2{std::sin(a), -std::cos(a)} * def_.linkLength;
    for (int i = 1; i <= def_.chainLinks; ++i) {
        const bool bob = i == def_.chainLinks;
        phys::ParticleDef link;
        link.position = def_.chainAnchor + step * i;
        link.mass = bob ? def_.bobMass : def_.linkMass;
        link.radius = bob ? 0.28 : 0.09;
        const phys::ParticleId id = world.particles.add(link);
        phys::Spring s;
        s.a = id;
        s.b = prev;
        s.restLength = def_.linkLength;
        s.stiffness = def_.linkStiffness;
        s.damping = def_.linkDamping;
        world.springs.push_back(s);
        prev = id;
    }
}

void DemoScene::fire() {
    const double a = def_.angleDeg * kDegrees;
    const Vec2 dir{std::cos(a), std::sin(a)};
    auto launch = [&](bool vacuum) {
        phys::ParticleDef shell;
        shell.position = muzzle();
        shell.velocity = dir * def_.muzzleSpeed;
        shell.mass = def_.shellMass;
        shell.radius = def_.shellRadius;
        shell.dragCoefficient = def_.shellCd;
        shell.flags = phys::kProjectile | (vacuum ? phys::kNoDrag : 0u);
        const phys::ParticleId id = world.particles.add(shell);
        shells_.push_back({id, vacuum, world.time(), {shell.position}});
    };
    // With drag (or wind) on, a drag-free twin flies beside the real shell: the gap
    // between their landing points is what the air costs.
    const phys::ForceDef& f = world.def().forces;
    const bool airActs = f.drag != phys::DragModel::None;
    if (airActs) launch(true);
    launch(false);
    ++shotsFired_;
    nextShot_ = world.time() + def_.fireInterval;
}

void DemoScene::tick() {
    if (world.time() >= nextShot_) fire();
    world.step();
    retireLandedShells();
    if (world.tick() % static_cast<std::uint64_t>(std::max(def_.trailEveryTicks, 1)) == 0)
        for (ShellTrack& s : shells_)
            s.trail.push_back(world.particles.position(s.id));
}

void DemoScene::retireLandedShells() {
    for (std::size_t i = 0; i < shells_.size();) {
        ShellTrack& s = shells_[i];
        const Vec2 p = world.particles.position(s.id);
        const bool landed = p.y - def_.shellRadius <= def_.groundY;
        const bool stale = world.time() - s.firedAt > def_.maxFlightSeconds ||
                           !std::isfinite(p.x) || !std::isfinite(p.y);
        if (!landed && !stale) {
            ++i;
            continue;
        }
        if (landed && std::isfinite(p.x)) {
            // Land on the surface, not wherever the last tick overshot to.
            Vec2 at = p;
            const Vec2 last = s.trail.empty() ? p : s.trail.back();
            const double drop = last.y - p.y;
            if (drop > 0.0) {
                const double t = (last.y - def_.shellRadius - def_.groundY) / drop;
                at = last + (p - last) * std::clamp(t, 0.0, 1.0);
            }
            at.y = def_.groundY + def_.shellRadius;
            s.trail.push_back(at);
            const double speed = length(world.particles.velocity(s.id));
            landings_.push_back(
                {at, world.time(), at.x - def_.cannonPivot.x, speed, s.vacuum, std::move(s.trail)});
            ++landingsMade_;
            if (landings_.size() > kLandingsKept) landings_.erase(landings_.begin());
        }
        world.particles.remove(s.id);
        shells_.erase(shells_.begin() + static_cast<std::ptrdiff_t>(i));
    }
}

} // namespace ui
