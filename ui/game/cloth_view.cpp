#include "ui/game/cloth_view.h"

#include "ui/game/palette.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace ui {

namespace {

using namespace palette;
using phys::ParticleId;
using phys::Vec2;

const Color kFabric = Color::hex(0xd9826b);
const Color kFabricTaut = Color::hex(0xf2b9a2);
const Color kFabricFold = Color::hex(0x8f4a3b);
const Color kRod = Color::hex(0x2b2f35);

/// Particle `row`, `col` of the cloth, or none if the grid has no such particle or it is
/// gone.
const ParticleId* cell(const game::ClothState& c, const phys::ParticleSet& ps, int row, int col) {
    const std::size_t i = static_cast<std::size_t>(row) * static_cast<std::size_t>(c.columns) +
                          static_cast<std::size_t>(col);
    if (i >= c.particles.size() || !ps.alive(c.particles[i])) return nullptr;
    return &c.particles[i];
}

void drawCloth(Renderer2D& r, const game::ClothState& c, const phys::ParticleSet& ps) {
    if (c.columns < 2 || !(c.spacing > 0.0)) return;
    const int rows = static_cast<int>(c.particles.size()) / c.columns;
    const Color thread = darker(kFabric, 0.72f).withAlpha(0.6f);
    for (int row = 0; row + 1 < rows; ++row)
        for (int col = 0; col + 1 < c.columns; ++col) {
            const ParticleId* ids[] = {cell(c, ps, row, col), cell(c, ps, row, col + 1),
                                       cell(c, ps, row + 1, col + 1), cell(c, ps, row + 1, col)};
            if (std::any_of(std::begin(ids), std::end(ids), [](const ParticleId* id) { return !id; }))
                continue;
            std::array<Vec2, 4> q;
            for (std::size_t k = 0; k < 4; ++k) q[k] = ps.position(*ids[k]);
            double sides = 0.0;
            for (std::size_t k = 0; k < 4; ++k) sides += length(q[(k + 1) % 4] - q[k]);
            const Color fill = clothFill(sides / (4.0 * c.spacing) - 1.0);
            r.triangle(q[0], q[1], q[2], fill, fill, fill);
            r.triangle(q[0], q[2], q[3], fill, fill, fill);
            // The threads: the cell's top and left sides, and the last row's and column's.
            r.line(q[0], q[1], thread, 1.0f);
            r.line(q[0], q[3], thread, 1.0f);
            if (row + 2 == rows) r.line(q[3], q[2], thread, 1.0f);
            if (col + 2 == c.columns) r.line(q[1], q[2], thread, 1.0f);
        }
    // The rod it hangs from, along its top row.
    std::vector<Vec2> top;
    for (int col = 0; col < c.columns; ++col)
        if (const ParticleId* id = cell(c, ps, 0, col)) top.push_back(ps.position(*id));
    if (top.size() > 1) r.polyline(top, kRod, 4.0f);
}

} // namespace

Color clothColor() { return kFabric; }

Color clothFill(double strain) {
    const float t = static_cast<float>(std::min(std::abs(strain) / 0.15, 1.0));
    return mix(kFabric, strain > 0.0 ? kFabricTaut : kFabricFold, t);
}

void drawCloths(Renderer2D& r, const game::Match& match) {
    for (const game::ClothState& c : match.cloths()) drawCloth(r, c, match.world().particles);
}

void markClothParticles(const game::Match& match, std::vector<bool>& owned) {
    for (const game::ClothState& c : match.cloths())
        for (const ParticleId id : c.particles)
            if (id < owned.size()) owned[id] = true;
}

} // namespace ui
