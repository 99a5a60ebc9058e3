// Input -> commands without a window: a drag from the cannon, held keys, a Space charge,
// projectile keys and the physics panel all become the commands a replay records.
#include "game/files/text_file.h"
#include "game/level.h"
#include "game/match.h"
#include "game/session.h"
#include "ui/game/aim_input.h"
#include "ui/game/player_settings.h"
#include "ui/game/settings_commands.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace {

using game::Command;
using game::CommandKind;

std::string sourceDir() {
    return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path().string();
}

game::CannonState cannon(double angle = 45.0, double speed = 30.0, double maxSpeed = 60.0) {
    game::CannonState c;
    c.def.maxSpeedMps = maxSpeed;
    c.def.projectiles = {"cannonball", "golf-ball", "tennis-ball"};
    c.angleDeg = angle;
    c.speedMps = speed;
    return c;
}

TEST(AimFromDrag, DirectionIsTheAngleAndLengthIsThePower) {
    // Pivot at (100, 500) px; pointer 130 px right and 130 px up (screen y runs down):
    // 45 degrees, half of the 260 px that mean full power.
    const double d = 130.0 / std::sqrt(2.0);
    const ui::PendingAim a = ui::aimFromDrag({100, 500}, {100 + d, 500 - d}, 60.0, 260.0);
    EXPECT_NEAR(a.angleDeg, 45.0, 0.05);
    EXPECT_NEAR(a.speedMps, 30.0, 0.05);
    // Straight left and far: 180 degrees, clamped to full power.
    const ui::PendingAim b = ui::aimFromDrag({100, 500}, {-900, 500}, 60.0, 260.0);
    EXPECT_DOUBLE_EQ(b.angleDeg, 180.0);
    EXPECT_DOUBLE_EQ(b.speedMps, 60.0);
}

TEST(AimInput, DragGivesAimAndPowerCommandsOnRelease) {
    ui::AimInput in;
    const game::CannonState c = cannon();
    in.sync(c);
    in.beginDrag({200, 400}, {200, 400}, c.def.maxSpeedMps);
    in.dragTo({200, 400}, {200 + 104, 400 - 180}, c.def.maxSpeedMps); // 60 deg, 207.8 px
    EXPECT_TRUE(in.editing());
    const std::vector<Command> cmds = in.endDrag(c);
    ASSERT_EQ(cmds.size(), 2u);
    EXPECT_EQ(cmds[0].kind, CommandKind::Aim);
    EXPECT_NEAR(cmds[0].number, 60.0, 0.05);
    EXPECT_EQ(cmds[1].kind, CommandKind::Power);
    EXPECT_NEAR(cmds[1].number, 60.0 * std::hypot(104.0, 180.0) / 260.0, 0.05);
    EXPECT_FALSE(in.editing());
}

TEST(AimInput, UnchangedAimSendsNothingAndFireSendsFire) {
    ui::AimInput in;
    const game::CannonState c = cannon(30.0, 25.0);
    in.sync(c);
    EXPECT_TRUE(in.commit(c).empty());
    const auto fire = in.fire(c);
    ASSERT_EQ(fire.size(), 1u);
    EXPECT_EQ(fire[0].kind, CommandKind::Fire);
}

// A tap of an arrow key steps the aim by the same amount every time, whatever the frame
// rate: 0.5 deg or 0.5 m/s, a fifth of it with Shift.
TEST(AimInput, ATapStepsAFixedAmount) {
    ui::AimInput in;
    const game::CannonState c = cannon(45.0, 30.0);
    in.sync(c);
    in.step(1, 0, false, c.def.maxSpeedMps);
    EXPECT_DOUBLE_EQ(in.pending().angleDeg, 45.5);
    in.step(0, -1, false, c.def.maxSpeedMps);
    EXPECT_DOUBLE_EQ(in.pending().speedMps, 29.5);
    in.step(-1, 1, true, c.def.maxSpeedMps);
    EXPECT_DOUBLE_EQ(in.pending().angleDeg, 45.4);
    EXPECT_DOUBLE_EQ(in.pending().speedMps, 29.6);
    const auto cmds = in.commit(c);
    ASSERT_EQ(cmds.size(), 2u);
    EXPECT_DOUBLE_EQ(cmds[0].number, 45.4);
    EXPECT_DOUBLE_EQ(cmds[1].number, 29.6);
}

