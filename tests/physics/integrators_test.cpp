// Every integrator against something exact: the textbooks' claims, measured convergence
// orders, and the energy behaviour theory predicts on an undamped spring.
#include "physics/ballistics.h"
#include "physics/oscillator.h"
#include "physics/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace phys;

namespace {

// A mass on a zero-rest-length spring to the origin, no gravity: x'' = -(k/m) x.
struct Oscillator {
    World world;
    ParticleId id;
    Oscillator(Integrator method, double dt, double k = 1.0, double m = 1.0, double x0 = 1.0,
               double c = 0.0)
        : world([&] {
              WorldDef d;
              d.model = ModelPolicy::Integrate; // every particle through the integrator
              d.tickSeconds = dt;
              d.integrator = method;
              d.forces.gravity = {0, 0};
              return d;
          }()) {
        ParticleDef pd;
        pd.position = {x0, 0};
        pd.mass = m;
        id = world.particles.add(pd);
        Spring s;
        s.a = id;
        s.restLength = 0.0;
        s.stiffness = k;
        s.damping = c;
        world.springs.push_back(s);
    }
    double energy() const { return phys::energy(world.particles, world.springs, world.def().forces).total(); }
    double x() const { return world.particles.px[id]; }
    double v() const { return world.particles.vx[id]; }
};

// Error in the state at time T on the unit oscillator, |x - x*| + |v - v*|.
double oscillatorError(Integrator method, double dt, double T = 2.0) {
    Oscillator o(method, dt);
    const long n = std::lround(T / dt);
    for (long i = 0; i < n; ++i) o.world.step();
    const auto e = dampedOscillator(1.0, 0.0, 1.0, 1.0, 0.0, n * dt);
    return std::abs(o.x() - e.position) + std::abs(o.v() - e.velocity);
}

// A projectile with quadratic drag and wind: nonlinear and velocity-dependent.
Vec2 dragShot(Integrator method, double dt, double T = 2.0) {
    WorldDef d;
    d.model = ModelPolicy::Integrate; // every particle through the integrator
    d.tickSeconds = dt;
    d.integrator = method;
    d.forces.drag = DragModel::Quadratic;
    d.forces.wind = {-8.0, 0.0};
    World w(d);
    ParticleDef pd;
    pd.velocity = {40.0, 30.0};
    pd.mass = 0.2;
    pd.radius = 0.05;
    const auto id = w.particles.add(pd);
    const long n = std::lround(T / dt);
    for (long i = 0; i < n; ++i) w.step();
    return w.particles.position(id);
}

class EveryIntegrator : public ::testing::TestWithParam<Integrator> {};

std::string nameOf(const ::testing::TestParamInfo<Integrator>& p) {
    std::string n = info(p.param).name;
    std::replace(n.begin(), n.end(), '-', '_');
    return n;
}

} // namespace

// Halving dt divides the error by 2^order: about 2, 4 or 16.
TEST_P(EveryIntegrator, ConvergenceOrderOnTheSpring) {
    const Integrator m = GetParam();
    const int order = info(m).order;
    const double dt = order >= 4 ? 0.02 : 0.005;
    const double ratio = oscillatorError(m, dt) / oscillatorError(m, dt / 2);
    const double expected = std::pow(2.0, order);
    EXPECT_NEAR(std::log2(ratio), order, 0.15) << "ratio " << ratio << " expected " << expected;
}

TEST_P(EveryIntegrator, ConvergenceOrderWithQuadraticDragAndWind) {
    const Integrator m = GetParam();
    const int order = info(m).order;
    const Vec2 ref = dragShot(Integrator::RK4, 1e-4);
    const double dt = order >= 4 ? 0.02 : 0.004;
    const double e1 = length(dragShot(m, dt) - ref);
    const double e2 = length(dragShot(m, dt / 2) - ref);
    EXPECT_NEAR(std::log2(e1 / e2), order, 0.2) << e1 << " " << e2;
}

