// bench_soak: one simulated hour (by default) of a busy scene — thousands of particles
// bouncing in a closed box with perfectly elastic walls, springs holding a soft lattice,
// and Box2D crates coupled to the particles — printing every simulated minute the total
// energy against the start, the particles the guard had to remove (NaN or runaway: must
// stay 0) and the process's resident memory (must stay flat once warm).
//
//   bench_soak [--seconds S] [--particles N] [--bodies M]
#include "physics/coupling.h"
#include "physics/guard.h"
#include "physics/rigid/rigid_world.h"
#include "physics/world.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>

namespace {

double residentMiB() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return static_cast<double>(resident) * 4096.0 / (1024.0 * 1024.0);
}

double energyOf(const phys::World& w, const phys::RigidWorld& rigid) {
    double e = phys::energy(w.particles, w.springs, w.def().forces).total();
    for (const phys::BodyId id : rigid.bodies()) {
        const phys::RigidBodyState s = rigid.state(id);
        if (s.mass <= 0.0) continue;
        e += 0.5 * s.mass * phys::lengthSquared(s.linearVelocity) +
             0.5 * s.inertia * s.angularVelocity * s.angularVelocity + s.mass * 9.81 * s.position.y;
    }
    return e;
}

} // namespace

int main(int argc, char** argv) {
    double seconds = 3600.0;
    int particles = 2000, bodies = 100;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--seconds")) seconds = std::atof(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--particles")) particles = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--bodies")) bodies = std::atoi(argv[i + 1]);
    }
    if (!(seconds > 0.0) || particles < 1 || bodies < 0) {
        std::fprintf(stderr, "usage: bench_soak [--seconds S > 0] [--particles N >= 1] [--bodies M >= 0]\n");
        return 2;
    }
    using namespace phys;
    World w;
    RigidWorld rigid;
    ParticleBodyCoupling coupling;
    const std::vector<Vec2> box{{0, 40}, {0, 0}, {60, 0}, {60, 40}, {0, 40}};
    w.shapes.addPolyline(box, material::kFloor);
    rigid.createTerrain(box, RigidMaterial{0.0, 0.3, 0.0});
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> x(1.0, 59.0), y(5.0, 38.0), v(-8.0, 8.0);
    for (int i = 0; i < particles; ++i) {
        ParticleDef pd;
        pd.position = {x(rng), y(rng)};
        pd.velocity = {v(rng), v(rng)};
        pd.radius = 0.1;
        pd.material = material::kPerfectlyElastic;
        w.particles.add(pd);
    }
    // A soft lattice of springs among the first particles.
    for (int i = 0; i + 1 < std::min(particles, 200); i += 2) {
        Spring s;
        s.a = static_cast<ParticleId>(i);
        s.b = static_cast<ParticleId>(i + 1);
        s.restLength = 0.5;
        s.stiffness = 200.0;
        s.damping = 0.1;
        w.springs.push_back(s);
    }
    for (int i = 0; i < bodies; ++i) {
        BodyDef bd;
        bd.position = {x(rng), y(rng)};
        rigid.createBox(bd, {0.4, 0.4}, RigidMaterial{50.0, 0.4, 0.5});
    }
    const double tick = w.def().tickSeconds;
    const long ticks = static_cast<long>(seconds / tick);
    const long perMinute = static_cast<long>(60.0 / tick);
    const double e0 = energyOf(w, rigid);
    long removed = 0;
    const auto t0 = std::chrono::steady_clock::now();
    std::printf("soak: %d particles, %zu springs, %d bodies, %.0f s at %.0f Hz\n", particles,
                w.springs.size(), bodies, seconds, 1.0 / tick);
    std::printf("%8s %14s %10s %10s %12s\n", "minute", "energy/E0", "removed", "RSS MiB", "wall s");
    for (long t = 1; t <= ticks; ++t) {
        coupling.prepare(w, rigid);
        w.step();
        coupling.exchange(w, rigid);
        rigid.step(tick);
        removed += guardWorld(w).removed;
        if (t % perMinute == 0 || t == ticks) {
            const double wall =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::printf("%8.1f %14.6f %10ld %10.1f %12.1f\n", static_cast<double>(t) * tick / 60.0,
                        energyOf(w, rigid) / e0, removed, residentMiB(), wall);
            std::fflush(stdout);
        }
    }
    std::printf("non-finite or runaway particles removed: %ld (must be 0)\n", removed);
    return removed == 0 ? 0 : 1;
}
