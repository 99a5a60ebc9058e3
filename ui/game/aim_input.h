// Player gestures -> commands. The aim being edited (mouse drag, held arrow keys, a
// game controller's stick, a Space charge) is kept here as a pending aim and sent as
// `aim` / `power` commands only when it settles (drag released, key released, fire),
// so a replay records what the player chose rather than every mouse motion, and the
// match itself only ever changes through Session::submit.
//
// No SDL here: positions are pixels, times are wall seconds of the UI (they shape the
// gesture, never the simulation; the commands are stamped with ticks by the session).
// That keeps the mapping testable without a window (tests/ui/aim_input_test.cpp).
#pragma once

#include "game/command.h"
#include "game/match.h"
#include "ui/game/match_view.h"

#include <optional>
#include <vector>

namespace ui {

struct AimInputDef {
    double fullPowerPixels = 260.0; ///< drag length from the cannon that means full power, px
    double chargeSeconds = 1.5;     ///< holding Space this long charges from 0 to full power, s
    /// Space released sooner than this is a tap, not a charge: it fires at the power set
    /// (by a drag, say), as Enter does, instead of at the few per cent charged, s.
    double tapSeconds = 0.2;
    /// A key tap steps the aim by this much (a fifth of it with Shift): a tap always does
    /// the same, whatever the frame rate, deg and m/s.
    double stepDeg = 0.5;
    double stepMps = 0.5;
    /// Held past this, the key repeats, slowly at first and faster the longer it is held:
    /// from `stepsPerSecond` steps a second, doubling every `doublingSeconds`, up to the
    /// rates below (x0.2 with Shift), s.
    double repeatDelaySeconds = 0.35;
    double stepsPerSecond = 8.0;
    double doublingSeconds = 0.5;
    double angleRate = 40.0;        ///< deg/s at most while an arrow key is held
    double powerRate = 15.0;        ///< m/s per s at most while up/down is held
    /// A press that the pointer leaves by less than this is a click, not a drag: it leaves
    /// the aim alone, px.
    double dragStartPixels = 6.0;
    double stickDeadzone = 0.3;     ///< stick deflection (0..1) under which it is ignored
};

/// The aim a drag from the cannon's pivot to the pointer gives: direction = angle
/// (screen y runs down, so it is flipped), length = power (full at `fullPowerPixels`,
/// clamped to the cannon's maximum).
PendingAim aimFromDrag(phys::Vec2 pivotPx, phys::Vec2 pointerPx, double maxSpeedMps,
                       double fullPowerPixels);

class AimInput {
  public:
    explicit AimInput(const AimInputDef& def = {}) : def_(def) {}

    /// Adopts the cannon's committed aim unless an edit is in progress (call every frame:
    /// a turn change or a command from elsewhere then shows at once).
    void sync(const game::CannonState& cannon);
    const PendingAim& pending() const { return pending_; }
    /// True while the pending aim differs from what was last committed.
    bool editing() const { return dirty_ || dragging_ || charge_.has_value(); }

    // Mouse: press starts, motion past dragStartPixels aims from the pointer (the rubber
    // band), release commits; a press released where it began leaves the aim alone.
    void beginDrag(phys::Vec2 pivotPx, phys::Vec2 pointerPx, double maxSpeedMps);
    void dragTo(phys::Vec2 pivotPx, phys::Vec2 pointerPx, double maxSpeedMps);
    std::vector<game::Command> endDrag(const game::CannonState& cannon);
    bool dragging() const { return dragging_; }
    /// Where the pointer pulls the aim, px, while a drag is aiming (the rubber band's end).
    std::optional<phys::Vec2> rubberBand() const {
        return dragging_ && dragMoved_ ? std::optional(pointerPx_) : std::nullopt;
    }

    /// A key tap: the angle by `angleSteps` and the power by `powerSteps` steps (stepDeg,
    /// stepMps; a fifth with `fine`). Commit with commit() when the keys are released.
    void step(int angleSteps, int powerSteps, bool fine, double maxSpeedMps);
    /// Held keys or a controller: `angleAxis` and `powerAxis` in -1..1 (0.2 is Shift's
    /// fine) for `dt` seconds more of holding; past the repeat delay the aim moves, faster
    /// the longer they are held.
    void hold(double angleAxis, double powerAxis, double dt, double maxSpeedMps);
    /// An analog control (a controller's trigger or stick): the aim moves at once, at
    /// `angleAxis` x angleRate and `powerAxis` x powerRate, for `dt` seconds.
    void sweep(double angleAxis, double powerAxis, double dt, double maxSpeedMps);
    /// The keys are let go: the next hold starts slow again.
    void releaseHold() { heldSeconds_ = 0.0; }
    /// A controller stick (x right, y down as SDL reports it, -1..1): beyond the dead
    /// zone its direction is the angle.
    void stick(double x, double y);

    /// Space pressed: the power starts from zero and rises while held.
    void startCharge();
    void updateCharge(double dt);
    bool charging() const { return charge_.has_value(); }
    /// 0..1 of full power, while charging and past a tap (before that the power set is
    /// what a release fires).
    std::optional<double> chargeFraction() const {
        return charge_ && !tapped() ? charge_ : std::nullopt;
    }
    /// Space released: power = charge x maximum, then aim, power and fire; after a tap,
    /// aim, the power set and fire.
    std::vector<game::Command> releaseCharge(const game::CannonState& cannon);
    /// Drops a charge without firing (Esc, or the turn passed).
    void cancelCharge() { charge_.reset(); }

    /// The aim and power commands that bring the cannon to the pending aim (none when
    /// they already match).
    std::vector<game::Command> commit(const game::CannonState& cannon);
    /// commit() then fire.
    std::vector<game::Command> fire(const game::CannonState& cannon);

    /// The select command for projectile `index` (0-based) of the cannon, if it has one.
    static std::optional<game::Command> select(const game::CannonState& cannon, std::size_t index);
    /// The select command for the cannon's next projectile (after the last, the first).
    static std::optional<game::Command> selectNext(const game::CannonState& cannon);
    /// The end_turn command.
    static game::Command endTurn();

  private:
    /// Space has been held for less than a tap.
    bool tapped() const { return charge_ && *charge_ * def_.chargeSeconds < def_.tapSeconds; }

    AimInputDef def_;
    PendingAim pending_;
    bool dirty_ = false;
    bool dragging_ = false;
    bool dragMoved_ = false;           ///< the pointer left the press: the drag aims
    phys::Vec2 pressPx_, pointerPx_;   ///< where the press began, where the pointer is
    double heldSeconds_ = 0.0;         ///< how long the keys have been held
    std::optional<double> charge_;
};

} // namespace ui
