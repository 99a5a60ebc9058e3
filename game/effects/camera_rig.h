// The camera as a view of the match: it rests on the level's framing ("home"), follows
// the shell smoothly while it flies (framing it with the targets still standing, so the
// view closes in as the shell nears them), frames the point of impact for a moment, then
// returns home. It holds a centre and a zoom in world units only (the window turns them
// into pixels), moves by ticks so tests can drive it, and never touches the match.
//
// Smoothing is exponential: each tick moves the view a fraction 1 - exp(-dt / tau) of the
// way to where it should be, so it converges without overshoot at any frame rate, and
// the zoom moves the same way in log space (equal steps feel equal zooming in and out).
#pragma once

#include "physics/vec2.h"

#include <cstdint>

namespace game {

class Match;

struct CameraRigDef {
    double followSeconds = 0.35;   ///< tau while following the shell, s
    double returnSeconds = 0.6;    ///< tau going back home, s
    double holdSeconds = 1.2;      ///< how long the impact stays framed, s
    double leadSeconds = 0.3;      ///< the view looks ahead along the shell's velocity, s
    double followMarginPx = 110.0; ///< room around the shell and the targets it frames, px
    double impactZoom =
        2.2; ///< zoom on the impact (and the most while following), relative to home
};

class CameraRig {
  public:
    enum class Phase { Home, Following, Holding, Returning };

    explicit CameraRig(const CameraRigDef& def = {}) : def_(def) {}

    /// Where the view rests: the level's framing (centre, m; zoom, px/m; the view's
    /// height, px). Jumps there.
    void setHome(phys::Vec2 center, double pixelsPerMetre, int viewWidthPx = 1280,
                 int viewHeightPx = 720);
    /// After each tick of `match`, or once a frame: it moves by the ticks since the last
    /// call.
    void tick(const Match& match);
    /// Moves home to a new framing (the window's panels changed): the view glides there
    /// as it returns, or jumps with `jump`. The player's wheel zoom is kept.
    void moveHome(phys::Vec2 center, double pixelsPerMetre, bool jump);
    /// The player's wheel: multiplies every zoom from now on (home's too).
    void zoomBy(double factor);
    /// The lowest `fraction` of the view is covered (by the window's panels along its
    /// bottom): the shell, the targets and the impact are framed in the view above it.
    /// Home is the level's framing, which keeps its own soil band under them.
    void setCoveredBottom(double fraction);
    /// The rightmost `fraction` of the view is covered (by panels along its right edge):
    /// the shell, the targets and the impact are framed in the view left of it.
    void setCoveredRight(double fraction);

    phys::Vec2 center() const { return center_; }
    double pixelsPerMetre() const { return zoom_; }
    Phase phase() const { return phase_; }
    /// The point being framed now (the shell ahead, the impact, home).
    phys::Vec2 aim() const { return aim_; }

  private:
    void approach(phys::Vec2 target, double zoom, double tau, double dt);
    /// How far the middle of the open picture (above the covered bottom) lies above the
    /// view's centre at `zoom`, m.
    double openCentreAbove(double zoom) const {
        return 0.5 * coveredBottom_ * viewHeightPx_ / zoom;
    }
    /// How far the middle of the open picture (left of the covered right) lies left of
    /// the view's centre at `zoom`, m.
    double openCentreLeft(double zoom) const { return 0.5 * coveredRight_ * viewWidthPx_ / zoom; }

    CameraRigDef def_;
    Phase phase_ = Phase::Home;
    phys::Vec2 homeCenter_, center_, aim_;
    double homeZoom_ = 20.0, zoom_ = 20.0, userZoom_ = 1.0;
    std::uint64_t heldShot_ = ~0ull; ///< tick of the shot's end being framed
    bool shellSeen_ = false;
    std::uint64_t lastTick_ = 0;
    bool started_ = false;
    int viewWidthPx_ = 1280, viewHeightPx_ = 720;
    double coveredBottom_ = 0.0; ///< fraction of the view's height
    double coveredRight_ = 0.0;  ///< fraction of the view's width
    phys::Vec2 lastShell_;
};

} // namespace game
