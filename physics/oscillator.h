// Analytic solution of the damped harmonic oscillator m x'' + c x' + k x = 0, the
// exact reference the spring verb, the convergence tests and the benchmarks use.
#pragma once

namespace phys {

struct OscillatorState {
    double position; ///< m
    double velocity; ///< m/s
};

/// State at time t from x(0) = x0, x'(0) = v0 (under-, critically or over-damped).
OscillatorState dampedOscillator(double x0, double v0, double k, double m, double c, double t);

} // namespace phys
