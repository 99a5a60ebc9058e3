// The heads-up display over the field: a few small boxes, each placed where it covers
// nothing the player must see (ScreenLayout's rule): the score and shots (or both players'
// hit points), the wind, the aim readout with the projectile chosen, a banner ("PAUSED",
// "the computer is aiming..."), a refused command, and the card at a match's end. Each box
// has places it may stand, in order of preference (the score at the top left, else the top
// right, ...); it keeps its place while that stays clear, and stands aside (or, if no place
// is clear, is not drawn) when the camera brings a target, a cannon or the shell under it.
// Laid out on the 1280x720 design canvas and scaled to the picture (design_canvas.h).
#pragma once

#include "game/effects/effects.h"
#include "game/match.h"
#include "ui/render/pixel_rect.h"
#include "ui/render/renderer2d.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ui {

struct MatchViewOptions;
struct PendingAim;
struct ScreenLayout;

class Hud {
  public:
    /// Draws the HUD of `match` through `r` (its camera is the screen's), the aim shown
    /// being `aim`. With `options.layout`, each box is placed clear of the objects already
    /// in it and of the boxes before it, and is added to it as an overlay.
    void draw(Renderer2D& r, const game::Match& match, const MatchViewOptions& options,
              const PendingAim& aim, const game::Effects& effects);
    /// Forgets where the boxes stood (a new match).
    void reset() { places_.clear(); }

  private:
    void drawRulesAndCard(Renderer2D& r, const game::Match& match, const MatchViewOptions& options);
    /// Where a box of `name` goes among `candidates` (design pixels): the place it had if
    /// still clear, else the first clear one; none when every place covers something.
    std::optional<PixelRect> place(const std::string& name, const std::vector<PixelRect>& candidates,
                                   const MatchViewOptions& options, double scale, double width,
                                   double height);

    std::map<std::string, std::size_t> places_; ///< each box's place last frame
};

} // namespace ui
