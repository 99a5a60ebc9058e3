#include "physics/forces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace phys {

std::optional<double> gravityFromPlanet(std::string_view name) {
    for (const auto& p : kGravityPresets)
        if (name == p.name) return p.g;
    return std::nullopt;
}

Dynamics::Dynamics(const ForceDef& def, const std::vector<Spring>& springs, const ParticleSet& set,
                   const SpringTerms* terms)
    : def_(def), springs_(springs), terms_(terms), set_(set), local_(def) {}

void SpringTerms::build(const std::vector<Spring>& springs) {
    terms.clear();
    for (const Spring& s : springs) {
        if (s.broken) continue;
        terms.push_back({s.a, s.b, s.restLength, s.stiffness, s.damping});
        if (s.b == kNoParticle) {
            if (anchors.size() < terms.size()) anchors.resize(terms.size());
            anchors[terms.size() - 1] = s.anchor;
        }
    }
}

Vec2 Dynamics::gravityOn(std::size_t i) const {
    if (!active(i) || (set_.flags[i] & kNoGravity)) return {};
    return def_.gravity;
}

namespace {

// A damped Hooke spring from a to b (or to `anchor` when b is kNoParticle):
// F_a = -(k (L - L0) + c (v_a - v_b).n) n, n = (p_a - p_b)/L; F_b = -F_a. S is a Spring or
// a SpringTerms::Term (the same fields).
template <class S>
inline void addSpringForce(const S& s, Vec2 anchor, const double* px, const double* py,
                           const double* vx, const double* vy, double* fx, double* fy) {
    const bool toAnchor = s.b == kNoParticle;
    const double bx = toAnchor ? anchor.x : px[s.b], by = toAnchor ? anchor.y : py[s.b];
    const double dx = px[s.a] - bx, dy = py[s.a] - by;
    const double rvx = vx[s.a] - (toAnchor ? 0.0 : vx[s.b]);
    const double rvy = vy[s.a] - (toAnchor ? 0.0 : vy[s.b]);
    if (s.restLength == 0.0) {
        // Zero rest length: the vector form F_a = -k d - c (v_a - v_b), d = p_a - p_b,
        // defined everywhere, also where the spring passes through zero length and n is
        // not. (k L n = k d; the damping acts on the whole relative velocity, which is
        // the textbook m x'' = -k x - c x' in each coordinate.)
        const double fxa = -s.stiffness * dx - s.damping * rvx;
        const double fya = -s.stiffness * dy - s.damping * rvy;
        fx[s.a] += fxa;
        fy[s.a] += fya;
        if (!toAnchor) {
            fx[s.b] -= fxa;
            fy[s.b] -= fya;
        }
        return;
    }
    const double len = std::sqrt(dx * dx + dy * dy);
    if (len <= 0.0) return; // direction undefined; no force
    const double nx = dx / len, ny = dy / len;
    const double mag = s.stiffness * (len - s.restLength) + s.damping * (rvx * nx + rvy * ny);
    fx[s.a] -= mag * nx;
    fy[s.a] -= mag * ny;
    if (!toAnchor) {
        fx[s.b] += mag * nx;
        fy[s.b] += mag * ny;
    }
}

} // namespace

