#include "physics/constraints/rods_and_cables.h"

#include <algorithm>
#include <cmath>

namespace phys {

namespace {

Vec2 otherEnd(const DistanceConstraint& c, const ParticleSet& s) {
    return c.b == kNoParticle ? c.anchor : s.position(c.b);
}

double wOf(const ParticleSet& s, ParticleId id) {
    return id == kNoParticle ? 0.0 : s.invMass[id];
}

// dp = W J^T x over the active constraints.
void applyJt(const std::vector<DistanceConstraint>& cs, const ParticleSet& s, ConstraintScratch& w,
             const std::vector<double>& x) {
    // Only the constraints' ends are ever read: clear those, not every slot (a rope in a
    // world of thousands of particles costs its own size).
    for (const auto& c : cs) {
        w.dp[c.a] = Vec2{};
        if (c.b != kNoParticle) w.dp[c.b] = Vec2{};
    }
    for (std::size_t k = 0; k < cs.size(); ++k) {
        if (!w.active[k]) continue;
        const auto& c = cs[k];
        w.dp[c.a] += w.dir[k] * (x[k] * s.invMass[c.a]);
        if (c.b != kNoParticle) w.dp[c.b] -= w.dir[k] * (x[k] * s.invMass[c.b]);
    }
}

// out = J dp.
void applyJ(const std::vector<DistanceConstraint>& cs, ConstraintScratch& w,
            std::vector<double>& out) {
    for (std::size_t k = 0; k < cs.size(); ++k) {
        const auto& c = cs[k];
        out[k] = w.active[k] ? dot(w.dir[k], w.dp[c.a] - (c.b != kNoParticle ? w.dp[c.b] : Vec2{}))
                             : 0.0;
    }
}

// The bandwidth of J W J^T in list order: the largest k - j over constraints j < k that
// share a particle.
int bandwidthOf(const std::vector<DistanceConstraint>& cs, std::size_t slots,
                ConstraintScratch& w) {
    // Only the constraints' ends are touched, and put back to -1 after: a rope in a world
    // of thousands of particles costs its own size.
    if (w.lastRow.size() < slots) w.lastRow.resize(slots, -1);
    int b = 0;
    for (std::size_t k = 0; k < cs.size(); ++k)
        for (const ParticleId id : {cs[k].a, cs[k].b}) {
            if (id == kNoParticle || id >= slots) continue;
            if (w.lastRow[id] >= 0) b = std::max(b, static_cast<int>(k) - w.lastRow[id]);
            w.lastRow[id] = static_cast<int>(k);
        }
    for (const auto& c : cs)
        for (const ParticleId id : {c.a, c.b})
            if (id != kNoParticle && id < slots) w.lastRow[id] = -1;
    return b;
}

// Entry (k, j) of J W J^T: the particles k and j share, each with w_p (n_k . n_j) times
// the signs of the two rows there (+ at a, - at b).
double couplingOf(const DistanceConstraint& ck, const DistanceConstraint& cj, Vec2 nk, Vec2 nj,
                  const ParticleSet& s) {
    // Signs: (+1)(+1) at a shared a-a or b-b, (+1)(-1) at a-b or b-a; ck.a is a particle.
    double sum = 0.0;
    const double wa = s.invMass[ck.a];
    if (cj.a == ck.a) sum += wa;
    if (cj.b == ck.a) sum += -wa;
    if (ck.b != kNoParticle) {
        const double wb = s.invMass[ck.b];
        if (cj.a == ck.b) sum += -wb;
        if (cj.b == ck.b) sum += wb;
    }
    return sum == 0.0 ? 0.0 : sum * dot(nk, nj);
}

// Tridiagonal J W J^T (bandwidth 1: ropes): the banded factorization below with its
// empty inner loops left out, the same operations in the same order.
bool solveTridiagonal(const std::vector<DistanceConstraint>& cs, const ParticleSet& s,
                      ConstraintScratch& w) {
    const std::size_t m = cs.size();
    w.band.assign(2 * m, 0.0); // row k: L(k, k), L(k, k - 1)
    double* L = w.band.data();
    for (std::size_t k = 0; k < m; ++k) {
        if (!w.active[k]) {
            L[2 * k] = 1.0;
            continue;
        }
        const double diag = (wOf(s, cs[k].a) + wOf(s, cs[k].b)) * dot(w.dir[k], w.dir[k]);
        double a = diag;
        if (k > 0) {
            const double c =
                w.active[k - 1] ? couplingOf(cs[k], cs[k - 1], w.dir[k], w.dir[k - 1], s) : 0.0;
            L[2 * k + 1] = c / L[2 * k - 2];
            a -= L[2 * k + 1] * L[2 * k + 1];
        }
        if (!(a > 1e-10 * diag)) return false;
        L[2 * k] = std::sqrt(a);
    }
    for (std::size_t k = 0; k < m; ++k) {
        double y = w.active[k] ? w.rhs[k] : 0.0;
        if (k > 0) y -= L[2 * k + 1] * w.x[k - 1];
        w.x[k] = y / L[2 * k];
    }
    for (std::size_t k = m; k-- > 0;) {
        double x = w.x[k];
        if (k + 1 < m) x -= L[2 * k + 3] * w.x[k + 1];
        w.x[k] = x / L[2 * k];
    }
    ++w.lastDirectSolves;
    applyJt(cs, s, w, w.x);
    return true;
}

// Solves (J W J^T) x = rhs by banded Cholesky (the inactive rows and columns replaced by
// the identity, so their x is 0, as CG leaves it); false, with nothing solved, when a
// pivot is not clearly positive (a singular or nearly singular set). The result is left
// in w.x and W J^T x in w.dp.
bool solveBanded(const std::vector<DistanceConstraint>& cs, const ParticleSet& s,
                 ConstraintScratch& w, int b) {
    const std::size_t m = cs.size(), width = static_cast<std::size_t>(b) + 1;
    w.band.assign(m * width, 0.0);
    auto L = [&](std::size_t k, std::size_t j) -> double& { return w.band[k * width + (k - j)]; };
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t first = k >= static_cast<std::size_t>(b) ? k - b : 0;
        if (!w.active[k]) {
            L(k, k) = 1.0;
            continue;
        }
        for (std::size_t j = first; j < k; ++j) {
            double a = w.active[j] ? couplingOf(cs[k], cs[j], w.dir[k], w.dir[j], s) : 0.0;
            for (std::size_t i = std::max(first, j >= static_cast<std::size_t>(b) ? j - b : 0);
                 i < j; ++i)
                a -= L(k, i) * L(j, i);
            L(k, j) = a / L(j, j);
        }
        const double diag = (wOf(s, cs[k].a) + wOf(s, cs[k].b)) * dot(w.dir[k], w.dir[k]);
        double a = diag;
        for (std::size_t i = first; i < k; ++i)
            a -= L(k, i) * L(k, i);
        // Cancellation down to 1e-10 of the diagonal: the rows are (nearly) dependent.
        if (!(a > 1e-10 * diag)) return false;
        L(k, k) = std::sqrt(a);
    }
    // L y = rhs, then L^T x = y.
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t first = k >= static_cast<std::size_t>(b) ? k - b : 0;
        double y = w.active[k] ? w.rhs[k] : 0.0;
        for (std::size_t i = first; i < k; ++i)
            y -= L(k, i) * w.x[i];
        w.x[k] = y / L(k, k);
    }
    for (std::size_t k = m; k-- > 0;) {
        double x = w.x[k];
        for (std::size_t i = k + 1; i < std::min(m, k + width); ++i)
            x -= L(i, k) * w.x[i];
        w.x[k] = x / L(k, k);
    }
    ++w.lastDirectSolves;
    applyJt(cs, s, w, w.x);
    return true;
}

