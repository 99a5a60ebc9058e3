// The ground: a heightfield polyline resampled to an even spacing, so that a blast can
// carve a round crater anywhere and later shots and rolling balls feel it.
#pragma once

#include "physics/vec2.h"

#include <vector>

namespace game {

class Heightfield {
  public:
    /// Resamples the level's polyline (x strictly increasing) every `spacing` metres, or
    /// in 8192 equal steps when that is coarser (grounds longer than 4 km).
    explicit Heightfield(const std::vector<phys::Vec2>& points, double spacing = 0.5);

    /// Ground height at x (linear between samples; clamped at the ends).
    double heightAt(double x) const;
    /// Removes the disc of `radius` around `center` from the ground: every sample
    /// inside it drops to the disc's lower edge. Returns true when anything changed.
    bool carve(phys::Vec2 center, double radius);
    const std::vector<phys::Vec2>& points() const { return points_; }
    double minX() const { return points_.front().x; }
    double maxX() const { return points_.back().x; }

  private:
    std::vector<phys::Vec2> points_;
    double spacing_;
};

} // namespace game
