#include "game/effects/camera_rig.h"

#include "game/match.h"

#include "game/effects/shot_feedback.h"
#include "game/standing_targets.h"

#include <algorithm>
#include <cmath>

namespace game {

using phys::Vec2;

void CameraRig::setHome(Vec2 center, double pixelsPerMetre, int viewWidthPx, int viewHeightPx) {
    viewWidthPx_ = viewWidthPx;
    viewHeightPx_ = viewHeightPx;
    homeCenter_ = center_ = aim_ = center;
    homeZoom_ = zoom_ = pixelsPerMetre;
    userZoom_ = 1.0;
    phase_ = Phase::Home;
}

void CameraRig::moveHome(Vec2 center, double pixelsPerMetre, bool jump) {
    homeCenter_ = center;
    homeZoom_ = pixelsPerMetre;
    if (phase_ != Phase::Home) return; // it goes to the new home once the shot is over
    if (jump) {
        center_ = aim_ = center;
        zoom_ = pixelsPerMetre * userZoom_;
    } else {
        phase_ = Phase::Returning;
    }
}

void CameraRig::zoomBy(double factor) {
    userZoom_ *= factor;
    zoom_ *= factor;
}

void CameraRig::setCoveredBottom(double fraction) {
    // At most half: what is left must still hold a shot worth following.
    coveredBottom_ = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 0.5) : 0.0;
}

void CameraRig::setCoveredRight(double fraction) {
    coveredRight_ = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 0.5) : 0.0;
}

void CameraRig::approach(Vec2 target, double zoom, double tau, double dt) {
    const double k = 1.0 - std::exp(-dt / tau);
    aim_ = target;
    center_ += (target - center_) * k;
    zoom_ = std::exp(std::log(zoom_) + (std::log(zoom) - std::log(zoom_)) * k);
}

void CameraRig::tick(const Match& m) {
    // Every tick since the last call at once: k = 1 - exp(-n dt / tau) is n single ticks'
    // approach composed, so a caller once per frame sees the same path as one per tick.
    // A first call, or a tick that went back (a rewind, a seek), counts as one.
    const std::uint64_t n = started_ && m.tick() >= lastTick_ ? m.tick() - lastTick_ : 1;
    started_ = true;
    lastTick_ = m.tick();
    if (n == 0) return;
    const double dt = static_cast<double>(n) * m.world().def().tickSeconds;
    const double home = homeZoom_ * userZoom_;
    const auto shell = m.shell();
    if (shell) {
        const phys::ParticleSet& ps = m.world().particles;
        lastShell_ = ps.position(*shell);
        shellSeen_ = true;
        phase_ = Phase::Following;
        // Frame the shell (a little ahead of it) together with the targets still standing:
        // the view closes in as the shell nears them, from home's zoom up to the impact's.
        const Vec2 ahead = lastShell_ + ps.velocity(*shell) * def_.leadSeconds;
        Vec2 lo{std::min(ahead.x, lastShell_.x), std::min(ahead.y, lastShell_.y)};
        Vec2 hi{std::max(ahead.x, lastShell_.x), std::max(ahead.y, lastShell_.y)};
        for (const StandingTarget& t : standingTargets(m, m.currentPlayer())) {
            lo = {std::min(lo.x, t.where.x - t.reach), std::min(lo.y, t.where.y - t.reach)};
            hi = {std::max(hi.x, t.where.x + t.reach), std::max(hi.y, t.where.y + t.reach)};
        }
        const double margin = def_.followMarginPx;
        const double openPx = viewHeightPx_ * (1.0 - coveredBottom_);
        const double openWidthPx = viewWidthPx_ * (1.0 - coveredRight_);
        const double fit = std::min((openWidthPx - 2.0 * margin) / std::max(1e-6, hi.x - lo.x),
                                    (openPx - 2.0 * margin) / std::max(1e-6, hi.y - lo.y));
        const double zoom = std::clamp(fit, home, home * def_.impactZoom);
        // The lowest of them a quarter of the way up the open picture (the ground low, as
        // at home), unless the shell needs the view higher to stay in it.
        const double visible = openPx / zoom, m = margin / zoom;
        const double y = std::max(lo.y + 0.25 * visible, hi.y + m - 0.5 * visible);
        approach({0.5 * (lo.x + hi.x) + openCentreLeft(zoom), y - openCentreAbove(zoom)}, zoom,
                 def_.followSeconds, dt);
        return;
    }
    // The shot's end from the match's events (not from having watched it fall: a viewer
    // that skips ahead still frames the impact): where it burst, else where it was seen.
    const double tick = m.world().def().tickSeconds;
    for (auto e = m.events().rbegin(); e != m.events().rend(); ++e) {
        if (static_cast<double>(m.tick() - e->tick) * tick > def_.holdSeconds) break;
        if (e->kind != EventKind::ShotOver) continue;
        if (e->tick == heldShot_) break;
        heldShot_ = e->tick;
        bool found = shellSeen_;
        for (auto b = e; b != m.events().rend() && b->tick == e->tick; ++b)
            if (b->kind == EventKind::Burst) lastShell_ = b->where, found = true;
        if (found) phase_ = Phase::Holding;
        break;
    }
    shellSeen_ = false;
    if (phase_ == Phase::Following) phase_ = Phase::Returning; // gone without a shot's end
    if (phase_ == Phase::Holding) {
        // The impact low in the open picture, so what it threw up is in view.
        const double zoom = home * def_.impactZoom;
        const double visibleHeight = viewHeightPx_ * (1.0 - coveredBottom_) / zoom; // m
        approach(lastShell_ + Vec2{openCentreLeft(zoom), 0.15 * visibleHeight - openCentreAbove(zoom)},
                 zoom, def_.followSeconds, dt);
        if (static_cast<double>(m.tick() - heldShot_) * tick >= def_.holdSeconds)
            phase_ = Phase::Returning;
    } else if (phase_ == Phase::Returning || phase_ == Phase::Home) {
        approach(homeCenter_, home, def_.returnSeconds, dt);
        if (length(center_ - homeCenter_) < 1e-3 && std::abs(zoom_ / home - 1.0) < 1e-6)
            phase_ = Phase::Home;
    }
}

} // namespace game
