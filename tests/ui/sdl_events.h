// Synthetic SDL events for the game screen's tests, as the window would send them.
#pragma once

#include "physics/vec2.h"

#include <SDL.h>

namespace test_events {

/// A mouse button press or release (type SDL_MOUSEBUTTONDOWN or UP) at a pixel.
inline SDL_Event button(Uint32 type, phys::Vec2 pixel, Uint8 which = SDL_BUTTON_LEFT) {
    SDL_Event e{};
    e.type = type;
    e.button.button = which;
    e.button.x = static_cast<int>(pixel.x);
    e.button.y = static_cast<int>(pixel.y);
    return e;
}

/// The pointer moved to a pixel, by `rel` pixels since the last motion.
inline SDL_Event motion(phys::Vec2 pixel, phys::Vec2 rel = {}) {
    SDL_Event e{};
    e.type = SDL_MOUSEMOTION;
    e.motion.x = static_cast<int>(pixel.x);
    e.motion.y = static_cast<int>(pixel.y);
    e.motion.xrel = static_cast<int>(rel.x);
    e.motion.yrel = static_cast<int>(rel.y);
    return e;
}

/// A key pressed and let go, as SDL reports it.
inline SDL_Event keyEvent(Uint32 type, SDL_Keycode key) {
    SDL_Event e{};
    e.type = type;
    e.key.keysym.sym = key;
    return e;
}

} // namespace test_events
