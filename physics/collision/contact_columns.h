// The contact solver's rows as columns, and the sweeps over them (the velocity and the
// position steps of ParticleCollisions::relaxContacts).
//
// A sweep's rows are laid out in its wavefronts (wavefronts.h): each wavefront's rows
// share no particle, so four of them at a time go through AVX2 lanes where the processor
// has AVX2, and one at a time otherwise. Each lane does the operations of the one-row step
// in the same order (no fused multiply-add; max, min and the clamp pick as std::max,
// std::min and std::clamp do, signed zeros included), and writes back only what that step
// writes, so both give the bits of the one-row sweep in the rows' own order.
//
// Particle indices point into the sweeps' copies of the velocities and positions, which
// have two slots past the particles: still (at rest: what a shape "moves" at) and sink
// (where a push on something immovable goes), so no row branches on either. A padding
// row stands at the sink against still, with no mass and no reach: it does nothing.
#pragma once

#include "physics/vec2.h"

#include <cstdint>
#include <vector>

namespace phys {

/// The velocity step's rows: the normal impulse that stops the closing velocity
/// (accumulated, never pulling) and friction along the tangent within mu_s times it.
/// Each row has two sets of masses: those of the sweeps over all contacts, and those of
/// the sweeps over its band alone (shock propagation: what holds it up may be immovable).
struct ImpulseColumns {
    /// Inverse masses, the effective mass 1 / (wa + wb) (or 0: no step), where b's impulse
    /// goes (b, or the sink).
    struct Masses {
        std::vector<double> wa, wb, mass;
        std::vector<std::uint32_t> pushB;
    };
    std::vector<std::uint32_t> a, readB; ///< readB: b, or still for a shape
    std::vector<double> nx, ny, closing, friction;
    Masses all, band;
    std::vector<double> normalImpulse, tangentImpulse; ///< accumulated, N s
    /// All ones where a lane sweep's step changed something (markTouched reads it).
    std::vector<std::uint64_t> changed;

    std::size_t size() const { return a.size(); }
    void resize(std::size_t n);
};

/// The position step's rows: push the overlap of a pair of particles apart along their
/// current normal, at most `cap` at once, `fa` and `fb` of it to each side. A row against
/// a shape (b = kShapeRow) is the caller's to step.
struct ProjectColumns {
    static constexpr std::uint32_t kShapeRow = 0xffffffffu;
    std::vector<std::uint32_t> a, b, pushB, contact; ///< contact: the caller's index
    std::vector<double> reach, cap, fa, fb;          ///< radii summed; most moved at once
    std::vector<std::uint64_t> changed;              ///< as for ImpulseColumns

    std::size_t size() const { return a.size(); }
    void resize(std::size_t n);
};

/// Whether the sweeps below take four rows at a time here (AVX2 on this processor).
bool contactLanesAvailable();

/// One velocity sweep over rows [from, to) with `masses` (rows.all or rows.band), in
/// wavefronts of four (`lanes`: from, to and
/// the wavefronts' runs multiples of 4) or one row at a time. `touched[k]` becomes 1 for
/// each slot a step changed: at once one row at a time, by markTouched after the lanes
/// (which keep what changed in `changed`, not to scatter flags at every step).
void sweepImpulseColumns(ImpulseColumns& rows, const ImpulseColumns::Masses& masses,
                         std::size_t from, std::size_t to, Vec2* velocity, std::uint8_t* touched,
                         bool lanes);

/// One position sweep over rows [from, to), the same way; `shapeStep(k)` steps a row
/// against a shape (such rows gather in runs of their own, four to a run when `lanes`).
template <class ShapeStep>
void sweepProjectColumns(ProjectColumns& rows, std::size_t from, std::size_t to, Vec2* position,
                         std::uint8_t* touched, bool lanes, ShapeStep&& shapeStep);

/// touched[k] = 1 for the slots of every row the lane sweeps changed (a, and where b's
/// push goes in any of `pushes`); `changed` cleared.
template <class Columns, class... Pushes>
void markTouched(Columns& rows, std::uint8_t* touched, const Pushes&... pushes) {
    for (std::size_t k = 0; k < rows.size(); ++k)
        if (rows.changed[k] != 0) {
            touched[rows.a[k]] = 1;
            ((touched[pushes[k]] = 1), ...);
            rows.changed[k] = 0;
        }
}

// The parts of sweepProjectColumns that are not templates.
namespace detail {
void projectPair(const ProjectColumns& rows, std::size_t k, Vec2* position, std::uint8_t* touched);
/// Four pair rows k .. k + 3 at once (contactLanesAvailable() only).
void projectPairs4(ProjectColumns& rows, std::size_t k, Vec2* position);
} // namespace detail

template <class ShapeStep>
void sweepProjectColumns(ProjectColumns& rows, std::size_t from, std::size_t to, Vec2* position,
                         std::uint8_t* touched, bool lanes, ShapeStep&& shapeStep) {
    if (!lanes) {
        for (std::size_t k = from; k < to; ++k) {
            if (rows.b[k] == ProjectColumns::kShapeRow)
                shapeStep(k);
            else
                detail::projectPair(rows, k, position, touched);
        }
        return;
    }
    for (std::size_t k = from; k < to; k += 4) {
        if (rows.b[k] != ProjectColumns::kShapeRow) {
            detail::projectPairs4(rows, k, position);
            continue;
        }
        for (std::size_t l = k; l < k + 4; ++l)
            if (rows.b[l] == ProjectColumns::kShapeRow) shapeStep(l); // padding: a pair row
    }
}

} // namespace phys
