#include "game/effects/camera_rig.h"

#include "game/match.h"

#include <cmath>

namespace game {

using phys::Vec2;

void CameraRig::setHome(Vec2 center, double pixelsPerMetre) {
    homeCenter_ = center_ = aim_ = center;
    homeZoom_ = zoom_ = pixelsPerMetre;
    userZoom_ = 1.0;
    phase_ = Phase::Home;
}

void CameraRig::zoomBy(double factor) {
    userZoom_ *= factor;
    zoom_ *= factor;
}

void CameraRig::approach(Vec2 target, double zoom, double tau, double dt) {
    const double k = 1.0 - std::exp(-dt / tau);
    aim_ = target;
    center_ += (target - center_) * k;
    zoom_ = std::exp(std::log(zoom_) + (std::log(zoom) - std::log(zoom_)) * k);
}

void CameraRig::tick(const Match& m) {
    const double dt = m.world().def().tickSeconds;
    const double home = homeZoom_ * userZoom_;
    const auto shell = m.shell();
    if (shell) {
        const phys::ParticleSet& ps = m.world().particles;
        lastShell_ = ps.position(*shell);
        phase_ = Phase::Following;
        held_ = 0.0;
        approach(lastShell_ + ps.velocity(*shell) * def_.leadSeconds, home * def_.followZoom,
                 def_.followSeconds, dt);
    } else if (shellWasFlying_) {
        phase_ = Phase::Holding; // the shell came down (or burst) where it was last seen
        held_ = 0.0;
    }
    shellWasFlying_ = shell.has_value();
    if (phase_ == Phase::Holding) {
        // The impact low in the picture, so what it threw up is in view.
        const double zoom = home * def_.impactZoom;
        const double visibleHeight = 720.0 / zoom; // m at the design height of 720 px
        approach(lastShell_ + Vec2{0.0, 0.15 * visibleHeight}, zoom, def_.followSeconds, dt);
        held_ += dt;
        if (held_ >= def_.holdSeconds) phase_ = Phase::Returning;
    } else if (phase_ == Phase::Returning || phase_ == Phase::Home) {
        approach(homeCenter_, home, def_.returnSeconds, dt);
        if (length(center_ - homeCenter_) < 1e-3 && std::abs(zoom_ / home - 1.0) < 1e-6)
            phase_ = Phase::Home;
    }
    lastTick_ = m.tick();
}

} // namespace game
