// The contact solver's rows as columns, and the sweeps over them (the velocity and the
// position steps of the contact solver, contact_solver.h).
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

/// The solver's rows, one per contact, which both steps sweep: velocity (the normal
/// impulse that stops the closing velocity, accumulated and never pulling, and friction
/// along the tangent within mu_s times it) and position (push the overlap apart along the
/// current normal, at most `cap` at once, `fa` and `fb` of it to each side). Each row has
/// two sets of masses: those of the sweeps over all contacts, and those of the sweeps over
/// its band alone (shock propagation: what holds it up may be immovable).
struct ContactRows {
    /// Inverse masses, the effective mass 1 / (wa + wb) (0: the row does nothing in these
    /// sweeps), each side's share of a push (wa and wb over wa + wb), where b's push goes
    /// (b, or the sink).
    struct Masses {
        std::vector<double> wa, wb, mass, fa, fb;
        std::vector<std::uint32_t> pushB;
    };
    std::vector<std::uint32_t> a, readB; ///< readB: b, or still for a shape
    std::vector<std::uint32_t> contact;  ///< the caller's index of the row's contact
    std::vector<std::uint8_t> shape;     ///< against a shape: the caller projects the row
    std::vector<double> nx, ny, closing, friction;
    std::vector<double> reach, cap; ///< radii summed (a's radius for a shape); most moved
    Masses all, band;
    std::vector<double> normalImpulse, tangentImpulse; ///< accumulated, N s
    /// All ones where a lane sweep's step changed something (markTouched reads it).
    std::vector<std::uint64_t> changed;

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
void sweepImpulseRows(ContactRows& rows, const ContactRows::Masses& masses,
                         std::size_t from, std::size_t to, Vec2* velocity, std::uint8_t* touched,
                         bool lanes);

/// One position sweep over rows [from, to), the same way; `shapeStep(k)` steps a row
/// against a shape (such rows gather in runs of their own, four to a run when `lanes`) and
/// returns how far it pushed (0: not at all). Returns whether any row pushed its sides
/// apart by more than `deepShare` of its cap (the most it moves at once): deep overlap is
/// left.
template <class ShapeStep>
bool sweepProjectRows(ContactRows& rows, const ContactRows::Masses& masses,
                         std::size_t from, std::size_t to, Vec2* position, std::uint8_t* touched,
                         bool lanes, double deepShare, ShapeStep&& shapeStep);

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

// The parts of sweepProjectRows that are not templates.
namespace detail {
/// Whether the push was deep.
bool projectPair(const ContactRows& rows, const ContactRows::Masses& masses, std::size_t k,
                 Vec2* position, std::uint8_t* touched, double deepShare);
/// The runs of four pair rows from `from` on, each four at once, up to `to` or the first
/// run of shape rows, where it stops (contactLanesAvailable() only); `deep` becomes true
/// where a push was deep.
std::size_t projectPairRuns(ContactRows& rows, const ContactRows::Masses& masses,
                            std::size_t from, std::size_t to, Vec2* position, double deepShare,
                            bool& deep);
} // namespace detail

template <class ShapeStep>
bool sweepProjectRows(ContactRows& rows, const ContactRows::Masses& masses,
                         std::size_t from, std::size_t to, Vec2* position, std::uint8_t* touched,
                         bool lanes, double deepShare, ShapeStep&& shapeStep) {
    bool deep = false;
    auto shapeRow = [&](std::size_t k) { return shapeStep(k) > deepShare * rows.cap[k]; };
    if (!lanes) {
        for (std::size_t k = from; k < to; ++k) {
            const bool deepPush =
                rows.shape[k] ? shapeRow(k)
                              : detail::projectPair(rows, masses, k, position, touched, deepShare);
            deep = deep || deepPush;
        }
        return deep;
    }
    for (std::size_t k = detail::projectPairRuns(rows, masses, from, to, position, deepShare, deep);
         k < to; k = detail::projectPairRuns(rows, masses, k + 4, to, position, deepShare, deep))
        for (std::size_t l = k; l < k + 4; ++l)
            if (rows.shape[l]) deep = shapeRow(l) || deep; // padding: a pair row
    return deep;
}

} // namespace phys
