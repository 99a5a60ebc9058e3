// The paths of one sub-step: where each active particle goes between the start of the
// sub-step (S0, kept before the integrator moves it) and where the integrator put it
// (S1), as the parabola through both (time_of_impact.h). For a particle that nothing
// touches, S1 stands as it is. A contact changes a path from its time on (rebase, then
// a new velocity and, on a resting contact, support by the surface); finish writes the
// end of each changed path back as the particle's state.
//
// Beside each path runs the state velocity and its rate: the velocity the integrator
// reports, which for explicit Euler differs from the path's slope. The impulses act on
// that velocity, so each integrator keeps its own error.
#pragma once

#include "physics/collision/time_of_impact.h"
#include "physics/materials.h"
#include "physics/particles.h"

#include <cstdint>
#include <span>
#include <vector>

namespace phys {

class SubstepPaths {
  public:
    /// Saves the state the sub-step starts from (call before integrating).
    void begin(const ParticleSet& set);
    /// The paths of the `active` particles over a sub-step of h seconds, untouched.
    void build(const ParticleSet& set, const std::vector<std::uint32_t>& active, double h);
    /// For the contact solver: each active particle's path a straight line from where it
    /// started the sub-step to where it ends it.
    void straightenToEnd(const ParticleSet& set, const std::vector<std::uint32_t>& active,
                         double h);
    /// A particle whose path a contact changed takes the end of its new path as its state.
    void finish(ParticleSet& set, const std::vector<std::uint32_t>& active, double h) const;

    PathMotion& path(std::size_t i) { return path_[i]; }
    const PathMotion& path(std::size_t i) const { return path_[i]; }
    /// The first n paths (n: the particles' slots).
    std::span<const PathMotion> paths(std::size_t n) const {
        return std::span<const PathMotion>(path_).first(n);
    }
    /// The state velocity and its rate at the path's start.
    Vec2& velocity(std::size_t i) { return sv_[i]; }
    Vec2& rate(std::size_t i) { return sa_[i]; }
    /// |acceleration| over the sub-step before any contact, m/s^2.
    double accel0(std::size_t i) const { return accel0_[i]; }
    /// Where particle i started the sub-step.
    Vec2 start(std::size_t i) const { return {x0_[i], y0_[i]}; }

    /// Whether a contact changed particle i's path.
    bool touched(std::size_t i) const { return touched_[i] != 0; }
    void touch(std::size_t i) { touched_[i] = 1; }
    void untouch(std::size_t i) { touched_[i] = 0; }

    /// Moves particle i's path start to time t (state velocity carried with its own rate).
    void rebase(std::size_t i, double t);
    /// Resting contact: the surface of normal n carries particle i for the `remaining`
    /// time of the step (normal force and Coulomb friction through the acceleration), and
    /// with the surface that last supported it in this sub-step, if another (`surface`:
    /// the proxy of what supports it, a particle or slots + a shape's index), both at once.
    void support(std::size_t i, Vec2 n, Vec2 vNew, const PairProperties& pp, double remaining,
                 std::uint32_t surface);

  private:
    void supportAlong(std::size_t i, Vec2 n, Vec2 vNew, const PairProperties& pp, double remaining);
    // Start of the sub-step (S0).
    std::vector<double> x0_, y0_, vx0_, vy0_;
    // Paths: position, path velocity, path acceleration at t0, and the path's start time;
    // state velocity and its rate at t0.
    std::vector<PathMotion> path_;
    std::vector<Vec2> sv_, sa_;
    std::vector<double> accel0_;
    std::vector<std::uint8_t> touched_;
    struct LastSupport {
        Vec2 normal;
        std::uint32_t surface = 0;
        std::uint64_t substep = 0; ///< substep_ when it supported
    };
    std::vector<LastSupport> lastSupport_;
    std::uint64_t substep_ = 0; ///< counts the sub-steps over the world's life
};

} // namespace phys
