#include "physics/ballistics.h"

#include <cmath>
#include <numbers>

namespace phys {

double apexTime(Vec2 v0, double g) { return v0.y > 0.0 ? v0.y / g : 0.0; }

Vec2 apex(Vec2 p0, Vec2 v0, double g) {
    const double t = apexTime(v0, g);
    return ballisticState(p0, v0, {0.0, -g}, t).position;
}

std::optional<double> timeToHeight(Vec2 p0, Vec2 v0, double g, double y, bool ascending) {
    // y0 + vy t - g/2 t^2 = y  ->  g/2 t^2 - vy t + (y - y0) = 0
    const double a = 0.5 * g, b = -v0.y, c = y - p0.y;
    if (a == 0.0) {
        if (b == 0.0) return std::nullopt;
        const double t = -c / b;
        return t >= 0.0 ? std::optional<double>(t) : std::nullopt;
    }
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return std::nullopt;
    const double root = std::sqrt(disc);
    // Stable quadratic roots (no cancellation between b and root).
    const double q = -0.5 * (b + std::copysign(root, b));
    double t1 = q / a, t2 = q != 0.0 ? c / q : t1;
    if (t1 > t2) std::swap(t1, t2);
    // t1 <= t2: the ascending crossing comes first, the descending one second.
    const double t = ascending ? t1 : t2;
    if (t < 0.0) return std::nullopt;
    return t;
}

double range(Vec2 v0, double g) { return v0.y > 0.0 ? v0.x * 2.0 * v0.y / g : 0.0; }

std::vector<FiringSolution> solveFiring(Vec2 from, Vec2 to, double speed, double g) {
    std::vector<FiringSolution> out;
    const Vec2 d = to - from;
    const double dd = lengthSquared(d);
    if (!(speed > 0.0) || dd == 0.0) return out;
    const Vec2 gv{0.0, -g};
    auto make = [&](double t) {
        const Vec2 v = d / t - gv * (0.5 * t);
        double angle = std::atan2(v.y, v.x) * 180.0 / std::numbers::pi;
        if (angle <= -180.0) angle += 360.0;
        out.push_back({angle, t, v});
    };
    if (g == 0.0) { // straight line at constant speed
        make(std::sqrt(dd) / speed);
        return out;
    }
    // Quadratic in T = t^2: a T^2 - B T + c = 0 with a = g^2/4, B = s^2 + g.d, c = |d|^2.
    const double a = 0.25 * g * g;
    const double B = speed * speed + dot(gv, d);
    const double disc = B * B - 4.0 * a * dd;
    if (disc < 0.0 || B <= 0.0) return out;
    const double root = std::sqrt(disc);
    // Larger root directly, smaller in Vieta's form T = 2c / (B + sqrt(disc)), which
    // neither cancels nor divides by a (g^2/4 underflows to 0 below g ~ 1e-162).
    const double tLong2 = (B + root) / (2.0 * a);
    const double tShort2 = 2.0 * dd / (B + root);
    make(std::sqrt(tShort2));
    if (disc > 0.0) make(std::sqrt(tLong2));
    return out;
}

} // namespace phys
