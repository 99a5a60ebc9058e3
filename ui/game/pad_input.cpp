#include "ui/game/pad_input.h"

namespace ui {

PadInput::~PadInput() {
    if (pad_) SDL_GameControllerClose(pad_);
}

void PadInput::openFirst() {
    for (int i = 0; i < SDL_NumJoysticks() && !pad_; ++i)
        if (SDL_IsGameController(i)) pad_ = SDL_GameControllerOpen(i);
}

PadAction PadInput::handle(const SDL_Event& e) {
    if (e.type == SDL_CONTROLLERDEVICEADDED && !pad_) pad_ = SDL_GameControllerOpen(e.cdevice.which);
    if (e.type == SDL_CONTROLLERDEVICEREMOVED && pad_ &&
        e.cdevice.which == SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(pad_))) {
        SDL_GameControllerClose(pad_);
        pad_ = nullptr;
    }
    if (e.type != SDL_CONTROLLERBUTTONDOWN || !pad_ ||
        e.cbutton.which != SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(pad_)))
        return PadAction::None;
    switch (e.cbutton.button) {
    case SDL_CONTROLLER_BUTTON_A: return PadAction::Fire;
    case SDL_CONTROLLER_BUTTON_B: return PadAction::EndTurn;
    case SDL_CONTROLLER_BUTTON_X: return PadAction::NextProjectile;
    case SDL_CONTROLLER_BUTTON_START: return PadAction::Pause;
    default: return PadAction::None;
    }
}

PadAxes PadInput::axes() const {
    if (!pad_) return {};
    // SDL axes run -32768..32767 (triggers 0..32767).
    const auto axis = [&](SDL_GameControllerAxis a) {
        return SDL_GameControllerGetAxis(pad_, a) / 32767.0;
    };
    return {axis(SDL_CONTROLLER_AXIS_LEFTX), axis(SDL_CONTROLLER_AXIS_LEFTY),
            axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT) - axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT)};
}

} // namespace ui
