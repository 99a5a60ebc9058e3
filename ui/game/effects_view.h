// How the effects look (game/effects/effects.h holds what they are): the crust of craters
// and the soil scattered around them under everything that moves; debris, splinters,
// spray, smoke, the flash and splash rings over the scene; the shot's feedback (the miss
// note at the landing point, score pop-ups, hit markers) on top. Reads, never writes.
#pragma once

#include "game/effects/effects.h"
#include "game/match.h"
#include "ui/render/renderer2d.h"

namespace ui {

/// Crater crusts and scattered soil: drawn right after the terrain.
void drawGroundMarks(Renderer2D& r, const game::Effects& fx, const game::Match& m);
/// Pieces in the air, smoke, flashes and splash rings: drawn over the scene.
void drawEffectsLayer(Renderer2D& r, const game::Effects& fx);
/// Miss notes, score pop-ups and hit markers.
void drawShotFeedback(Renderer2D& r, const game::Effects& fx);

} // namespace ui
