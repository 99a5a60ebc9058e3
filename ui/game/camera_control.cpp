#include "ui/game/camera_control.h"

#include "ui/game/level_camera.h"
#include "ui/render/design_canvas.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {

/// The top band the HUD's boxes stand in, a fraction of the height.
double coveredTop(int width, int height) {
    return height > 0 ? kHudTopBand * hudScale(width, height) / height : 0.0;
}

} // namespace

void CameraControl::frameLevel(const game::Match& m, int width, int height) {
    camera_ = levelCameraLeftOf(m, width, height, coveredRight_, coveredBottom_, coveredTop(width, height));
    rig_.setHome(camera_.center, camera_.pixelsPerMetre, camera_.width, camera_.height);
    rig_.tick(m); // from this tick on
    homeJumpFrames_ = 3;
}

void CameraControl::keepClearOfPanels(const game::Match& m, const std::optional<PixelRect>& panel,
                                      int w, int h, bool follow) {
    const double covered = coveredBottom(panel.value_or(PixelRect{}), w, h);
    const bool mayJump = homeJumpFrames_ > 0;
    homeJumpFrames_ = std::max(0, homeJumpFrames_ - 1); // called once a frame
    rig_.setCoveredBottom(covered);
    rig_.setCoveredRight(coveredRightNow_);
    // A line more or less in the panel (a hint's, a duel's) moves home; a pixel does not.
    if (std::abs(covered - coveredBottom_) < 0.005 && std::abs(coveredRightNow_ - coveredRight_) < 0.005)
        return;
    coveredBottom_ = covered;
    coveredRight_ = coveredRightNow_;
    const Camera home = levelCameraLeftOf(m, w, h, coveredRight_, coveredBottom_, coveredTop(w, h));
    rig_.moveHome(home.center, home.pixelsPerMetre, mayJump);
    if (following(follow) && rig_.phase() == game::CameraRig::Phase::Home) {
        camera_.center = rig_.center();
        camera_.pixelsPerMetre = rig_.pixelsPerMetre();
    }
}

void CameraControl::followShot(const game::Match& m, bool follow) {
    rig_.tick(m);
    if (!following(follow)) return;
    camera_.center = rig_.center();
    camera_.pixelsPerMetre = rig_.pixelsPerMetre();
}

Camera CameraControl::shaken(const game::Effects& effects, bool shakeOn) const {
    Camera c = camera_;
    const double shake = effects.shake();
    if (!shakeOn || shake <= 0.0) return c;
    // Up to 9 px, in a pattern that depends on simulated time only (two incommensurate
    // frequencies), so a replay shakes the same way every time it is watched.
    const double t = effects.time();
    const double px = 9.0 * shake;
    c.center += phys::Vec2{std::sin(97.0 * t), std::cos(71.0 * t)} * c.metres(px);
    return c;
}

void CameraControl::event(const SDL_Event& e, phys::Vec2 pixelsPerPoint, bool followSetting) {
    auto pixels = [&](int x, int y) { return phys::Vec2{x * pixelsPerPoint.x, y * pixelsPerPoint.y}; };
    if (e.type == SDL_MOUSEWHEEL && e.wheel.y != 0) {
        int mx = 0, my = 0;
        SDL_GetMouseState(&mx, &my);
        const double factor = e.wheel.y > 0 ? 1.15 : 1.0 / 1.15;
        if (following(followSetting)) { // the followed view zooms about its centre, and keeps following
            rig_.zoomBy(factor);
            camera_.pixelsPerMetre *= factor;
        } else {
            camera_.zoomAt(pixels(mx, my), factor);
            moved_ = true;
        }
    } else if (e.type == SDL_MOUSEBUTTONDOWN && e.button.button != SDL_BUTTON_LEFT) {
        panning_ = true;
    } else if (e.type == SDL_MOUSEBUTTONUP && e.button.button != SDL_BUTTON_LEFT) {
        panning_ = false;
    } else if (e.type == SDL_MOUSEMOTION && panning_) {
        camera_.panPixels(pixels(e.motion.xrel, e.motion.yrel));
        moved_ = true;
    }
}

} // namespace ui
