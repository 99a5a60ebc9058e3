// The one path a match frame takes to the framebuffer, in the window and headless
// (the very same drawing code for both): clear, draw the match through MatchView, flush.
// Text labels are left in the renderer for the caller's ImGui layer, which the window
// also uses for its panels.
#pragma once

#include "ui/game/match_view.h"
#include "ui/render/renderer2d.h"

namespace ui {

void drawMatchFrame(Renderer2D& renderer, MatchView& view, const game::Match& match,
                    const Camera& camera, const MatchViewOptions& options);

} // namespace ui