// The spring loop, two springs at a time where SSE2 is there (sqrt and division dominate,
// and packed they cost what one does), their forces summed into the particles in the
// springs' order: the same operations and sums, so the same bits, as addSpringForce one
// spring at a time.
void Dynamics::springForces(const double* px, const double* py, const double* vx, const double* vy,
                            double* fx, double* fy) const {
    const std::vector<SpringTerms::Term>& t = terms_->terms;
    const std::size_t m = t.size();
    auto one = [&](std::size_t k) {
        addSpringForce(t[k], t[k].b == kNoParticle ? terms_->anchors[k] : Vec2{}, px, py, vx, vy,
                       fx, fy);
    };
    std::size_t k = 0;
#if defined(__SSE2__)
    alignas(16) double Fx[2], Fy[2];
    for (; k + 1 < m; k += 2) {
        const SpringTerms::Term &s0 = t[k], &s1 = t[k + 1];
        if (s0.b == kNoParticle || s1.b == kNoParticle || s0.restLength == 0.0 ||
            s1.restLength == 0.0) {
            one(k);
            one(k + 1);
            continue;
        }
        const __m128d dx =
            _mm_sub_pd(_mm_set_pd(px[s1.a], px[s0.a]), _mm_set_pd(px[s1.b], px[s0.b]));
        const __m128d dy =
            _mm_sub_pd(_mm_set_pd(py[s1.a], py[s0.a]), _mm_set_pd(py[s1.b], py[s0.b]));
        const __m128d len = _mm_sqrt_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)));
        // A zero length divides by 1 instead (no 0/0 to trap); that spring adds nothing.
        const __m128d positive = _mm_cmpgt_pd(len, _mm_setzero_pd());
        const __m128d safe =
            _mm_or_pd(_mm_and_pd(positive, len), _mm_andnot_pd(positive, _mm_set1_pd(1.0)));
        const __m128d nx = _mm_div_pd(dx, safe), ny = _mm_div_pd(dy, safe);
        const __m128d rvx =
            _mm_sub_pd(_mm_set_pd(vx[s1.a], vx[s0.a]), _mm_set_pd(vx[s1.b], vx[s0.b]));
        const __m128d rvy =
            _mm_sub_pd(_mm_set_pd(vy[s1.a], vy[s0.a]), _mm_set_pd(vy[s1.b], vy[s0.b]));
        const __m128d stretch =
            _mm_mul_pd(_mm_set_pd(s1.stiffness, s0.stiffness),
                       _mm_sub_pd(len, _mm_set_pd(s1.restLength, s0.restLength)));
        const __m128d damp = _mm_mul_pd(_mm_set_pd(s1.damping, s0.damping),
                                        _mm_add_pd(_mm_mul_pd(rvx, nx), _mm_mul_pd(rvy, ny)));
        const __m128d mag = _mm_add_pd(stretch, damp);
        _mm_store_pd(Fx, _mm_mul_pd(mag, nx));
        _mm_store_pd(Fy, _mm_mul_pd(mag, ny));
        const int on = _mm_movemask_pd(positive);
        if (on & 1) {
            fx[s0.a] -= Fx[0], fy[s0.a] -= Fy[0];
            fx[s0.b] += Fx[0], fy[s0.b] += Fy[0];
        }
        if (on & 2) {
            fx[s1.a] -= Fx[1], fy[s1.a] -= Fy[1];
            fx[s1.b] += Fx[1], fy[s1.b] += Fy[1];
        }
    }
#endif
    for (; k < m; ++k)
        one(k);
}

void Dynamics::nonGravityForces(const double* px, const double* py, const double* vx,
                                const double* vy, double* fx, double* fy) const {
    const std::size_t n = set_.slots();
    const auto& flags = set_.flags;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 f = localForce(i, px[i], py[i], vx[i], vy[i]);
        fx[i] = f.x;
        fy[i] = f.y;
    }

    // Damped Hooke springs.
    if (terms_) {
        springForces(px, py, vx, vy, fx, fy);
    } else {
        for (const Spring& s : springs_) {
            if (s.broken) continue;
            addSpringForce(s, s.anchor, px, py, vx, vy, fx, fy);
        }
    }

    // Inverse-square gravity between attractors: F = G m1 m2 / (r^2 + eps^2).
    if (def_.pointGravity) {
        const double eps2 = def_.pointGravitySoftening * def_.pointGravitySoftening;
        for (std::size_t i = 0; i < n; ++i) {
            if (!(flags[i] & kAttractor) || !(flags[i] & kAlive)) continue;
            const double mi = set_.mass(static_cast<ParticleId>(i));
            for (std::size_t j = i + 1; j < n; ++j) {
                if (!(flags[j] & kAttractor) || !(flags[j] & kAlive)) continue;
                const double mj = set_.mass(static_cast<ParticleId>(j));
                const double dx = px[j] - px[i], dy = py[j] - py[i];
                const double d2 = dx * dx + dy * dy + eps2;
                const double d = std::sqrt(d2);
                const double f = def_.gravitationalConstant * mi * mj / (d2 * d); // per unit d
                fx[i] += f * dx;
                fy[i] += f * dy;
                fx[j] -= f * dx;
                fy[j] -= f * dy;
            }
        }
    }

}

void Dynamics::accelerations(const double* px, const double* py, const double* vx,
                             const double* vy, double* ax, double* ay) const {
    nonGravityForces(px, py, vx, vy, ax, ay);
    const std::size_t n = set_.slots();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 a = accelerationFrom(i, {ax[i], ay[i]});
        ax[i] = a.x;
        ay[i] = a.y;
    }
}

void Dynamics::forceJacobianProduct(const double* px, const double* py, const double* vx,
                                    const double* vy, const double* wx, const double* wy,
                                    const double* ux, const double* uy, double* dfx,
                                    double* dfy) const {
    const std::size_t n = set_.slots();
    std::fill(dfx, dfx + n, 0.0);
    std::fill(dfy, dfy + n, 0.0);
    const JacobianTerms d{px, py, vx, vy, wx, wy, ux, uy, dfx, dfy};
    dragJacobian(d);
    springJacobian(d);
    if (def_.pointGravity) pointGravityJacobian(d);
    if (def_.water) waterJacobian(d);
}

