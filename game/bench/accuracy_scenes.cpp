#include "game/bench/accuracy_scenes.h"

#include "physics/oscillator.h"

#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <vector>

namespace game::bench {

using namespace phys;

namespace {

// Spring: k = 100 N/m, m = 1 kg (w = 10 rad/s), released from 0.5 m, 2 s.
constexpr double kSpringK = 100.0, kSpringM = 1.0, kSpringX0 = 0.5;
// Orbit: G = 1, two unit masses, 1 m apart: the relative vector obeys
// r'' = -G (m1 + m2) r / |r|^3, circular at |v_rel| = sqrt(G (m1 + m2) / r).
constexpr double kOrbitGM = 2.0, kOrbitR = 1.0;
const double kOrbitPeriod = 2.0 * std::numbers::pi * std::sqrt(kOrbitR * kOrbitR * kOrbitR / kOrbitGM);

const AccuracySceneInfo kScenes[] = {
    {AccuracyScene::ProjectileDrag, "projectile-drag", "RK4 at dt = 1e-5 s", 3.0},
    {AccuracyScene::Spring, "spring", "analytic x0 cos(w t)", 2.0},
    // Three quarters of a period: a generic time, where no symmetry cancels errors.
    {AccuracyScene::Orbit, "orbit", "analytic circular orbit", 0.75 * kOrbitPeriod},
    {AccuracyScene::PendulumRods, "pendulum", "RK4 at dt = 1e-5 s", 2.0},
    {AccuracyScene::Cloth, "cloth", "RK4 at dt = 2.5e-5 s", 1.0},
};

void addProjectile(World& w) {
    ParticleDef pd;
    pd.velocity = {45.0, 35.0};
    pd.mass = 0.0459;       // golf ball
    pd.radius = 0.02135;
    pd.dragCoefficient = 0.25;
    w.particles.add(pd);
}

void addSpring(World& w) {
    ParticleDef pd;
    pd.position = {kSpringX0, 0.0};
    pd.mass = kSpringM;
    const auto id = w.particles.add(pd);
    Spring s;
    s.a = id;
    s.restLength = 0.0;
    s.stiffness = kSpringK;
    w.springs.push_back(s);
}

void addOrbit(World& w) {
    // Zero total momentum: each body moves at half the relative speed.
    const double vRel = std::sqrt(kOrbitGM / kOrbitR);
    ParticleDef pd;
    pd.flags = kAttractor;
    pd.position = {-0.5 * kOrbitR, 0.0};
    pd.velocity = {0.0, -0.5 * vRel};
    w.particles.add(pd);
    pd.position = {0.5 * kOrbitR, 0.0};
    pd.velocity = {0.0, 0.5 * vRel};
    w.particles.add(pd);
}

void addPendulum(World& w) {
    // Five 0.5 m rods from an anchor, released horizontal.
    ParticleId prev = kNoParticle;
    for (int i = 0; i < 5; ++i) {
        ParticleDef pd;
        pd.position = {0.5 * (i + 1), 0.0};
        pd.mass = 1.0;
        const auto id = w.particles.add(pd);
        DistanceConstraint c;
        c.kind = ConstraintKind::Rod;
        c.a = id;
        c.b = prev;
        c.anchor = {0.0, 0.0};
        c.length = 0.5;
        w.constraints.push_back(c);
        prev = id;
    }
}

void addCloth(World& w) {
    // 12 x 12 particles 0.1 m apart, structural and shear springs, top corners pinned.
    const int n = 12;
    const double h = 0.1, k = 400.0, c = 0.05, m = 0.01;
    std::vector<ParticleId> id(n * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            ParticleDef pd;
            pd.position = {i * h, -j * h};
            pd.mass = (j == 0 && (i == 0 || i == n - 1)) ? 0.0 : m;
            pd.radius = 0.02;
            id[j * n + i] = w.particles.add(pd);
        }
    auto link = [&](int a, int b, double len) {
        Spring s;
        s.a = id[a];
        s.b = id[b];
        s.restLength = len;
        s.stiffness = k;
        s.damping = c;
        w.springs.push_back(s);
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if (i + 1 < n) link(j * n + i, j * n + i + 1, h);
            if (j + 1 < n) link(j * n + i, (j + 1) * n + i, h);
            if (i + 1 < n && j + 1 < n) link(j * n + i, (j + 1) * n + i + 1, h * std::sqrt(2.0));
            if (i > 0 && j + 1 < n) link(j * n + i, (j + 1) * n + i - 1, h * std::sqrt(2.0));
        }
}

std::vector<Vec2> positions(const World& w) {
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < w.particles.slots(); ++i)
        if (w.particles.flags[i] & kAlive) out.push_back(w.particles.position(static_cast<ParticleId>(i)));
    return out;
}

double referenceDt(AccuracyScene s) {
    return s == AccuracyScene::Cloth ? 2.5e-5 : 1e-5;
}

// Reference end states, computed once per scene (RK4 at a tiny dt).
const std::vector<Vec2>& reference(AccuracyScene s) {
    static std::mutex lock;
    static std::map<AccuracyScene, std::vector<Vec2>> cache;
    std::lock_guard<std::mutex> guard(lock);
    auto it = cache.find(s);
    if (it != cache.end()) return it->second;
    const double dt = referenceDt(s);
    auto w = makeAccuracyWorld(s, Integrator::RK4, dt);
    const long n = stepsFor(s, dt);
    for (long i = 0; i < n; ++i) w->step();
    return cache[s] = positions(*w);
}

} // namespace

