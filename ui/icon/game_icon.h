// The game's icon, drawn by the game's own renderer: a cannon on a hill, the dotted arc
// of its shot (the firing solution, physics/ballistics.h) and the shell coming down on a
// tower of blocks, on a rounded square of sky. Drawn at any size; the install puts it
// in the desktop's icon theme at several (packaging/install.cmake).
#pragma once

#include "game/cli/verbs.h"
#include "ui/charts/chart.h"
#include "ui/render/renderer2d.h"

namespace ui {

/// Draws the icon filling `area` (pixels, y up); outside the rounded square nothing is
/// drawn, so a picture cleared transparent keeps transparent corners.
void drawGameIcon(Renderer2D& r, charts::Rect area);

/// `artillery icon`: the icon as a PNG of a given size, headless.
const game::cli::Verb& iconVerb();

} // namespace ui