void Dynamics::dragJacobian(const JacobianTerms& d) const {
    const std::size_t n = set_.slots();
    const auto& flags = set_.flags;
    if (def_.drag == DragModel::Linear) {
        for (std::size_t i = 0; i < n; ++i) {
            if (flags[i] & kNoDrag) continue;
            d.dfx[i] -= def_.linearDrag * d.ux[i];
            d.dfy[i] -= def_.linearDrag * d.uy[i];
        }
    } else if (def_.drag == DragModel::Quadratic) {
        // d/du (-k|u|u) = -k (|u| I + u u^T / |u|)
        const double halfRhoPi = 0.5 * def_.airDensity * std::numbers::pi;
        for (std::size_t i = 0; i < n; ++i) {
            if (flags[i] & kNoDrag) continue;
            const double rx = d.vx[i] - def_.wind.x, ry = d.vy[i] - def_.wind.y;
            const double s = std::sqrt(rx * rx + ry * ry);
            if (s <= 0.0) continue;
            const double r = set_.radius[i];
            const double k = halfRhoPi * set_.dragCd[i] * r * r;
            const double proj = (rx * d.ux[i] + ry * d.uy[i]) / s;
            d.dfx[i] -= k * (s * d.ux[i] + rx * proj);
            d.dfy[i] -= k * (s * d.uy[i] + ry * proj);
        }
    }
}

void Dynamics::springJacobian(const JacobianTerms& d) const {
    const double *px = d.px, *py = d.py, *wx = d.wx, *wy = d.wy, *ux = d.ux, *uy = d.uy;
    double *dfx = d.dfx, *dfy = d.dfy;
    for (const Spring& sp : springs_) {
        if (sp.broken) continue;
        const bool toAnchor = sp.b == kNoParticle;
        const double bx = toAnchor ? sp.anchor.x : px[sp.b], by = toAnchor ? sp.anchor.y : py[sp.b];
        const double dx = px[sp.a] - bx, dy = py[sp.a] - by;
        // Relative direction vectors (a minus b).
        const double rwx = wx[sp.a] - (toAnchor ? 0.0 : wx[sp.b]);
        const double rwy = wy[sp.a] - (toAnchor ? 0.0 : wy[sp.b]);
        const double rux = ux[sp.a] - (toAnchor ? 0.0 : ux[sp.b]);
        const double ruy = uy[sp.a] - (toAnchor ? 0.0 : uy[sp.b]);
        double jx, jy;
        if (sp.restLength == 0.0) {
            // Vector form: dF_a/dx_a = -k I, dF_a/dv_a = -c I, at every length.
            jx = sp.stiffness * rwx + sp.damping * rux;
            jy = sp.stiffness * rwy + sp.damping * ruy;
        } else {
            const double len = std::sqrt(dx * dx + dy * dy);
            if (len <= 0.0) continue;
            const double nx = dx / len, ny = dy / len;
            // dF_a/dx_a = -k [n n^T + max(0, 1 - L0/L) (I - n n^T)]; dF_a/dv_a = -c n n^T.
            const double transverse = std::max(0.0, 1.0 - sp.restLength / len);
            const double wn = rwx * nx + rwy * ny;
            const double un = rux * nx + ruy * ny;
            jx = sp.stiffness * (wn * nx + transverse * (rwx - wn * nx)) + sp.damping * un * nx;
            jy = sp.stiffness * (wn * ny + transverse * (rwy - wn * ny)) + sp.damping * un * ny;
        }
        dfx[sp.a] -= jx;
        dfy[sp.a] -= jy;
        if (!toAnchor) {
            dfx[sp.b] += jx;
            dfy[sp.b] += jy;
        }
    }
}

// Point gravity: F_i = G m_i m_j d / |d|^3 with d = p_j - p_i, so
// dF_i/dp_j = G m_i m_j (I / r^3 - 3 d d^T / r^5) = K and dF_i/dp_i = -K.
// (K is not negative definite: gravity stretches along d. The solver's CG guards
// against a direction of non-positive curvature, which only very large dt reach.)
void Dynamics::pointGravityJacobian(const JacobianTerms& d) const {
    const std::size_t n = set_.slots();
    const auto& flags = set_.flags;
    const double eps2 = def_.pointGravitySoftening * def_.pointGravitySoftening;
    for (std::size_t i = 0; i < n; ++i) {
        if (!(flags[i] & kAttractor) || !(flags[i] & kAlive)) continue;
        const double mi = set_.mass(static_cast<ParticleId>(i));
        for (std::size_t j = i + 1; j < n; ++j) {
            if (!(flags[j] & kAttractor) || !(flags[j] & kAlive)) continue;
            const double mj = set_.mass(static_cast<ParticleId>(j));
            const double dx = d.px[j] - d.px[i], dy = d.py[j] - d.py[i];
            const double r2 = dx * dx + dy * dy + eps2, r = std::sqrt(r2);
            const double g = def_.gravitationalConstant * mi * mj / (r2 * r);
            const double rwx = d.wx[j] - d.wx[i], rwy = d.wy[j] - d.wy[i]; // w_j - w_i
            const double dw = (dx * rwx + dy * rwy) / r2;
            const double kx = g * (rwx - 3.0 * dx * dw), ky = g * (rwy - 3.0 * dy * dw);
            d.dfx[i] += kx;
            d.dfy[i] += ky;
            d.dfx[j] -= kx;
            d.dfy[j] -= ky;
        }
    }
}

