// A zero-rest-length spring is the linear oscillator m x'' = -k x - c x' in each
// coordinate, also at and through zero length, where the direction n = d/|d| of the
// magnitude form is undefined. One step from the origin (the spring at zero length)
// must equal each integrator's textbook one-step map of that linear system.
#include "physics/world.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace phys;

namespace {

constexpr double kK = 50.0, kC = 3.0, kM = 2.0, kDt = 0.01;

struct State {
    double x, y, vx, vy;
};

/// a = (-k x - c v) / m, per coordinate.
State derivative(const State& s, double c) {
    return {s.vx, s.vy, (-kK * s.x - c * s.vx) / kM, (-kK * s.y - c * s.vy) / kM};
}
State plus(const State& s, const State& d, double h) {
    return {s.x + h * d.x, s.y + h * d.y, s.vx + h * d.vx, s.vy + h * d.vy};
}

State simulateOneStep(Integrator method, const State& s0, double c) {
    WorldDef def;
    def.tickSeconds = kDt;
    def.integrator = method;
    def.forces.gravity = {0.0, 0.0};
    def.forces.drag = DragModel::None;
    World world(def);
    ParticleDef pd;
    pd.position = {s0.x, s0.y};
    pd.velocity = {s0.vx, s0.vy};
    pd.mass = kM;
    const auto id = world.particles.add(pd);
    Spring sp;
    sp.a = id;
    sp.anchor = {0.0, 0.0};
    sp.restLength = 0.0;
    sp.stiffness = kK;
    sp.damping = c;
    world.springs.push_back(sp);
    world.step();
    return {world.particles.px[id], world.particles.py[id], world.particles.vx[id],
            world.particles.vy[id]};
}

void expectState(const State& got, const State& want, const char* what) {
    const double tol = 1e-13;
    EXPECT_NEAR(got.x, want.x, tol) << what;
    EXPECT_NEAR(got.y, want.y, tol) << what;
    EXPECT_NEAR(got.vx, want.vx, tol) << what;
    EXPECT_NEAR(got.vy, want.vy, tol) << what;
}

// At the anchor, moving off it in a direction that is not along any axis.
constexpr State kAtZero{0.0, 0.0, 2.0, -1.0};

} // namespace

TEST(SpringThroughZero, ExplicitEulerKeepsItsDamping) {
    // x1 = x0 + h v0, v1 = v0 + h a(x0, v0): here v1 = v0 (1 - h c / m).
    expectState(simulateOneStep(Integrator::ExplicitEuler, kAtZero, kC),
                plus(kAtZero, derivative(kAtZero, kC), kDt), "explicit Euler");
}

TEST(SpringThroughZero, SymplecticEulerMatchesItsMap) {
    // v1 = v0 + h a(x0, v0), x1 = x0 + h v1.
    const State d = derivative(kAtZero, kC);
    const double vx = kAtZero.vx + kDt * d.vx, vy = kAtZero.vy + kDt * d.vy;
    expectState(simulateOneStep(Integrator::SymplecticEuler, kAtZero, kC),
                {kAtZero.x + kDt * vx, kAtZero.y + kDt * vy, vx, vy}, "symplectic Euler");
}

TEST(SpringThroughZero, MidpointAndRK4MatchTheirMaps) {
    const State k1 = derivative(kAtZero, kC);
    const State mid = plus(kAtZero, k1, kDt / 2);
    expectState(simulateOneStep(Integrator::Midpoint, kAtZero, kC),
                plus(kAtZero, derivative(mid, kC), kDt), "midpoint");
    const State k2 = derivative(plus(kAtZero, k1, kDt / 2), kC);
    const State k3 = derivative(plus(kAtZero, k2, kDt / 2), kC);
    const State k4 = derivative(plus(kAtZero, k3, kDt), kC);
    const State rk4{
        kAtZero.x + kDt / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
        kAtZero.y + kDt / 6 * (k1.y + 2 * k2.y + 2 * k3.y + k4.y),
        kAtZero.vx + kDt / 6 * (k1.vx + 2 * k2.vx + 2 * k3.vx + k4.vx),
        kAtZero.vy + kDt / 6 * (k1.vy + 2 * k2.vy + 2 * k3.vy + k4.vy),
    };
    expectState(simulateOneStep(Integrator::RK4, kAtZero, kC), rk4, "RK4");
}

TEST(SpringThroughZero, VelocityVerletAndPositionVerletMatchTheirMaps) {
    // Undamped (Verlet's map for a velocity-dependent force is not one textbook map):
    // velocity Verlet x1 = x0 + h v0 + h^2 a0 / 2, v1 = v0 + h (a0 + a1) / 2; position
    // Verlet's first step is the explicit Euler step that primes it.
    const State a0 = derivative(kAtZero, 0.0);
    const State x1{kAtZero.x + kDt * kAtZero.vx + 0.5 * kDt * kDt * a0.vx,
                   kAtZero.y + kDt * kAtZero.vy + 0.5 * kDt * kDt * a0.vy, 0.0, 0.0};
    const State a1 = derivative(x1, 0.0);
    expectState(simulateOneStep(Integrator::VelocityVerlet, kAtZero, 0.0),
                {x1.x, x1.y, kAtZero.vx + 0.5 * kDt * (a0.vx + a1.vx),
                 kAtZero.vy + 0.5 * kDt * (a0.vy + a1.vy)},
                "velocity Verlet");
    expectState(simulateOneStep(Integrator::Verlet, kAtZero, 0.0),
                plus(kAtZero, derivative(kAtZero, 0.0), kDt), "position Verlet");
}

TEST(SpringThroughZero, ImplicitEulerSolvesTheLinearSystemExactly) {
    // Backward Euler on a linear system: v1 = v0 + h a(x1, v1), x1 = x0 + h v1, so
    // v1 (1 + h c/m + h^2 k/m) = v0 - h k x0 / m. Linearising it (Baraff & Witkin) is
    // exact here, if the Jacobian is -k I and -c I at zero length too.
    const double denom = 1.0 + kDt * kC / kM + kDt * kDt * kK / kM;
    const double vx = (kAtZero.vx - kDt * kK * kAtZero.x / kM) / denom;
    const double vy = (kAtZero.vy - kDt * kK * kAtZero.y / kM) / denom;
    const State got = simulateOneStep(Integrator::ImplicitEuler, kAtZero, kC);
    // Conjugate gradients stops at a residual tolerance, not at exact zero.
    EXPECT_NEAR(got.vx, vx, 1e-9);
    EXPECT_NEAR(got.vy, vy, 1e-9);
    EXPECT_NEAR(got.x, kAtZero.x + kDt * got.vx, 1e-15);
    EXPECT_NEAR(got.y, kAtZero.y + kDt * got.vy, 1e-15);
}
