// How a cloth looks: a sheet of fabric over its grid of particles, each cell two
// triangles shaded by how far the cell is stretched or bunched, thin threads along its
// rows and columns, and a rod along the top row it hangs from. Its particles are not
// drawn as dots (the debug view's rings still show them).
#pragma once

#include "game/match.h"
#include "ui/render/renderer2d.h"

#include <vector>

namespace ui {

/// The fabric's colour: the cloth at rest.
phys::Color clothColor();
/// A cell's fill at `strain` (mean side length over the rest spacing, minus one): lighter
/// where it is pulled taut, darker where it bunches into a fold, fully so at 15 %.
phys::Color clothFill(double strain);

/// Draws every cloth of the match.
void drawCloths(Renderer2D& r, const game::Match& match);

/// Marks the particles of every cloth in `owned` (indexed by particle slot), so the
/// loose particles leave them out.
void markClothParticles(const game::Match& match, std::vector<bool>& owned);

} // namespace ui