TEST_P(EveryIntegrator, ExactUnderConstantAccelerationWhenItClaimsToBe) {
    const Integrator m = GetParam();
    WorldDef d;
    d.model = ModelPolicy::Integrate; // every particle through the integrator
    d.tickSeconds = 0.05;
    d.integrator = m;
    World w(d);
    ParticleDef pd;
    pd.velocity = {12.0, 25.0};
    const auto id = w.particles.add(pd);
    for (int i = 0; i < 80; ++i) w.step();
    const auto exact = ballisticState({0, 0}, pd.velocity, d.forces.gravity, 80 * 0.05);
    const double err = length(w.particles.position(id) - exact.position);
    if (info(m).exactUnderConstantAcceleration)
        EXPECT_LT(err, 1e-10);
    else
        EXPECT_GT(err, 1e-3) << "a first-order method should show its truncation error";
}

INSTANTIATE_TEST_SUITE_P(Integrators, EveryIntegrator,
                         ::testing::Values(Integrator::ExplicitEuler, Integrator::SymplecticEuler,
                                           Integrator::Verlet, Integrator::VelocityVerlet,
                                           Integrator::Leapfrog, Integrator::Midpoint,
                                           Integrator::RK4, Integrator::ImplicitEuler),
                         nameOf);

// Rabin 4.3: "For constant acceleration, Verlet integration produces results identical
// to those of explicit Euler" (Verlet bootstrapped by one Euler step).
TEST(Verlet, EqualsExplicitEulerUnderConstantAcceleration) {
    auto run = [](Integrator m) {
        WorldDef d;
        d.model = ModelPolicy::Integrate; // every particle through the integrator
        d.tickSeconds = 0.1;
        d.integrator = m;
        World w(d);
        ParticleDef pd;
        pd.position = {10, 2};
        pd.velocity = {7.68, 29};
        const auto id = w.particles.add(pd);
        std::vector<Vec2> path;
        for (int i = 0; i < 60; ++i) {
            w.step();
            path.push_back(w.particles.position(id));
        }
        return path;
    };
    const auto euler = run(Integrator::ExplicitEuler), verlet = run(Integrator::Verlet);
    for (std::size_t i = 0; i < euler.size(); ++i) {
        EXPECT_NEAR(verlet[i].x, euler[i].x, 1e-11 * (1 + std::abs(euler[i].x))) << i;
        EXPECT_NEAR(verlet[i].y, euler[i].y, 1e-11 * (1 + std::abs(euler[i].y))) << i;
    }
}

TEST(Verlet, DiffersFromExplicitEulerUnderASpringForce) {
    Oscillator euler(Integrator::ExplicitEuler, 0.1), verlet(Integrator::Verlet, 0.1);
    // The first (bootstrap) step is the same Euler step...
    euler.world.step();
    verlet.world.step();
    EXPECT_EQ(euler.x(), verlet.x());
    // ...after which the position-dependent force makes them part.
    for (int i = 0; i < 50; ++i) {
        euler.world.step();
        verlet.world.step();
    }
    EXPECT_GT(std::abs(euler.x() - verlet.x()), 0.05);
}

// Explicit Euler's amplification matrix on x'' = -w^2 x has |lambda|^2 = 1 + (w dt)^2,
// and the energy is multiplied by exactly that every step.
TEST(SpringEnergy, ExplicitEulerGrowsByOnePlusOmegaDtSquaredPerStep) {
    for (double wdt : {0.01, 0.1, 0.5}) {
        Oscillator o(Integrator::ExplicitEuler, wdt);
        double e = o.energy();
        for (int i = 0; i < 100; ++i) {
            o.world.step();
            const double next = o.energy();
            EXPECT_NEAR(next / e, 1.0 + wdt * wdt, 1e-12) << "w dt " << wdt << " step " << i;
            e = next;
        }
    }
}

namespace {
// Largest energy ratio E/E0 seen over n steps, and whether it stayed finite.
double peakEnergyRatio(Integrator m, double wdt, int n) {
    Oscillator o(m, wdt);
    const double e0 = o.energy();
    double peak = 1.0;
    for (int i = 0; i < n; ++i) {
        o.world.step();
        const double r = o.energy() / e0;
        if (!std::isfinite(r)) return INFINITY;
        peak = std::max(peak, r);
    }
    return peak;
}
} // namespace

namespace {
// Peak energy ratio in the first and in the second half of n steps.
std::pair<double, double> peakHalves(Integrator m, double wdt, int n) {
    Oscillator o(m, wdt);
    const double e0 = o.energy();
    double first = 1.0, second = 1.0;
    for (int i = 0; i < n; ++i) {
        o.world.step();
        double& peak = i < n / 2 ? first : second;
        peak = std::max(peak, o.energy() / e0);
    }
    return {first, second};
}
} // namespace

