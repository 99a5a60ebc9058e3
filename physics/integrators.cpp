#include "physics/integrators.h"

#include "physics/model_pass.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace phys {

namespace {

constexpr IntegratorInfo kIntegrators[] = {
    {Integrator::ExplicitEuler, "explicit-euler", nullptr, 1, 1, false,
     "p' = p + dt v, v' = v + dt a(p, v)"},
    {Integrator::SymplecticEuler, "symplectic-euler", "euler-cromer", 1, 1, false,
     "v' = v + dt a(p, v), p' = p + dt v'"},
    {Integrator::Verlet, "verlet", "position-verlet", 1, 1, false,
     "p' = 2p - p_prev + dt^2 a(p), first step explicit Euler"},
    {Integrator::VelocityVerlet, "velocity-verlet", nullptr, 2, 2, true,
     "p' = p + dt v + dt^2/2 a, v' = v + dt/2 (a + a')"},
    {Integrator::Leapfrog, "leapfrog", nullptr, 2, 1, true,
     "v(n+1/2) = v(n-1/2) + dt a(p), p' = p + dt v(n+1/2)"},
    {Integrator::Midpoint, "midpoint", "rk2", 2, 2, true,
     "S' = S + dt f(S + dt/2 f(S))"},
    {Integrator::RK4, "rk4", "runge-kutta", 4, 4, true,
     "S' = S + dt/6 (k1 + 2 k2 + 2 k3 + k4)"},
    {Integrator::ImplicitEuler, "implicit-euler", "backward-euler", 1, 2, false,
     "(M - dt dF/dv - dt^2 dF/dx) dv = dt (F + dt dF/dx v), p' = p + dt v'"},
};

// --- explicit Euler: S(t+dt) = S(t) + dt dS/dt(t). Order 1. -------------------------
void explicitEuler(const Dynamics& dyn, ParticleSet& s, double dt, IntegratorScratch& w) {
    const std::size_t n = s.slots();
    dyn.accelerations(s.px.data(), s.py.data(), s.vx.data(), s.vy.data(), w.ax.data(),
                      w.ay.data());
    for (std::size_t i = 0; i < n; ++i) {
        s.px[i] += dt * s.vx[i];
        s.py[i] += dt * s.vy[i];
        s.vx[i] += dt * w.ax[i];
        s.vy[i] += dt * w.ay[i];
    }
}

// --- symplectic Euler (Euler-Cromer): the new velocity moves the position. Order 1,
// symplectic, so energy stays bounded on a spring for w dt < 2.
void symplecticEuler(const Dynamics& dyn, ParticleSet& s, double dt, IntegratorScratch& w) {
    const std::size_t n = s.slots();
    if (dyn.onlyLocalForces()) {
        // Fused: each particle's acceleration depends on its own state only, so force
        // evaluation and update share one pass over memory (same arithmetic, same bits
        // as the general path). A closed-form particle only drifts: the world sets it
        // from its parabola after the step.
        const LocalForceLaw law = dyn.localLaw();
        const Vec2 g = dyn.def().gravity;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t f = s.flags[i];
            symplecticLocalStep(s, i, (f & kBallistic) ? 0u : f, law, g, dt); // 0: no forces
        }
        return;
    }
    dyn.accelerations(s.px.data(), s.py.data(), s.vx.data(), s.vy.data(), w.ax.data(),
                      w.ay.data());
    for (std::size_t i = 0; i < n; ++i) {
        s.vx[i] += dt * w.ax[i];
        s.vy[i] += dt * w.ay[i];
        s.px[i] += dt * s.vx[i];
        s.py[i] += dt * s.vy[i];
    }
}