// Buoyancy: lift rho_w g V(h) with h = level - (y - r), so dLift/dy = -rho_w g pi h (2r - h);
// water drag as quadratic drag on the submerged fraction (its dependence on y is left out).
void Dynamics::waterJacobian(const JacobianTerms& d) const {
    const std::size_t n = set_.slots();
    const auto& flags = set_.flags;
    const double g = length(def_.gravity);
    const Vec2 up = g > 0.0 ? def_.gravity * (-1.0 / g) : Vec2{0.0, 1.0};
    const double halfRhoPi = 0.5 * def_.waterDensity * std::numbers::pi;
    for (std::size_t i = 0; i < n; ++i) {
        if (!(flags[i] & kAlive)) continue;
        const double r = set_.radius[i];
        const double h = submergedDepth(d.py[i], r, def_.waterLevel);
        if (h <= 0.0) continue;
        if (h < 2.0 * r) { // partly submerged: the lift changes with depth
            const double dLift = -def_.waterDensity * g * std::numbers::pi * h * (2.0 * r - h);
            d.dfx[i] += dLift * d.wy[i] * up.x;
            d.dfy[i] += dLift * d.wy[i] * up.y;
        }
        const double vx = d.vx[i], vy = d.vy[i];
        const double s = std::sqrt(vx * vx + vy * vy);
        if (s <= 0.0) continue;
        const double k = halfRhoPi * set_.dragCd[i] * r * r * (h / (2.0 * r));
        const double proj = (vx * d.ux[i] + vy * d.uy[i]) / s;
        d.dfx[i] -= k * (s * d.ux[i] + vx * proj);
        d.dfy[i] -= k * (s * d.uy[i] + vy * proj);
    }
}

int applyBlast(ParticleSet& set, const Blast& blast) {
    if (!(blast.radius > 0.0)) return 0;
    int pushed = 0;
    for (std::size_t i = 0; i < set.slots(); ++i) {
        if (!(set.flags[i] & kAlive) || set.invMass[i] <= 0.0) continue;
        const Vec2 d = set.position(static_cast<ParticleId>(i)) - blast.center;
        const double dist = length(d);
        if (dist >= blast.radius) continue;
        // At the very centre the direction is undefined: push straight up.
        const Vec2 dir = dist > 0.0 ? d / dist : Vec2{0.0, 1.0};
        const double j = blast.impulse * (1.0 - dist / blast.radius);
        const auto id = static_cast<ParticleId>(i);
        set.flags[i] &= ~kSleeping;
        set.setVelocity(id, set.velocity(id) + dir * (j * set.invMass[i]));
        ++pushed;
    }
    return pushed;
}

int updateSprings(std::vector<Spring>& springs, const ParticleSet& set, double dt) {
    int broke = 0;
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (Spring& s : springs) {
        if (s.broken || !(s.restLength > 0.0)) continue;
        // Neither breaks nor flows, whatever its strain: nothing to measure.
        if (!(s.breakStrain < inf) && !(s.yieldStrain < inf && s.plasticRate > 0.0)) continue;
        const Vec2 b = s.b == kNoParticle ? s.anchor : set.position(s.b);
        const double len = length(set.position(s.a) - b);
        const double strain = (len - s.restLength) / s.restLength;
        if (std::abs(strain) > s.breakStrain) {
            s.broken = true;
            ++broke;
            continue;
        }
        if (std::abs(strain) > s.yieldStrain && s.plasticRate > 0.0) {
            // Move the rest length toward the length at which the strain would be
            // exactly the yield strain, at plasticRate (first-order relaxation).
            const double target = len / (1.0 + std::copysign(s.yieldStrain, strain));
            const double f = std::min(1.0, s.plasticRate * dt);
            s.restLength += (target - s.restLength) * f;
        }
    }
    return broke;
}

} // namespace phys