TEST(SpringEnergy, SymplecticEulerAndVerletBoundedBelowTwoBlowUpAbove) {
    for (Integrator m : {Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Leapfrog,
                         Integrator::VelocityVerlet}) {
        for (double wdt : {0.1, 1.0, 1.9, 1.99}) {
            // Bounded: no secular growth, the second half of a long run peaks no
            // higher than the first.
            const auto [first, second] = peakHalves(m, wdt, 40000);
            EXPECT_LE(second, first * (1.0 + 1e-6)) << info(m).name << " w dt " << wdt;
            EXPECT_TRUE(std::isfinite(first));
        }
        EXPECT_GT(peakEnergyRatio(m, 2.01, 4000), 1e6) << info(m).name;
    }
    // Symplectic Euler conserves Q = v^2 + w^2 x^2 - w^2 dt x v exactly, so released
    // from rest its energy oscillates between E0 and E0 / (1 - w dt / 2).
    for (double wdt : {0.1, 1.0, 1.9}) {
        const double peak = peakEnergyRatio(Integrator::SymplecticEuler, wdt, 20000);
        EXPECT_NEAR(peak, 1.0 / (1.0 - wdt / 2.0), 1e-3 / (1.0 - wdt / 2.0)) << wdt;
    }
}

TEST(SpringEnergy, RK4BoundedBelowTwoRootTwoBlowsUpAbove) {
    // |R(i w dt)| < 1 up to w dt = 2 sqrt(2) = 2.828...
    EXPECT_LE(peakEnergyRatio(Integrator::RK4, 1.0, 20000), 1.0 + 1e-9);
    EXPECT_LE(peakEnergyRatio(Integrator::RK4, 2.8, 20000), 1.0 + 1e-9);
    EXPECT_GT(peakEnergyRatio(Integrator::RK4, 2.9, 2000), 1e6);
}

TEST(SpringEnergy, ImplicitEulerDecaysAtAnyDt) {
    for (double wdt : {0.01, 0.5, 2.0, 10.0, 1000.0}) {
        Oscillator o(Integrator::ImplicitEuler, wdt);
        double e = o.energy();
        for (int i = 0; i < 200; ++i) {
            o.world.step();
            const double next = o.energy();
            // Backward Euler on the linear oscillator: E' = E / (1 + (w dt)^2).
            EXPECT_NEAR(next / e, 1.0 / (1.0 + wdt * wdt), 1e-9) << "w dt " << wdt;
            EXPECT_LE(next, e);
            e = next;
            if (e < 1e-250) break;
        }
    }
}

// A hanging chain of stiff springs at the game's tick: far beyond every explicit
// method's limit (w dt ~ 90), yet implicit Euler settles it without exploding.
TEST(ImplicitEuler, StableForSpringsFarTooStiffForExplicitMethods) {
    auto chain = [](Integrator m) {
        WorldDef d;
        d.model = ModelPolicy::Integrate; // every particle through the integrator
        d.integrator = m; // default tick 1/120 s
        // Springs only: the beads (radius 0.1 m, 0.1 m apart) overlap from the start, so
        // contacts would push them apart and this would no longer test the springs.
        d.collision.model = ContactModel::None;
        auto w = std::make_unique<World>(d);
        const int n = 20;
        ParticleId prev = kNoParticle;
        for (int i = 0; i < n; ++i) {
            ParticleDef pd;
            pd.position = {0.1 * (i + 1), 10.0};
            pd.mass = 0.1;
            pd.radius = 0.02; // links 0.1 m apart never touch
            const auto id = w->particles.add(pd);
            Spring s;
            s.a = id;
            s.b = prev;
            s.anchor = {0.0, 10.0};
            s.restLength = 0.1;
            s.stiffness = 1e7; // w = sqrt(k/m) ~ 1e4 rad/s
            w->springs.push_back(s);
            prev = id;
        }
        return w;
    };
    auto implicit = chain(Integrator::ImplicitEuler);
    const auto& f = implicit->def().forces;
    const double e0 = energy(implicit->particles, implicit->springs, f).total();
    for (int i = 0; i < 1200; ++i) { // 10 s of swinging
        implicit->step();
        // Backward Euler only ever removes energy.
        ASSERT_LE(energy(implicit->particles, implicit->springs, f).total(), e0 + 1e-9) << i;
    }
    // Every link keeps its length: the stretch under the chain's own weight is
    // at most n m g / k ~ 2e-6 m, plus what the swing adds.
    for (const Spring& s : implicit->springs) {
        const Vec2 b = s.b == kNoParticle ? s.anchor : implicit->particles.position(s.b);
        const double len = length(implicit->particles.position(s.a) - b);
        EXPECT_NEAR(len, s.restLength, 1e-3 * s.restLength);
    }

    auto explicitChain = chain(Integrator::SymplecticEuler);
    double peak = 0.0;
    for (int i = 0; i < 200; ++i) {
        explicitChain->step();
        peak = std::max(peak, std::abs(explicitChain->particles.vy[5]));
        if (!std::isfinite(peak)) break;
    }
    EXPECT_TRUE(!std::isfinite(peak) || peak > 1e6) << "symplectic Euler should explode here";
}

