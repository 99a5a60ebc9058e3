#include "ui/game/aim_input.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ui {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

/// Aim commands accept [-180, 180] degrees (Match::apply).
double wrapDegrees(double a) {
    while (a > 180.0) a -= 360.0;
    while (a < -180.0) a += 360.0;
    return a;
}

/// Commands carry what the HUD shows: angles to 0.1 degree, speeds to 0.1 m/s, so a
/// hand-edited script and a recorded game read alike.
double round1(double v) { return std::round(v * 10.0) / 10.0; }

game::Command make(game::CommandKind kind, double number) {
    game::Command c;
    c.kind = kind;
    c.number = number;
    return c;
}

} // namespace

PendingAim aimFromDrag(phys::Vec2 pivotPx, phys::Vec2 pointerPx, double maxSpeedMps,
                       double fullPowerPixels) {
    const double dx = pointerPx.x - pivotPx.x, dy = pivotPx.y - pointerPx.y; // y up
    const double len = std::hypot(dx, dy);
    PendingAim a;
    a.angleDeg = round1(std::atan2(dy, dx) * kRadToDeg);
    a.speedMps = round1(std::min(1.0, len / fullPowerPixels) * maxSpeedMps);
    return a;
}

void AimInput::sync(const game::CannonState& cannon) {
    if (editing()) return;
    pending_ = {cannon.angleDeg, cannon.speedMps};
}

void AimInput::beginDrag(phys::Vec2 /*pivotPx*/, phys::Vec2 pointerPx, double /*maxSpeedMps*/) {
    // Nothing changes yet: a click is not a drag (a click in the sky would otherwise aim
    // there at full power).
    dragging_ = true;
    dragMoved_ = false;
    pressPx_ = pointerPx_ = pointerPx;
}

void AimInput::dragTo(phys::Vec2 pivotPx, phys::Vec2 pointerPx, double maxSpeedMps) {
    if (!dragging_) return;
    pointerPx_ = pointerPx;
    if (!dragMoved_ && length(pointerPx - pressPx_) < def_.dragStartPixels) return;
    dragMoved_ = true;
    pending_ = aimFromDrag(pivotPx, pointerPx, maxSpeedMps, def_.fullPowerPixels);
    dirty_ = true;
}

std::vector<game::Command> AimInput::endDrag(const game::CannonState& cannon) {
    if (!dragging_) return {};
    dragging_ = false;
    if (!dragMoved_) return {}; // a click: the aim as it was
    dragMoved_ = false;
    return commit(cannon);
}

void AimInput::step(int angleSteps, int powerSteps, bool fine, double maxSpeedMps) {
    const double k = fine ? 0.2 : 1.0;
    pending_.angleDeg = round1(wrapDegrees(pending_.angleDeg + angleSteps * k * def_.stepDeg));
    pending_.speedMps =
        std::clamp(round1(pending_.speedMps + powerSteps * k * def_.stepMps), 0.0, maxSpeedMps);
    dirty_ = true;
    heldSeconds_ = 0.0;
}

void AimInput::hold(double angleAxis, double powerAxis, double dt, double maxSpeedMps) {
    if (angleAxis == 0.0 && powerAxis == 0.0) return;
    heldSeconds_ += dt;
    const double repeating = heldSeconds_ - def_.repeatDelaySeconds;
    if (repeating <= 0.0) return; // the tap's step was all, so far
    // Steps a second, doubling as the keys stay down, up to the most rates.
    const double steps = def_.stepsPerSecond * std::exp2(repeating / def_.doublingSeconds);
    const double angleRate = std::min(def_.angleRate, steps * def_.stepDeg);
    const double powerRate = std::min(def_.powerRate, steps * def_.stepMps);
    pending_.angleDeg = wrapDegrees(pending_.angleDeg + angleAxis * angleRate * dt);
    pending_.speedMps =
        std::clamp(pending_.speedMps + powerAxis * powerRate * dt, 0.0, maxSpeedMps);
    dirty_ = true;
}

void AimInput::sweep(double angleAxis, double powerAxis, double dt, double maxSpeedMps) {
    if (angleAxis == 0.0 && powerAxis == 0.0) return;
    pending_.angleDeg = wrapDegrees(pending_.angleDeg + angleAxis * def_.angleRate * dt);
    pending_.speedMps =
        std::clamp(pending_.speedMps + powerAxis * def_.powerRate * dt, 0.0, maxSpeedMps);
    dirty_ = true;
}

void AimInput::stick(double x, double y) {
    if (std::hypot(x, y) < def_.stickDeadzone) return;
    pending_.angleDeg = round1(std::atan2(-y, x) * kRadToDeg);
    dirty_ = true;
}

void AimInput::startCharge() {
    if (!charge_) charge_ = 0.0;
}

void AimInput::updateCharge(double dt) {
    if (charge_) charge_ = std::min(1.0, *charge_ + dt / def_.chargeSeconds);
}

std::vector<game::Command> AimInput::releaseCharge(const game::CannonState& cannon) {
    if (!charge_) return {};
    if (tapped()) {
        charge_.reset();
        return fire(cannon);
    }
    pending_.speedMps = std::max(0.0, round1(*charge_ * cannon.def.maxSpeedMps));
    pending_.speedMps = std::min(pending_.speedMps, cannon.def.maxSpeedMps);
    charge_.reset();
    dirty_ = true;
    return fire(cannon);
}

std::vector<game::Command> AimInput::commit(const game::CannonState& cannon) {
    std::vector<game::Command> out;
    const double angle = round1(pending_.angleDeg);
    const double speed = std::clamp(round1(pending_.speedMps), 0.0, cannon.def.maxSpeedMps);
    if (angle != cannon.angleDeg) out.push_back(make(game::CommandKind::Aim, angle));
    if (speed != cannon.speedMps) out.push_back(make(game::CommandKind::Power, speed));
    pending_ = {angle, speed};
    dirty_ = false;
    return out;
}

std::vector<game::Command> AimInput::fire(const game::CannonState& cannon) {
    dragging_ = false;
    std::vector<game::Command> out = commit(cannon);
    out.push_back(make(game::CommandKind::Fire, 0.0));
    return out;
}

std::optional<game::Command> AimInput::select(const game::CannonState& cannon, std::size_t index) {
    if (index >= cannon.def.projectiles.size()) return std::nullopt;
    game::Command c;
    c.kind = game::CommandKind::Select;
    c.text = cannon.def.projectiles[index];
    return c;
}

std::optional<game::Command> AimInput::selectNext(const game::CannonState& cannon) {
    if (cannon.def.projectiles.empty()) return std::nullopt;
    return select(cannon, (cannon.projectile + 1) % cannon.def.projectiles.size());
}

game::Command AimInput::endTurn() {
    game::Command c;
    c.kind = game::CommandKind::EndTurn;
    return c;
}

} // namespace ui
