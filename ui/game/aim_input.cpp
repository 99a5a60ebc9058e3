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

void AimInput::beginDrag(phys::Vec2 pivotPx, phys::Vec2 pointerPx, double maxSpeedMps) {
    dragging_ = true;
    dragTo(pivotPx, pointerPx, maxSpeedMps);
}

void AimInput::dragTo(phys::Vec2 pivotPx, phys::Vec2 pointerPx, double maxSpeedMps) {
    if (!dragging_) return;
    pending_ = aimFromDrag(pivotPx, pointerPx, maxSpeedMps, def_.fullPowerPixels);
    dirty_ = true;
}

std::vector<game::Command> AimInput::endDrag(const game::CannonState& cannon) {
    if (!dragging_) return {};
    dragging_ = false;
    return commit(cannon);
}

void AimInput::hold(double angleAxis, double powerAxis, double dt, double maxSpeedMps) {
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