TEST(Integrators, NamesAndAliasesParse) {
    EXPECT_EQ(integratorFromName("euler-cromer"), Integrator::SymplecticEuler);
    EXPECT_EQ(integratorFromName("symplectic-euler"), Integrator::SymplecticEuler);
    EXPECT_EQ(integratorFromName("rk4"), Integrator::RK4);
    EXPECT_FALSE(integratorFromName("rk5").has_value());
    for (const auto& i : integrators()) EXPECT_EQ(integratorFromName(i.name), i.id);
}

TEST(Integrators, FixedParticlesNeverMove) {
    for (const auto& i : integrators()) {
        WorldDef d;
        d.model = ModelPolicy::Integrate; // every particle through the integrator
        d.integrator = i.id;
        World w(d);
        ParticleDef pd;
        pd.position = {1, 2};
        pd.mass = 0.0;
        const auto id = w.particles.add(pd);
        for (int s = 0; s < 10; ++s) w.step();
        EXPECT_EQ(w.particles.position(id), (Vec2{1, 2})) << i.name;
    }
}

namespace phys {
// Test names print the integrator's name, not its bytes.
void PrintTo(Integrator m, std::ostream* os) { *os << info(m).name; }
} // namespace phys

// Point gravity enters the implicit solve through its Jacobian (were it explicit,
// linearised backward Euler would collapse into symplectic Euler): on an orbit,
// backward Euler's numerical damping makes the pair ever more bound.
TEST(ImplicitEuler, PointGravityIsTreatedImplicitly) {
    auto orbit = [](Integrator m) {
        WorldDef d;
        d.model = ModelPolicy::Integrate; // every particle through the integrator
        d.integrator = m;
        d.tickSeconds = 0.02;
        d.forces.gravity = {0, 0};
        d.forces.pointGravity = true;
        d.forces.gravitationalConstant = 1.0;
        d.forces.pointGravitySoftening = 0.0;
        d.collision.model = ContactModel::None;
        auto w = std::make_unique<World>(d);
        ParticleDef pd;
        pd.flags = kAttractor;
        pd.radius = 0.01;
        pd.position = {-0.5, 0};
        pd.velocity = {0, -std::sqrt(2.0) / 2};
        w->particles.add(pd);
        pd.position = {0.5, 0};
        pd.velocity = {0, std::sqrt(2.0) / 2};
        w->particles.add(pd);
        return w;
    };
    auto implicit = orbit(Integrator::ImplicitEuler), symplectic = orbit(Integrator::SymplecticEuler);
    // Kinetic energy plus the pair's potential -G m1 m2 / r.
    auto total = [](const World& w) {
        const double r = length(w.particles.position(1) - w.particles.position(0));
        return energy(w.particles, w.springs, w.def().forces).kinetic - 1.0 / r;
    };
    const double e0 = total(*implicit);
    double previous = e0;
    for (int i = 0; i < 200; ++i) {
        implicit->step();
        symplectic->step();
        const double e = total(*implicit);
        EXPECT_LT(e, previous + 1e-12) << "backward Euler never adds energy, step " << i;
        previous = e;
    }
    EXPECT_LT(previous, e0 - 1e-3);
    EXPECT_GT(length(implicit->particles.position(1) - symplectic->particles.position(1)), 1e-3);
}