// --- position Verlet (Rabin, Introduction to Game Development, 4.3): S = <p>, p(t+dt) = 2 p(t) - p(t-dt) + dt^2 a(t).
// It needs two prior states, so a particle's first step (and the first after anything
// changed its velocity from outside) is one explicit Euler step. The velocity it
// reports is (p' - p)/dt + dt/2 a, which is second-order accurate at the new time.
// The recursion itself is second order, but the Euler start puts an O(dt^2) error in
// p(dt), which is an O(dt) error in the initial velocity the recursion implies: so as
// that chapter builds it, Verlet converges with order 1 (measured: the error halves with
// dt). Under constant acceleration it reproduces explicit Euler's positions exactly.
void verlet(const Dynamics& dyn, ParticleSet& s, double dt, IntegratorScratch& w) {
    const std::size_t n = s.slots();
    dyn.accelerations(s.px.data(), s.py.data(), s.vx.data(), s.vy.data(), w.ax.data(),
                      w.ay.data());
    const double dt2 = dt * dt;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = s.px[i], y = s.py[i];
        if (s.flags[i] & kVerletPrimed) {
            s.px[i] = 2.0 * x - s.prevX[i] + dt2 * w.ax[i];
            s.py[i] = 2.0 * y - s.prevY[i] + dt2 * w.ay[i];
            s.vx[i] = (s.px[i] - x) / dt + 0.5 * dt * w.ax[i];
            s.vy[i] = (s.py[i] - y) / dt + 0.5 * dt * w.ay[i];
        } else {
            s.px[i] = x + dt * s.vx[i];
            s.py[i] = y + dt * s.vy[i];
            s.vx[i] += dt * w.ax[i];
            s.vy[i] += dt * w.ay[i];
            s.flags[i] |= kVerletPrimed;
        }
        s.prevX[i] = x;
        s.prevY[i] = y;
    }
}

// --- velocity Verlet: p' = p + dt v + dt^2/2 a(p, v); v' = v + dt/2 (a + a(p', v*)),
// with v* = v + dt a the predicted velocity for velocity-dependent forces. Order 2.
void velocityVerlet(const Dynamics& dyn, ParticleSet& s, double dt, IntegratorScratch& w) {
    const std::size_t n = s.slots();
    dyn.accelerations(s.px.data(), s.py.data(), s.vx.data(), s.vy.data(), w.ax.data(),
                      w.ay.data());
    const double half = 0.5 * dt * dt;
    for (std::size_t i = 0; i < n; ++i) {
        s.px[i] += dt * s.vx[i] + half * w.ax[i];
        s.py[i] += dt * s.vy[i] + half * w.ay[i];
        w.tvx[i] = s.vx[i] + dt * w.ax[i];
        w.tvy[i] = s.vy[i] + dt * w.ay[i];
    }
    dyn.accelerations(s.px.data(), s.py.data(), w.tvx.data(), w.tvy.data(), w.bx.data(),
                      w.by.data());
    for (std::size_t i = 0; i < n; ++i) {
        s.vx[i] += 0.5 * dt * (w.ax[i] + w.bx[i]);
        s.vy[i] += 0.5 * dt * (w.ay[i] + w.by[i]);
    }
}

// --- leapfrog: velocities live at half steps. v(n+1/2) = v(n-1/2) + dt a(p_n),
// p(n+1) = p(n) + dt v(n+1/2). One force evaluation per step. The reported velocity is
// v(n+1/2) + dt/2 a(p_n); a particle without a half-step velocity gets v - dt/2 a.
void leapfrog(const Dynamics& dyn, ParticleSet& s, double dt, IntegratorScratch& w) {
    const std::size_t n = s.slots();
    dyn.accelerations(s.px.data(), s.py.data(), s.vx.data(), s.vy.data(), w.ax.data(),
                      w.ay.data());
    for (std::size_t i = 0; i < n; ++i) {
        double hx = s.halfVx[i], hy = s.halfVy[i];
        if (!(s.flags[i] & kLeapfrogPrimed)) {
            hx = s.vx[i] - 0.5 * dt * w.ax[i];
            hy = s.vy[i] - 0.5 * dt * w.ay[i];
            s.flags[i] |= kLeapfrogPrimed;
        }
        hx += dt * w.ax[i];
        hy += dt * w.ay[i];
        s.px[i] += dt * hx;
        s.py[i] += dt * hy;
        s.vx[i] = hx + 0.5 * dt * w.ax[i];
        s.vy[i] = hy + 0.5 * dt * w.ay[i];
        s.halfVx[i] = hx;
        s.halfVy[i] = hy;
    }
}