// Solves (J W J^T) x = rhs by Jacobi-preconditioned conjugate gradients; the result
// is left in w.x and W J^T x in w.dp.
void solveIterative(const std::vector<DistanceConstraint>& cs, const ParticleSet& s,
                    ConstraintScratch& w) {
    const std::size_t m = cs.size();
    auto diag = [&](std::size_t k) { return wOf(s, cs[k].a) + wOf(s, cs[k].b); };
    double rz = 0.0, rr0 = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
        w.x[k] = 0.0;
        w.r[k] = w.active[k] ? w.rhs[k] : 0.0;
        const double d = diag(k);
        w.z[k] = w.active[k] && d > 0.0 ? w.r[k] / d : 0.0;
        w.p[k] = w.z[k];
        rz += w.r[k] * w.z[k];
        rr0 += w.r[k] * w.r[k];
    }
    const int maxIt = static_cast<int>(std::min<std::size_t>(2 * m + 10, 1000));
    for (int it = 0; it < maxIt && rz > 0.0; ++it) {
        applyJt(cs, s, w, w.p);
        applyJ(cs, w, w.q);
        double pq = 0.0;
        for (std::size_t k = 0; k < m; ++k)
            pq += w.p[k] * w.q[k];
        if (!(pq > 0.0)) break; // a dependent direction (a loop, or fixed ends): stop here
        const double alpha = rz / pq;
        double rzNew = 0.0, rr = 0.0;
        for (std::size_t k = 0; k < m; ++k) {
            w.x[k] += alpha * w.p[k];
            w.r[k] -= alpha * w.q[k];
            const double d = diag(k);
            w.z[k] = w.active[k] && d > 0.0 ? w.r[k] / d : 0.0;
            rzNew += w.r[k] * w.z[k];
            rr += w.r[k] * w.r[k];
        }
        ++w.lastIterations;
        if (rr <= 1e-28 * rr0) break;
        const double beta = rzNew / rz;
        rz = rzNew;
        for (std::size_t k = 0; k < m; ++k)
            w.p[k] = w.z[k] + beta * w.p[k];
    }
    applyJt(cs, s, w, w.x);
}

