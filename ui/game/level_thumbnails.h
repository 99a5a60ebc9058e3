// The level select's pictures of the levels: each level drawn by the game's own renderer
// as it opens (its home framing, no HUD) into a small texture, once, the first time its
// tile is shown, and kept while the menu lives.
#pragma once

#include "ui/game/match_view.h"
#include "ui/render/renderer2d.h"
#include "ui/render/texture_target.h"

#include <map>
#include <memory>
#include <string>

namespace ui {

class LevelThumbnails {
  public:
    /// The picture of the level in `file`, width x height px: drawn now if it is new
    /// (then `restoreFbo` is bound for drawing again). Null when the level does not load
    /// or the driver refuses the texture.
    const TextureTarget* picture(const std::string& file, int width, int height, unsigned restoreFbo);

  private:
    std::map<std::string, std::unique_ptr<TextureTarget>> pictures_;
    std::unique_ptr<Renderer2D> renderer_; ///< made at the first picture (it needs GL)
    MatchView view_;
};

} // namespace ui