std::span<const AccuracySceneInfo> accuracyScenes() { return kScenes; }

const AccuracySceneInfo& info(AccuracyScene s) {
    for (const auto& i : kScenes)
        if (i.id == s) return i;
    return kScenes[0];
}

std::optional<AccuracyScene> accuracySceneFromName(std::string_view name) {
    for (const auto& i : kScenes)
        if (name == i.name) return i.id;
    return std::nullopt;
}

long stepsFor(AccuracyScene s, double dt) { return std::lround(info(s).seconds / dt); }

double snapDt(AccuracyScene s, double dt) {
    const double T = info(s).seconds;
    return T / std::max(1.0, std::round(T / dt));
}

std::unique_ptr<World> makeAccuracyWorld(AccuracyScene s, Integrator m, double dt) {
    WorldDef d;
    d.tickSeconds = dt;
    d.integrator = m;
    d.collision.model = ContactModel::None; // nothing here collides
    switch (s) {
    case AccuracyScene::ProjectileDrag:
        d.forces.drag = DragModel::Quadratic;
        d.forces.wind = {-6.0, 0.0};
        break;
    case AccuracyScene::Spring:
    case AccuracyScene::Orbit:
        d.forces.gravity = {0.0, 0.0};
        break;
    case AccuracyScene::PendulumRods:
    case AccuracyScene::Cloth:
        break;
    }
    if (s == AccuracyScene::Orbit) {
        d.forces.pointGravity = true;
        d.forces.gravitationalConstant = 1.0;
        d.forces.pointGravitySoftening = 0.0;
    }
    auto w = std::make_unique<World>(d);
    switch (s) {
    case AccuracyScene::ProjectileDrag: addProjectile(*w); break;
    case AccuracyScene::Spring: addSpring(*w); break;
    case AccuracyScene::Orbit: addOrbit(*w); break;
    case AccuracyScene::PendulumRods: addPendulum(*w); break;
    case AccuracyScene::Cloth: addCloth(*w); break;
    }
    return w;
}

double accuracyError(AccuracyScene s, const World& w) {
    const auto now = positions(w);
    for (const Vec2& p : now)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return INFINITY;
    switch (s) {
    case AccuracyScene::Spring: {
        const double t = w.time();
        const auto e = dampedOscillator(kSpringX0, 0.0, kSpringK, kSpringM, 0.0, t);
        return length(now[0] - Vec2{e.position, 0.0});
    }
    case AccuracyScene::Orbit: {
        // The relative vector turns at w = 2 pi / T on a circle of radius r.
        const double angle = 2.0 * std::numbers::pi * w.time() / kOrbitPeriod;
        const Vec2 rel = now[1] - now[0];
        return length(rel - Vec2{kOrbitR * std::cos(angle), kOrbitR * std::sin(angle)});
    }
    default: {
        const auto& ref = reference(s);
        double sum = 0.0;
        for (std::size_t i = 0; i < now.size() && i < ref.size(); ++i)
            sum += lengthSquared(now[i] - ref[i]);
        return std::sqrt(sum / static_cast<double>(now.size()));
    }
    }
}

} // namespace game::bench
