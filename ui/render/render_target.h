// An offscreen multisampled colour buffer the world is drawn into and then resolved
// (averaged) into the context's framebuffer, so edges are smooth on every context:
// OSMesa and EGL have no multisampled default framebuffer, and a window may not either.
// ImGui draws afterwards straight into the resolved picture (its text is already
// anti-aliased by its font texture).
#pragma once

namespace ui {

class MultisampleTarget {
  public:
    MultisampleTarget() = default;
    ~MultisampleTarget();
    MultisampleTarget(const MultisampleTarget&) = delete;
    MultisampleTarget& operator=(const MultisampleTarget&) = delete;

    /// (Re)allocates for this size and sample count; samples <= 1 disables it. Returns
    /// false (and stays disabled) when the driver refuses the combination.
    bool resize(int width, int height, int samples);
    bool enabled() const { return fbo_ != 0; }
    int samples() const { return samples_; }

    /// Binds the multisampled buffer for drawing (or `fallbackFbo` when disabled).
    void bind(unsigned fallbackFbo) const;
    /// Averages the samples into `destinationFbo` and leaves it bound for drawing.
    void resolveInto(unsigned destinationFbo) const;

  private:
    void release();
    unsigned fbo_ = 0;
    unsigned colour_ = 0;
    int width_ = 0;
    int height_ = 0;
    int samples_ = 0;
};

} // namespace ui
