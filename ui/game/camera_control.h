// The game screen's camera: the level's framing (home) kept clear of the panels along the
// bottom, the rig that follows the shell and frames the impact (game/effects/camera_rig.h),
// the player's own zoom and pan, and the shake of blasts. A view of the match: nothing
// here changes it.
#pragma once

#include "game/effects/camera_rig.h"
#include "game/effects/effects.h"
#include "game/match.h"
#include "ui/render/camera.h"
#include "ui/render/pixel_rect.h"

#include <optional>

union SDL_Event;

namespace ui {

class CameraControl {
  public:
    Camera& camera() { return camera_; }
    const Camera& camera() const { return camera_; }

    /// The level's framing in a view of w x h, and the rig's home; the rig follows from
    /// the match's tick on.
    void frameLevel(const game::Match& m, int width, int height);
    /// The panel along the bottom (the Match panel, or the replay viewer's: where it was
    /// drawn open, openWindowRect) covers part of the screen: the follow camera frames
    /// shots above it, and home moves so nothing to aim at stands under it. Called once a
    /// frame while one is drawn; `follow` is whether the camera follows the shell.
    void keepClearOfPanels(const game::Match& m, const std::optional<PixelRect>& panel,
                           int width, int height, bool follow);
    /// Panels stand along the right edge, over its rightmost `fraction` of the width (the
    /// lab's, open): home and the follow camera frame the level left of them. Called once a
    /// frame, before keepClearOfPanels().
    void keepClearOfTheRight(double fraction) { coveredRightNow_ = fraction; }
    /// Once a frame: the rig watches the match, and the camera goes where it points
    /// while `follow` is on and the player has not moved the view.
    void followShot(const game::Match& m, bool follow);
    /// The camera follows the shell: the setting is on and the player has not panned.
    bool following(bool followSetting) const { return followSetting && !moved_; }
    /// The camera drawn with: the view shaken by blasts, when `shakeOn`.
    Camera shaken(const game::Effects& effects, bool shakeOn) const;

    /// The wheel zooms (about the pointer, or about the centre while following), a
    /// right or middle drag pans. `pixelsPerPoint`: window points to framebuffer pixels.
    void event(const SDL_Event& e, phys::Vec2 pixelsPerPoint, bool followSetting);

    /// The player moved the view away from the framing (panned or zoomed it).
    bool moved() const { return moved_; }
    /// The view is still: home, or where the player put it (not following, holding on an
    /// impact or gliding back).
    bool still() const { return moved_ || rig_.phase() == game::CameraRig::Phase::Home; }
    /// Home again (Home, a new level): framed anew, following again.
    void forgetMoves() { moved_ = false; }
    bool panning() const { return panning_; }
    void stopPanning() { panning_ = false; }

  private:
    Camera camera_;
    game::CameraRig rig_; ///< follows the shell, frames the impact, returns
    /// How much of the bottom the panels there covered when the level was last framed (a
    /// fraction of the height), and for how many more frames home jumps to a new framing
    /// rather than gliding: ImGui sizes a panel over its first two frames, and a level that
    /// just opened should not be seen moving into place.
    double coveredBottom_ = 0.0;
    double coveredRight_ = 0.0, coveredRightNow_ = 0.0; ///< framed with, asked for
    int homeJumpFrames_ = 3;
    bool moved_ = false;
    bool panning_ = false;
};

} // namespace ui