// --- explicit midpoint (RK2): S' = S + dt f(S + dt/2 f(S)). Order 2.
void midpoint(const Dynamics& dyn, ParticleSet& s, double dt, IntegratorScratch& w) {
    const std::size_t n = s.slots();
    dyn.accelerations(s.px.data(), s.py.data(), s.vx.data(), s.vy.data(), w.ax.data(),
                      w.ay.data());
    const double h = 0.5 * dt;
    for (std::size_t i = 0; i < n; ++i) {
        w.tpx[i] = s.px[i] + h * s.vx[i];
        w.tpy[i] = s.py[i] + h * s.vy[i];
        w.tvx[i] = s.vx[i] + h * w.ax[i];
        w.tvy[i] = s.vy[i] + h * w.ay[i];
    }
    dyn.accelerations(w.tpx.data(), w.tpy.data(), w.tvx.data(), w.tvy.data(), w.bx.data(),
                      w.by.data());
    for (std::size_t i = 0; i < n; ++i) {
        s.px[i] += dt * w.tvx[i];
        s.py[i] += dt * w.tvy[i];
        s.vx[i] += dt * w.bx[i];
        s.vy[i] += dt * w.by[i];
    }
}

// --- classic Runge-Kutta: k1 = f(S), k2 = f(S + dt/2 k1), k3 = f(S + dt/2 k2),
// k4 = f(S + dt k3), S' = S + dt/6 (k1 + 2 k2 + 2 k3 + k4). Order 4.
// The position part of k_i is the stage velocity, so it is carried in the sums below.
void rk4(const Dynamics& dyn, ParticleSet& s, double dt, IntegratorScratch& w) {
    const std::size_t n = s.slots();
    const double h = 0.5 * dt, sixth = dt / 6.0;
    // k1: (v, a) at S.
    dyn.accelerations(s.px.data(), s.py.data(), s.vx.data(), s.vy.data(), w.ax.data(),
                      w.ay.data());
    // Accumulate the weighted velocity sum in d* and acceleration sum in c*.
    for (std::size_t i = 0; i < n; ++i) {
        w.dx[i] = s.vx[i];
        w.dy[i] = s.vy[i];
        w.cx[i] = w.ax[i];
        w.cy[i] = w.ay[i];
        w.tpx[i] = s.px[i] + h * s.vx[i];
        w.tpy[i] = s.py[i] + h * s.vy[i];
        w.tvx[i] = s.vx[i] + h * w.ax[i];
        w.tvy[i] = s.vy[i] + h * w.ay[i];
    }
    // k2 and k3 at midpoints, k4 at the end.
    const double stageStep[3] = {h, dt, 0.0};
    const double stageWeight[3] = {2.0, 2.0, 1.0};
    for (int stage = 0; stage < 3; ++stage) {
        dyn.accelerations(w.tpx.data(), w.tpy.data(), w.tvx.data(), w.tvy.data(), w.bx.data(),
                          w.by.data());
        const double wgt = stageWeight[stage], next = stageStep[stage];
        for (std::size_t i = 0; i < n; ++i) {
            const double kvx = w.tvx[i], kvy = w.tvy[i]; // this stage's dp/dt
            w.dx[i] += wgt * kvx;
            w.dy[i] += wgt * kvy;
            w.cx[i] += wgt * w.bx[i];
            w.cy[i] += wgt * w.by[i];
            if (next > 0.0) {
                w.tpx[i] = s.px[i] + next * kvx;
                w.tpy[i] = s.py[i] + next * kvy;
                w.tvx[i] = s.vx[i] + next * w.bx[i];
                w.tvy[i] = s.vy[i] + next * w.by[i];
            }
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        s.px[i] += sixth * w.dx[i];
        s.py[i] += sixth * w.dy[i];
        s.vx[i] += sixth * w.cx[i];
        s.vy[i] += sixth * w.cy[i];
    }
}

// --- implicit (backward) Euler, linearised (Baraff & Witkin 1998):
//   v' = v + dv,  (M - dt dF/dv - dt^2 dF/dx) dv = dt (F(p, v) + dt dF/dx v),  p' = p + dt v'.
// The system is symmetric positive definite for springs and drag, so it is solved by
// conjugate gradients, matrix-free (the force model multiplies by its Jacobian).
// Fixed and sleeping particles are filtered out (dv = 0). Unconditionally stable:
// on an undamped spring the energy decays by 1/(1 + (w dt)^2) per step.
// The linear system of one implicit Euler step, A dv = b with A = M - dt dF/dv - dt^2
// dF/dx, solved matrix-free: A is applied through the force model's Jacobian product.
class ImplicitSystem {
  public:
    ImplicitSystem(const Dynamics& dyn, ParticleSet& s, double dt, IntegratorScratch& w)
        : dyn_(dyn), s_(s), w_(w), n_(s.slots()), dt_(dt), dt2_(dt * dt) {}

    // b = dt F + dt^2 dF/dx v, stored in r (the residual of dv = 0), with z = 0, q = r.
    void rightHandSide() {
        IntegratorScratch& w = w_;
        dyn_.nonGravityForces(s_.px.data(), s_.py.data(), s_.vx.data(), s_.vy.data(), w.ax.data(),
                              w.ay.data());
        for (std::size_t i = 0; i < n_; ++i) {
            w.tpx[i] = dt2_ * s_.vx[i];
            w.tpy[i] = dt2_ * s_.vy[i];
            w.tvx[i] = 0.0;
            w.tvy[i] = 0.0;
        }
        dyn_.forceJacobianProduct(s_.px.data(), s_.py.data(), s_.vx.data(), s_.vy.data(),
                                  w.tpx.data(), w.tpy.data(), w.tvx.data(), w.tvy.data(),
                                  w.bx.data(), w.by.data());
        for (std::size_t i = 0; i < n_; ++i) {
            const double m = mass(i);
            const Vec2 g = dyn_.gravityOn(i);
            w.rx[i] = m > 0.0 ? dt_ * (w.ax[i] + m * g.x) + w.bx[i] : 0.0;
            w.ry[i] = m > 0.0 ? dt_ * (w.ay[i] + m * g.y) + w.by[i] : 0.0;
            w.zx[i] = w.zy[i] = 0.0;
            w.qx[i] = w.rx[i];
            w.qy[i] = w.ry[i];
        }
    }

    // Conjugate gradients on A dv = b, into z; the iterations taken.
    int solve(const ImplicitDef& def) {
        IntegratorScratch& w = w_;
        double rr = dot2(w.rx, w.ry, w.rx, w.ry);
        const double stop = rr * def.tolerance * def.tolerance;
        int it = 0;
        for (; it < def.maxIterations && rr > stop && rr > 0.0; ++it) {
            applyA(w.qx, w.qy, w.sx, w.sy);
            const double qAq = dot2(w.qx, w.qy, w.sx, w.sy);
            if (!(qAq > 0.0)) break; // not positive definite along q: stop with what we have
            const double alpha = rr / qAq;
            for (std::size_t i = 0; i < n_; ++i) {
                w.zx[i] += alpha * w.qx[i];
                w.zy[i] += alpha * w.qy[i];
                w.rx[i] -= alpha * w.sx[i];
                w.ry[i] -= alpha * w.sy[i];
            }
            const double rrNew = dot2(w.rx, w.ry, w.rx, w.ry);
            const double beta = rrNew / rr;
            rr = rrNew;
            for (std::size_t i = 0; i < n_; ++i) {
                w.qx[i] = w.rx[i] + beta * w.qx[i];
                w.qy[i] = w.ry[i] + beta * w.qy[i];
            }
        }
        return it;
    }

  private:
    double mass(std::size_t i) const { return dyn_.active(i) ? 1.0 / s_.invMass[i] : 0.0; }
    double dot2(const std::vector<double>& ax, const std::vector<double>& ay,
                const std::vector<double>& bx, const std::vector<double>& by) const {
        double sum = 0.0;
        for (std::size_t i = 0; i < n_; ++i) sum += ax[i] * bx[i] + ay[i] * by[i];
        return sum;
    }
    // out = A z for the active entries (inactive entries 0).
    void applyA(const std::vector<double>& zx, const std::vector<double>& zy,
                std::vector<double>& outx, std::vector<double>& outy) {
        IntegratorScratch& w = w_;
        for (std::size_t i = 0; i < n_; ++i) {
            w.tpx[i] = dt2_ * zx[i];
            w.tpy[i] = dt2_ * zy[i];
            w.tvx[i] = dt_ * zx[i];
            w.tvy[i] = dt_ * zy[i];
        }
        dyn_.forceJacobianProduct(s_.px.data(), s_.py.data(), s_.vx.data(), s_.vy.data(),
                                  w.tpx.data(), w.tpy.data(), w.tvx.data(), w.tvy.data(),
                                  outx.data(), outy.data());
        for (std::size_t i = 0; i < n_; ++i) {
            const double m = mass(i);
            outx[i] = m > 0.0 ? m * zx[i] - outx[i] : 0.0;
            outy[i] = m > 0.0 ? m * zy[i] - outy[i] : 0.0;
        }
    }
    const Dynamics& dyn_;
    ParticleSet& s_;
    IntegratorScratch& w_;
    std::size_t n_;
    double dt_, dt2_;
};

void implicitEuler(const Dynamics& dyn, ParticleSet& s, double dt, IntegratorScratch& w,
                   const ImplicitDef& def) {
    ImplicitSystem system(dyn, s, dt, w);
    system.rightHandSide();
    w.lastSolverIterations = system.solve(def);
    for (std::size_t i = 0; i < s.slots(); ++i) {
        s.vx[i] += w.zx[i];
        s.vy[i] += w.zy[i];
        s.px[i] += dt * s.vx[i];
        s.py[i] += dt * s.vy[i];
    }
}

} // namespace

