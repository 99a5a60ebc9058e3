// A game controller (SDL's GameController API, so any pad with a mapping reads the same):
// the left stick points the barrel, the triggers change the power (right up, left down),
// A fires, B ends the turn, X takes the next projectile, Start pauses. The pad only
// reports what the player does; AimInput and the game screen turn it into commands, the
// same ones the mouse and keys give (tests/ui/pad_input_test.cpp drives it with SDL's
// virtual joystick).
#pragma once

#include <SDL2/SDL.h>

namespace ui {

enum class PadAction { None, Fire, EndTurn, NextProjectile, Pause };

/// What the pad's axes say this frame, each in -1..1 (stick y down, as SDL reports it).
struct PadAxes {
    double stickX = 0.0, stickY = 0.0;
    double power = 0.0; ///< right trigger minus left trigger
};

class PadInput {
  public:
    PadInput() = default;
    PadInput(const PadInput&) = delete;
    PadInput& operator=(const PadInput&) = delete;
    ~PadInput();

    /// Opens the first controller already connected, if any (the game controller
    /// subsystem must be initialised).
    void openFirst();
    /// Follows controllers plugged in and out, and turns button presses into actions.
    PadAction handle(const SDL_Event& e);
    bool connected() const { return pad_ != nullptr; }
    PadAxes axes() const;

  private:
    SDL_GameController* pad_ = nullptr;
};

} // namespace ui
