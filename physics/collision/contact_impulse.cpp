#include "physics/collision/contact_impulse.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace phys {

ContactImpulse contactImpulse(Vec2 vrel, Vec2 n, double wa, double wb, double restitution,
                              const PairProperties& pair, double supportImpulse) {
    ContactImpulse out;
    const double w = wa + wb;
    if (!(w > 0.0)) return out;
    const double vn = dot(vrel, n);
    const double jn = vn < 0.0 ? -(1.0 + restitution) * vn / w : 0.0; // equation 4
    out.normal = jn;
    out.impulse = n * jn;
    const double N = jn + supportImpulse;
    const Vec2 vt = vrel - n * vn;
    const double speedT = length(vt);
    if (!(N > 0.0) || !(speedT > 0.0)) {
        out.stuck = speedT == 0.0;
        return out;
    }
    const double stop = speedT / w; // the tangential impulse that ends sliding
    const Vec2 t = vt / speedT;
    if (stop <= pair.staticFriction * N) {
        out.tangential = stop;
        out.stuck = true;
    } else {
        out.tangential = pair.dynamicFriction * N;
    }
    out.impulse -= t * out.tangential;
    return out;
}

double penaltyImpulse(double depth, double closingVelocity, double wa, double wb,
                      double restitution, double hertz, double h) {
    const double w = wa + wb;
    if (!(w > 0.0) || !(depth > 0.0)) return 0.0;
    const double omega = 2.0 * std::numbers::pi * hertz;
    const double lnE = std::log(std::max(restitution, 1e-12));
    const double zeta = restitution >= 1.0
                            ? 0.0
                            : -lnE / std::sqrt(std::numbers::pi * std::numbers::pi + lnE * lnE);
    // The spring pushes out; the damper opposes the normal relative velocity. A contact
    // never pulls (F >= 0).
    const double force = (omega * omega * depth - 2.0 * zeta * omega * closingVelocity) / w;
    return std::max(force, 0.0) * h;
}

} // namespace phys