// Held, the key repeats after a delay, slowly at first and faster the longer it is
// held, up to 40 deg/s: a frame's move grows with the time held, and reaches the most.
TEST(AimInput, HeldKeysRepeatAfterADelayFasterTheLonger) {
    ui::AimInputDef def; // 0.35 s delay; 8 steps/s doubling every 0.5 s; 40 deg/s at most
    ui::AimInput in(def);
    const game::CannonState c = cannon(45.0, 30.0);
    in.sync(c);
    const double dt = 1.0 / 60.0;
    for (int i = 0; i < 20; ++i) in.hold(1.0, 0.0, dt, c.def.maxSpeedMps); // 0.33 s
    EXPECT_DOUBLE_EQ(in.pending().angleDeg, 45.0) << "within the delay, the tap's step is all";
    double before = in.pending().angleDeg, lastMove = 0.0;
    for (int i = 0; i < 60; ++i) { // the next second
        in.hold(1.0, 0.0, dt, c.def.maxSpeedMps);
        const double move = in.pending().angleDeg - before;
        EXPECT_GE(move, lastMove - 1e-12) << "frame " << i;
        lastMove = move;
        before = in.pending().angleDeg;
    }
    EXPECT_GT(lastMove, 0.0);
    for (int i = 0; i < 120; ++i) in.hold(1.0, 0.0, dt, c.def.maxSpeedMps); // held 3.3 s
    before = in.pending().angleDeg;
    in.hold(1.0, 0.0, dt, c.def.maxSpeedMps);
    EXPECT_NEAR(in.pending().angleDeg - before, def.angleRate * dt, 1e-9) << "the most";
    // Let go and held again: slow from the start again.
    in.releaseHold();
    before = in.pending().angleDeg;
    in.hold(1.0, 0.0, dt, c.def.maxSpeedMps);
    EXPECT_DOUBLE_EQ(in.pending().angleDeg, before);
}

// A click (a press the pointer leaves by less than a few pixels) is not a drag: it leaves
// the aim alone, where it used to aim at the click at full power.
TEST(AimInput, AClickWithoutADragLeavesTheAimAlone) {
    ui::AimInput in;
    const game::CannonState c = cannon(45.0, 30.0);
    in.sync(c);
    in.beginDrag({200, 400}, {900, 100}, c.def.maxSpeedMps); // far up in the sky
    in.dragTo({200, 400}, {903, 102}, c.def.maxSpeedMps);    // a hand's tremble
    EXPECT_FALSE(in.rubberBand());
    EXPECT_TRUE(in.endDrag(c).empty());
    EXPECT_DOUBLE_EQ(in.pending().angleDeg, 45.0);
    EXPECT_DOUBLE_EQ(in.pending().speedMps, 30.0);
    // Past the few pixels it aims, and the rubber band runs to the pointer.
    in.beginDrag({200, 400}, {300, 400}, c.def.maxSpeedMps);
    in.dragTo({200, 400}, {300, 300}, c.def.maxSpeedMps);
    ASSERT_TRUE(in.rubberBand());
    EXPECT_DOUBLE_EQ(in.rubberBand()->y, 300.0);
    EXPECT_DOUBLE_EQ(in.pending().angleDeg, 45.0);
    EXPECT_FALSE(in.endDrag(c).empty());
}

