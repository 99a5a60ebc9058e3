// The boxes of the particles' paths over a step: what each detection boxes before it
// asks the pair cache (Proxies::build), every active particle of a pile
// twice a sub-step. A quadratic path lies in the triangle of its Bezier control points
// (start, start + v T/2, end), so its box is theirs, grown by the particle's reach.
//
// Where the processor has AVX2 the boxes are made four at a time: the paths loaded and
// transposed, the one-path arithmetic in lanes in the same order (no fused multiply-add;
// min and max pick as std::min and std::max do, signed zeros and NaNs included), so the
// boxes are the same bits.
#pragma once

#include "physics/collision/time_of_impact.h"

#include <cstdint>
#include <span>

namespace phys {

/// How a detection boxes its paths: to the step's end (h, seconds into the step), the
/// reach radius * (1 + grow) + tolerance, the end alone or the whole path.
struct PathBoxing {
    double h, grow, tolerance;
    bool atEndOnly;
};

/// The box of path `m` of a particle of `radius`, as PathBoxing says.
Aabb pathBox(const PathMotion& m, double radius, const PathBoxing& b);

/// boxes[i] = pathBox(paths[i], radius[i], b) for each i of `which`.
void pathBoxes(std::span<const std::uint32_t> which, std::span<const PathMotion> paths,
               std::span<const double> radius, const PathBoxing& b, Aabb* boxes);

/// pathBoxes one path at a time without AVX2 (the reference the tests compare with).
void pathBoxesScalar(std::span<const std::uint32_t> which, std::span<const PathMotion> paths,
                     std::span<const double> radius, const PathBoxing& b, Aabb* boxes);

} // namespace phys
