#include "physics/oscillator.h"

#include <cmath>

namespace phys {

OscillatorState dampedOscillator(double x0, double v0, double k, double m, double c, double t) {
    const double w0 = std::sqrt(k / m);  // natural angular frequency
    const double gamma = c / (2.0 * m);  // decay rate
    if (gamma < w0) {
        // Under-damped: x = e^{-gamma t} (A cos wd t + B sin wd t), wd = sqrt(w0^2 - gamma^2).
        const double wd = std::sqrt(w0 * w0 - gamma * gamma);
        const double A = x0, B = (v0 + gamma * x0) / wd;
        const double e = std::exp(-gamma * t), cs = std::cos(wd * t), sn = std::sin(wd * t);
        const double x = e * (A * cs + B * sn);
        const double v = e * ((B * wd - gamma * A) * cs - (A * wd + gamma * B) * sn);
        return {x, v};
    }
    if (gamma == w0) {
        // Critically damped: x = (A + B t) e^{-gamma t}.
        const double A = x0, B = v0 + gamma * x0;
        const double e = std::exp(-gamma * t);
        return {(A + B * t) * e, (B - gamma * (A + B * t)) * e};
    }
    // Over-damped: x = A e^{r1 t} + B e^{r2 t}, r = -gamma +- sqrt(gamma^2 - w0^2).
    const double s = std::sqrt(gamma * gamma - w0 * w0);
    const double r1 = -gamma + s, r2 = -gamma - s;
    const double B = (v0 - r1 * x0) / (r2 - r1), A = x0 - B;
    const double e1 = std::exp(r1 * t), e2 = std::exp(r2 * t);
    return {A * e1 + B * e2, A * r1 * e1 + B * r2 * e2};
}

} // namespace phys