TEST(AimInput, SpaceChargeFiresAtTheChargedPower) {
    ui::AimInput in; // full power after 1.5 s
    const game::CannonState c = cannon(45.0, 20.0, 60.0);
    in.sync(c);
    in.startCharge();
    for (int i = 0; i < 45; ++i) in.updateCharge(1.0 / 60.0); // 0.75 s: half
    ASSERT_TRUE(in.chargeFraction());
    EXPECT_NEAR(*in.chargeFraction(), 0.5, 1e-9);
    const auto cmds = in.releaseCharge(c);
    ASSERT_EQ(cmds.size(), 2u); // the angle is unchanged: power, then fire
    EXPECT_EQ(cmds[0].kind, CommandKind::Power);
    EXPECT_DOUBLE_EQ(cmds[0].number, 30.0);
    EXPECT_EQ(cmds[1].kind, CommandKind::Fire);
    EXPECT_FALSE(in.charging());
}

// A player who drags the power and then presses Space, the usual fire key, means that
// power: a tap fires at it, where a charge would fire at the few per cent reached.
TEST(AimInput, ATapOfSpaceFiresAtThePowerSetNotAtTheCharge) {
    ui::AimInput in; // a tap is under 0.2 s, full power after 1.5 s
    const game::CannonState c = cannon(45.0, 20.0, 60.0);
    in.sync(c);
    in.beginDrag({0.0, 0.0}, {0.0, 0.0}, 60.0);
    in.dragTo({0.0, 0.0}, {100.0, -100.0}, 60.0); // 45 degrees, 141 px of 260
    const auto dragged = in.endDrag(c);
    ASSERT_EQ(dragged.size(), 1u); // the angle is unchanged: the power
    const double power = dragged[0].number;
    ASSERT_GT(power, 30.0);
    game::CannonState aimed = c;
    aimed.speedMps = power;
    in.sync(aimed);
    in.startCharge();
    for (int i = 0; i < 6; ++i)
        in.updateCharge(1.0 / 60.0); // 0.1 s
    EXPECT_TRUE(in.charging());
    EXPECT_FALSE(in.chargeFraction()); // the power bar still shows the power set
    const auto cmds = in.releaseCharge(aimed);
    ASSERT_EQ(cmds.size(), 1u); // nothing to change: fire
    EXPECT_EQ(cmds[0].kind, CommandKind::Fire);
    EXPECT_DOUBLE_EQ(in.pending().speedMps, power);
    EXPECT_FALSE(in.charging());

    // Held past the tap, it is a charge from zero as before.
    in.startCharge();
    for (int i = 0; i < 15; ++i)
        in.updateCharge(1.0 / 60.0); // 0.25 s: a sixth
    ASSERT_TRUE(in.chargeFraction());
    const auto charged = in.releaseCharge(aimed);
    ASSERT_EQ(charged.size(), 2u);
    EXPECT_EQ(charged[0].kind, CommandKind::Power);
    EXPECT_DOUBLE_EQ(charged[0].number, 10.0);
}

TEST(AimInput, ChargeBeyondFullIsClampedAndSendsPowerThenFire) {
    ui::AimInput in;
    const game::CannonState c = cannon(45.0, 10.0, 50.0);
    in.sync(c);
    in.startCharge();
    in.updateCharge(5.0);
    const auto cmds = in.releaseCharge(c);
    ASSERT_EQ(cmds.size(), 2u);
    EXPECT_EQ(cmds[0].kind, CommandKind::Power);
    EXPECT_DOUBLE_EQ(cmds[0].number, 50.0);
    EXPECT_EQ(cmds[1].kind, CommandKind::Fire);
}

TEST(AimInput, StickBeyondDeadZoneSetsTheAngle) {
    ui::AimInput in;
    in.sync(cannon());
    in.stick(0.1, -0.1); // inside the dead zone
    EXPECT_DOUBLE_EQ(in.pending().angleDeg, 45.0);
    in.stick(0.0, -1.0); // straight up (SDL's y runs down)
    EXPECT_DOUBLE_EQ(in.pending().angleDeg, 90.0);
}

TEST(AimInput, ProjectileKeysSelectByIndex) {
    const game::CannonState c = cannon();
    const auto s = ui::AimInput::select(c, 1);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->kind, CommandKind::Select);
    EXPECT_EQ(s->text, "golf-ball");
    EXPECT_FALSE(ui::AimInput::select(c, 7));
}

