// The game controller path without a device: SDL's virtual joystick, declared as a game
// controller, is plugged in, its stick, triggers and buttons are set, and what the game
// reads from it (PadInput) drives AimInput and a real session to a fired shell.
#include "game/level.h"
#include "game/session.h"
#include "ui/game/aim_input.h"
#include "ui/game/pad_input.h"

#include <SDL2/SDL.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace {

std::string sourceDir() {
    return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path().string();
}

// A virtual pad with every GameController axis and button, mapped one to one.
class VirtualPad : public ::testing::Test {
  protected:
    void SetUp() override {
        // No window has focus here: let joystick events through anyway.
        SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
        ASSERT_EQ(SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER), 0) << SDL_GetError();
        SDL_VirtualJoystickDesc desc;
        SDL_zero(desc);
        desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
        desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
        desc.naxes = SDL_CONTROLLER_AXIS_MAX;
        desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
        desc.name = "artillery test pad";
        device_ = SDL_JoystickAttachVirtualEx(&desc);
        ASSERT_GE(device_, 0) << SDL_GetError();
        ASSERT_TRUE(SDL_IsGameController(device_));
        joystick_ = SDL_JoystickOpen(device_); // the handle that sets the virtual state
        ASSERT_NE(joystick_, nullptr) << SDL_GetError();
    }
    void TearDown() override {
        if (joystick_) SDL_JoystickClose(joystick_);
        if (device_ >= 0) SDL_JoystickDetachVirtual(device_);
        SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
    }

    // Sets the virtual state, lets SDL see it, and feeds every event to the pad.
    std::vector<ui::PadAction> pump(ui::PadInput& pad) {
        SDL_GameControllerUpdate();
        std::vector<ui::PadAction> actions;
        SDL_Event e;
        while (SDL_PollEvent(&e))
            if (const ui::PadAction a = pad.handle(e); a != ui::PadAction::None)
                actions.push_back(a);
        return actions;
    }
    // A stick axis, -1..1.
    void axis(SDL_GameControllerAxis a, double value) {
        SDL_JoystickSetVirtualAxis(joystick_, a, static_cast<Sint16>(std::lround(value * 32767.0)));
    }
    // A trigger, 0..1: the mapping spreads the joystick axis's whole range -32768..32767
    // over the trigger's 0..32767.
    void trigger(SDL_GameControllerAxis a, double value) {
        SDL_JoystickSetVirtualAxis(joystick_, a,
                                   static_cast<Sint16>(std::lround(-32768.0 + value * 65535.0)));
    }
    void button(SDL_GameControllerButton b, bool down) {
        SDL_JoystickSetVirtualButton(joystick_, b, down ? 1 : 0);
    }

    int device_ = -1;
    SDL_Joystick* joystick_ = nullptr;
};

TEST_F(VirtualPad, PluggedInItIsOpenedAndItsAxesRead) {
    ui::PadInput pad;
    EXPECT_FALSE(pad.connected());
    pump(pad); // the device-added event opens it
    ASSERT_TRUE(pad.connected());
    axis(SDL_CONTROLLER_AXIS_LEFTX, 0.5);
    axis(SDL_CONTROLLER_AXIS_LEFTY, -0.75);
    trigger(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 1.0);
    trigger(SDL_CONTROLLER_AXIS_TRIGGERLEFT, 0.25);
    pump(pad);
    const ui::PadAxes a = pad.axes();
    EXPECT_NEAR(a.stickX, 0.5, 1e-4);
    EXPECT_NEAR(a.stickY, -0.75, 1e-4);
    EXPECT_NEAR(a.power, 0.75, 1e-4);
}