// Directly where the band is narrow, else (or where that fails) iteratively.
void solve(const std::vector<DistanceConstraint>& cs, const ParticleSet& s, ConstraintScratch& w,
           int bandwidth) {
    if (bandwidth == 1 && solveTridiagonal(cs, s, w)) return;
    if (bandwidth != 1 && bandwidth <= kDirectBandwidth && solveBanded(cs, s, w, bandwidth)) return;
    solveIterative(cs, s, w);
}

// x += dp at every constraint end, once each (an end shared by two links is consumed
// by the first: its dp is zeroed after use).
void applyToEnds(const std::vector<DistanceConstraint>& cs, ConstraintScratch& w,
                 std::vector<double>& x, std::vector<double>& y) {
    for (const auto& c : cs)
        for (const ParticleId id : {c.a, c.b}) {
            if (id == kNoParticle) continue;
            x[id] += w.dp[id].x;
            y[id] += w.dp[id].y;
            w.dp[id] = Vec2{};
        }
}

} // namespace

std::string validate(const DistanceConstraint& c, const ParticleSet& set) {
    if (!set.alive(c.a)) return "constraint end a is not a live particle";
    if (c.b != kNoParticle && !set.alive(c.b)) return "constraint end b is not a live particle";
    if (c.b == c.a) return "constraint joins a particle to itself";
    if (!(c.length > 0.0) || !std::isfinite(c.length)) return "constraint length must be > 0 m";
    return {};
}

double lengthError(const DistanceConstraint& c, const ParticleSet& set) {
    const double L = length(set.position(c.a) - otherEnd(c, set));
    const double err = (L - c.length) / c.length;
    return c.kind == ConstraintKind::Cable ? std::max(err, 0.0) : std::abs(err);
}

double solveConstraints(const std::vector<DistanceConstraint>& cs, ParticleSet& set,
                        ConstraintScratch& w, int newtonSteps, double tolerance) {
    w.lastIterations = 0;
    w.lastDirectSolves = 0;
    if (cs.empty()) return 0.0;
    const std::size_t m = cs.size();
    for (auto* v : {&w.rhs, &w.x, &w.r, &w.z, &w.p, &w.q})
        v->resize(m);
    w.dir.resize(m);
    w.active.resize(m);
    w.dp.resize(set.slots());
    const int bandwidth = bandwidthOf(cs, set.slots(), w);

    // Position: Newton steps on C(p) = 0 over the rods and the taut cables.
    for (int step = 0; step < newtonSteps; ++step) {
        double worst = 0.0;
        for (std::size_t k = 0; k < m; ++k) {
            const auto& c = cs[k];
            const Vec2 d = set.position(c.a) - otherEnd(c, set);
            const double L = length(d);
            const double C = L - c.length;
            w.active[k] = L > 0.0 && (c.kind == ConstraintKind::Rod || C > 0.0) &&
                          wOf(set, c.a) + wOf(set, c.b) > 0.0;
            w.dir[k] = L > 0.0 ? d / L : Vec2{};
            w.rhs[k] = -C;
            if (w.active[k]) worst = std::max(worst, std::abs(C) / c.length);
        }
        if (worst <= tolerance) break;
        solve(cs, set, w, bandwidth);
        applyToEnds(cs, w, set.px, set.py);
    }

    // Velocity: no relative velocity along a rod, none stretching a taut cable.
    for (std::size_t k = 0; k < m; ++k) {
        const auto& c = cs[k];
        const Vec2 d = set.position(c.a) - otherEnd(c, set);
        const double L = length(d);
        w.dir[k] = L > 0.0 ? d / L : Vec2{};
        const Vec2 vb = c.b != kNoParticle ? set.velocity(c.b) : Vec2{};
        const double u = dot(set.velocity(c.a) - vb, w.dir[k]);
        const bool taut = L >= c.length * (1.0 - tolerance) - 1e-12;
        w.active[k] = L > 0.0 && wOf(set, c.a) + wOf(set, c.b) > 0.0 &&
                      (c.kind == ConstraintKind::Rod || (taut && u > 0.0));
        w.rhs[k] = -u;
    }
    solve(cs, set, w, bandwidth);
    applyToEnds(cs, w, set.vx, set.vy);

    // Anything a constraint moved forgets its multi-step integrator history.
    double worst = 0.0;
    for (const auto& c : cs) {
        for (const ParticleId id : {c.a, c.b})
            if (id != kNoParticle && set.invMass[id] > 0.0)
                set.flags[id] &= ~(kVerletPrimed | kLeapfrogPrimed);
        worst = std::max(worst, lengthError(c, set));
    }
    return worst;
}

} // namespace phys
