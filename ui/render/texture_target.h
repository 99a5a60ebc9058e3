// A picture drawn by the renderer into a texture of its own, to be shown by ImGui
// (ImGui::Image takes the texture's name): the level select's thumbnails, the lessons'
// pictures. Drawn once and kept; multisampled like the main frame, then resolved into it.
#pragma once

#include "ui/render/render_target.h"

namespace ui {

class TextureTarget {
  public:
    TextureTarget() = default;
    ~TextureTarget();
    TextureTarget(const TextureTarget&) = delete;
    TextureTarget& operator=(const TextureTarget&) = delete;

    /// Makes the texture w x h (RGBA). False when the driver refuses the framebuffer.
    bool create(int width, int height, int samples);
    /// Binds it for drawing (the multisampled buffer, when there is one).
    void bind() const;
    /// Resolves what was drawn into the texture and binds `restoreFbo` for drawing again.
    void finish(unsigned restoreFbo) const;

    unsigned texture() const { return texture_; }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    unsigned fbo_ = 0;
    unsigned texture_ = 0;
    int width_ = 0, height_ = 0;
    MultisampleTarget msaa_;
};

} // namespace ui