std::span<const IntegratorInfo> integrators() { return kIntegrators; }

const IntegratorInfo& info(Integrator id) {
    for (const auto& i : kIntegrators)
        if (i.id == id) return i;
    return kIntegrators[0];
}

std::optional<Integrator> integratorFromName(std::string_view name) {
    for (const auto& i : kIntegrators)
        if (name == i.name || (i.alias && name == i.alias)) return i.id;
    return std::nullopt;
}

std::string integratorNameList() {
    std::string out;
    for (const auto& i : kIntegrators) {
        if (!out.empty()) out += ", ";
        out += i.name;
        if (i.alias) out += std::string(" (") + i.alias + ")";
    }
    return out;
}

void IntegratorScratch::resize(std::size_t n) {
    for (auto* v : {&ax, &ay, &bx, &by, &cx, &cy, &dx, &dy, &tpx, &tpy, &tvx, &tvy, &rx, &ry,
                    &qx, &qy, &sx, &sy, &zx, &zy})
        if (v->size() < n) v->resize(n);
}

void integrate(Integrator method, const Dynamics& dyn, ParticleSet& set, double dt,
               IntegratorScratch& scratch, const ImplicitDef& implicit) {
    scratch.resize(set.slots());
    switch (method) {
    case Integrator::ExplicitEuler: explicitEuler(dyn, set, dt, scratch); break;
    case Integrator::SymplecticEuler: symplecticEuler(dyn, set, dt, scratch); break;
    case Integrator::Verlet: verlet(dyn, set, dt, scratch); break;
    case Integrator::VelocityVerlet: velocityVerlet(dyn, set, dt, scratch); break;
    case Integrator::Leapfrog: leapfrog(dyn, set, dt, scratch); break;
    case Integrator::Midpoint: midpoint(dyn, set, dt, scratch); break;
    case Integrator::RK4: rk4(dyn, set, dt, scratch); break;
    case Integrator::ImplicitEuler: implicitEuler(dyn, set, dt, scratch, implicit); break;
    }
}

} // namespace phys