TEST_F(VirtualPad, ButtonsAreTheGameActions) {
    ui::PadInput pad;
    pump(pad);
    ASSERT_TRUE(pad.connected());
    const std::pair<SDL_GameControllerButton, ui::PadAction> map[] = {
        {SDL_CONTROLLER_BUTTON_A, ui::PadAction::Fire},
        {SDL_CONTROLLER_BUTTON_B, ui::PadAction::EndTurn},
        {SDL_CONTROLLER_BUTTON_X, ui::PadAction::NextProjectile},
        {SDL_CONTROLLER_BUTTON_START, ui::PadAction::Pause},
        {SDL_CONTROLLER_BUTTON_Y, ui::PadAction::None},
    };
    for (const auto& [b, action] : map) {
        button(b, true);
        const auto pressed = pump(pad);
        button(b, false);
        EXPECT_TRUE(pump(pad).empty()) << "a release does nothing";
        if (action == ui::PadAction::None)
            EXPECT_TRUE(pressed.empty());
        else
            EXPECT_EQ(pressed, std::vector<ui::PadAction>{action});
    }
}

TEST_F(VirtualPad, UnpluggedItIsClosedAndReadsNothing) {
    ui::PadInput pad;
    pump(pad);
    ASSERT_TRUE(pad.connected());
    axis(SDL_CONTROLLER_AXIS_LEFTX, 1.0);
    SDL_JoystickClose(joystick_);
    joystick_ = nullptr;
    ASSERT_EQ(SDL_JoystickDetachVirtual(device_), 0);
    device_ = -1;
    pump(pad);
    EXPECT_FALSE(pad.connected());
    EXPECT_EQ(pad.axes().stickX, 0.0);
}

// The whole path: the stick sets the angle, the right trigger raises the power, A fires,
// and the shell leaves the muzzle at that angle and speed.
TEST_F(VirtualPad, StickTriggerAndAFireTheShotTheyAimed) {
    game::Session session(game::loadLevel(sourceDir() + "/levels/01_earth_basics.json"));
    const game::Match& m = session.match();
    ui::PadInput pad;
    ui::AimInput aim;
    pump(pad);
    ASSERT_TRUE(pad.connected());
    aim.sync(m.cannon());
    const double speed0 = aim.pending().speedMps;

    // Stick up and to the right at 30 degrees (SDL's y runs down), right trigger fully
    // in for 0.5 s: the power rises by AimInputDef::powerRate x 0.5 s.
    axis(SDL_CONTROLLER_AXIS_LEFTX, std::cos(M_PI / 6));
    axis(SDL_CONTROLLER_AXIS_LEFTY, -std::sin(M_PI / 6));
    trigger(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 1.0);
    pump(pad);
    for (int frame = 0; frame < 30; ++frame) {
        const ui::PadAxes a = pad.axes();
        aim.stick(a.stickX, a.stickY);
        aim.sweep(0.0, a.power, 1.0 / 60.0, m.cannon().def.maxSpeedMps);
    }
    EXPECT_NEAR(aim.pending().angleDeg, 30.0, 0.05);
    const double speed = std::min(speed0 + ui::AimInputDef{}.powerRate * 0.5,
                                  m.cannon().def.maxSpeedMps);
    EXPECT_NEAR(aim.pending().speedMps, speed, 1e-9);

    button(SDL_CONTROLLER_BUTTON_A, true);
    const auto actions = pump(pad);
    ASSERT_EQ(actions, std::vector<ui::PadAction>{ui::PadAction::Fire});
    for (const game::Command& c : aim.fire(m.cannon())) EXPECT_EQ(session.submit(c), "");
    const auto shell = m.shell();
    ASSERT_TRUE(shell.has_value());
    const phys::ParticleSet& p = m.world().particles;
    const double vx = p.vx[*shell], vy = p.vy[*shell];
    EXPECT_NEAR(std::atan2(vy, vx) * 180.0 / M_PI, m.cannon().angleDeg, 1e-9);
    EXPECT_NEAR(std::hypot(vx, vy), m.cannon().speedMps, 1e-9);
    EXPECT_NEAR(m.cannon().angleDeg, 30.0, 0.05);
    EXPECT_NEAR(m.cannon().speedMps, speed, 0.051); // commands carry 0.1 m/s steps
}

} // namespace