TEST(SettingCommands, PanelEditsBecomeSetCommandsByName) {
    phys::WorldDef before;
    phys::WorldDef after = before;
    after.integrator = phys::Integrator::RK4;
    after.forces.gravity = {0.0, -1.62};
    const auto cmds = ui::settingCommands(before, after);
    ASSERT_EQ(cmds.size(), 2u);
    EXPECT_EQ(cmds[0].kind, CommandKind::Set);
    EXPECT_EQ(cmds[0].text, "integrator");
    EXPECT_EQ(std::get<std::string>(cmds[0].value), "rk4");
    EXPECT_EQ(cmds[1].text, "gravity");
    EXPECT_DOUBLE_EQ(std::get<double>(cmds[1].value), 1.62);
    EXPECT_TRUE(ui::settingCommands(before, before).empty());
}

TEST(GestureToSession, ADragAndAChargedShotAreRecordedAndFireTheShell) {
    game::Session session(game::loadLevel(sourceDir() + "/levels/01_earth_basics.json"));
    ui::AimInput in;
    const game::Match& m = session.match();
    in.sync(m.cannon());
    in.beginDrag({100, 600}, {100, 600}, m.cannon().def.maxSpeedMps);
    in.dragTo({100, 600}, {200, 600 - 173.205}, m.cannon().def.maxSpeedMps); // 60 deg, 200 px
    for (const Command& c : in.endDrag(m.cannon())) EXPECT_EQ(session.submit(c), "");
    EXPECT_DOUBLE_EQ(m.cannon().angleDeg, 60.0);
    EXPECT_DOUBLE_EQ(m.cannon().speedMps, 46.2); // 200 / 260 of 60 m/s, to 0.1
    for (int i = 0; i < 10; ++i) session.step();
    in.startCharge();
    in.updateCharge(0.9); // 60 % of 60 m/s
    for (const Command& c : in.releaseCharge(m.cannon())) EXPECT_EQ(session.submit(c), "");
    EXPECT_DOUBLE_EQ(m.cannon().speedMps, 36.0);
    EXPECT_TRUE(m.shell().has_value());
    // The recording holds the gesture's commands at the ticks they were made.
    const auto& cmds = session.recording().commands;
    ASSERT_EQ(cmds.size(), 4u);
    EXPECT_EQ(cmds[0].kind, CommandKind::Aim);
    EXPECT_EQ(cmds[0].tick, 0u);
    EXPECT_EQ(cmds[1].kind, CommandKind::Power);
    EXPECT_EQ(cmds[2].kind, CommandKind::Power);
    EXPECT_EQ(cmds[2].tick, 10u);
    EXPECT_EQ(cmds[3].kind, CommandKind::Fire);
    EXPECT_EQ(cmds[3].tick, 10u);
}

// Level results are the progress file's (tests/game/progress_test.cpp); the settings keep
// the choices.
TEST(PlayerSettings, ChoicesRoundTrip) {
    const auto dir = std::filesystem::temp_directory_path() / "artillery-settings-test";
    std::filesystem::remove_all(dir);
    const std::string file = (dir / "settings.json").string();
    ui::PlayerSettings s;
    s.difficulty = game::Difficulty::Hard;
    s.hotseat = true;
    ASSERT_EQ(ui::savePlayerSettings(file, s), "");
    std::string warning;
    const ui::PlayerSettings back = ui::loadPlayerSettings(file, warning);
    EXPECT_EQ(warning, "");
    EXPECT_EQ(back.difficulty, game::Difficulty::Hard);
    EXPECT_TRUE(back.hotseat);
    // A damaged file gives the defaults and a warning, never a crash.
    std::filesystem::create_directories(dir);
    game::writeFileAtomically(file, "{not json");
    const ui::PlayerSettings broken = ui::loadPlayerSettings(file, warning);
    EXPECT_NE(warning.find("settings.json"), std::string::npos) << warning;
    EXPECT_EQ(broken.difficulty, game::Difficulty::Normal) << "the defaults";
    std::filesystem::remove_all(dir);
}

} // namespace
