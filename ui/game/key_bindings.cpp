#include "ui/game/key_bindings.h"

#include <iterator>

namespace ui {

namespace {

constexpr KeyBinding kBindings[] = {
    {SDLK_F12, false, GameKey::Screenshot, KeyScope::Always},
    {SDLK_F4, false, GameKey::BackToEditor, KeyScope::Playtest},
    {SDLK_F1, false, GameKey::Help, KeyScope::Always},
    {SDLK_QUESTION, false, GameKey::Help, KeyScope::Always},
    {SDLK_SLASH, true, GameKey::Help, KeyScope::Always},
    {SDLK_ESCAPE, false, GameKey::Back, KeyScope::Always},
    {SDLK_BACKSPACE, false, GameKey::Rewind, KeyScope::Live},
    {SDLK_z, false, GameKey::WatchLastShot, KeyScope::Match},
    {SDLK_p, false, GameKey::TogglePreview, KeyScope::Match},
    {SDLK_h, false, GameKey::ToggleHint, KeyScope::Match},
    {SDLK_v, false, GameKey::ToggleFullPreview, KeyScope::Match},
    {SDLK_c, false, GameKey::ToggleFollow, KeyScope::Match},
    {SDLK_F2, false, GameKey::TogglePhysicsPanel, KeyScope::Match},
    {SDLK_F6, false, GameKey::ToggleStats, KeyScope::Match},
    {SDLK_F3, false, GameKey::ToggleCost, KeyScope::Match},
    {SDLK_m, false, GameKey::NextMeasureTool, KeyScope::Match},
    {SDLK_x, false, GameKey::ToggleCompare, KeyScope::Match},
    {SDLK_PERIOD, false, GameKey::StepTick, KeyScope::Match},
    {SDLK_k, false, GameKey::TogglePause, KeyScope::Match},
    {SDLK_LEFTBRACKET, false, GameKey::Slower, KeyScope::Match},
    {SDLK_RIGHTBRACKET, false, GameKey::Faster, KeyScope::Match},
    {SDLK_BACKSLASH, false, GameKey::NormalSpeed, KeyScope::Match},
    {SDLK_r, false, GameKey::Restart, KeyScope::Match},
    {SDLK_l, false, GameKey::LevelSelect, KeyScope::Match},
    {SDLK_HOME, false, GameKey::Home, KeyScope::Match},
};

} // namespace

std::optional<KeyBinding> gameKey(SDL_Keycode key, bool shift) {
    for (const KeyBinding& b : kBindings)
        if (b.key == key && (!b.shift || shift)) return b;
    return std::nullopt;
}

} // namespace ui
