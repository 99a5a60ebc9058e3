// The soak's scenes (bench_soak.cpp). Two kinds, for two questions:
//
//   BusyScene        dissipative: a gas of particles that settles into a pile, springs,
//                    Box2D crates (e = 0.5) coupled to the particles, resting contact
//                    and sleep. Its energy falls by design, so it answers only "does it
//                    stay finite (guard removals 0) and does memory stay flat".
//   OscillatorBank   conservative, one per integrator: particles on undamped springs
//                    (no gravity, no collisions, no sleep), each a 1D harmonic oscillator
//                    whose energy and the integrator's own invariant are known exactly.
//   ElasticGas       conservative: particles in a closed box, e = 1 against the walls
//                    and each other, no friction, no sleep, no gravity.
//   ElasticBodies    conservative: Box2D circles and boxes in a closed box, e = 1, no
//                    friction, no sleep, no gravity.
//
// Every scene steps at the game tick (1/120 s) and reports its energy, so the driver
// can print the drift against the start; the conservative ones must not drift.
#pragma once

#include "physics/coupling.h"
#include "physics/integrators.h"
#include "physics/rigid/rigid_world.h"
#include "physics/world.h"

#include <cstdint>
#include <string>
#include <vector>

namespace soak {

constexpr double kTick = 1.0 / 120.0; ///< s: the game tick every scene steps at

/// Relative energy drift against the start, sampled every tick.
struct DriftMeter {
    double e0 = 0.0;
    double last = 0.0;
    double maxDeviation = 0.0; ///< max |E - E0| / |E0| over every sample
    void start(double e);
    void sample(double e);
    double drift() const; ///< (E - E0) / |E0| at the last sample
};

/// Non-finite values and guard removals seen so far (both must stay 0).
struct Faults {
    long nonFinite = 0;    ///< particles or bodies with a NaN or infinite state
    long removed = 0;      ///< particles the guard removed (non-finite or runaway)
    std::string cause;     ///< the guard's explanation of its latest removal ("" when none)
    bool newCause = false; ///< cause changed since the driver last printed it
};

struct BusyScene {
    phys::World world;
    phys::RigidWorld rigid;
    phys::ParticleBodyCoupling coupling;
    std::vector<phys::BodyId> bodies;
    double energy0 = 0.0; ///< J, at the start
    BusyScene(int particles, int crates, std::uint64_t seed);
    /// m: the box is 40 m high and this wide, so that the settled particles (0.2 m
    /// across) lie about two deep. A deeper pile costs more per tick than the rest of
    /// the soak together and never sleeps (the crates and springs keep it awake).
    static double width(int particles);
    void step(Faults& faults);
    double energy() const; ///< particles, springs and crates, J (potential from y = 0)
};

/// N undamped springs from fixed anchors to particles of 1 kg, stiffness spread over
/// [kMin, kMax] (w = sqrt(k)), each moving along x only, so it is exactly the linear
/// oscillator x'' = -w^2 x with x = L - L0. For symplectic Euler and velocity Verlet the
/// modified energy the method conserves exactly is known (see invariant()); the bank
/// checks it every tick.
struct OscillatorBank {
    static constexpr double kMin = 4.0, kMax = 400.0; ///< N/m: w dt = 0.017 .. 0.17 at 120 Hz
    static constexpr double kRestLength = 1.0;        ///< m; amplitudes stay under 0.8 m

    phys::Integrator method;
    phys::World world;
    DriftMeter total;            ///< energy of the whole bank
    double worstSingle = 0.0;    ///< max over oscillators and ticks of |E_i / E_i0 - 1|
    double invariantDrift = 0.0; ///< max |H_i / H_i0 - 1| of the conserved H (see energyOf)
    double bandUsed = 0.0;       ///< how far E_i/H_i reached toward its band's edge (<= 1)
    double bandExcess = 0.0;     ///< how far E_i/H_i ever went outside its band (0)

    OscillatorBank(phys::Integrator method, int oscillators, std::uint64_t seed);
    void step(Faults& faults);
    /// True when the method has a known exactly conserved quantity (symplectic Euler,
    /// velocity Verlet) that this bank checks.
    bool hasInvariant() const;

  private:
    struct Energy {
        double e = 0.0;            ///< J
        double h = 0.0;            ///< the method's conserved quantity, J
        double lo = 1.0, hi = 1.0; ///< the band E/H stays in
    };
    std::vector<double> stiffness_, e0_, h0_;
    Energy energyOf(std::size_t i) const;
    void sample();
};

struct ElasticGas {
    phys::World world;
    DriftMeter drift;
    ElasticGas(int particles, std::uint64_t seed);
    void step(Faults& faults);
    double energy() const; ///< kinetic, J
};

struct ElasticBodies {
    phys::RigidWorld rigid;
    std::vector<phys::BodyId> bodies;
    DriftMeter drift;
    ElasticBodies(int bodies, std::uint64_t seed);
    void step(Faults& faults);
    double energy() const; ///< translational + rotational kinetic, J
};

/// Kinetic + gravitational energy of Box2D bodies (potential zero at y = 0), J, and the
/// number of bodies whose state is not finite.
double rigidEnergy(const phys::RigidWorld& rigid, const std::vector<phys::BodyId>& bodies,
                   phys::Vec2 gravity, long* nonFinite = nullptr);

} // namespace soak
