#include "ui/platform/key_taps.h"

namespace ui {

bool KeyTaps::holdBack(const SDL_Event& e) {
    if (e.type == SDL_KEYDOWN) pressedThisFrame_.insert(e.key.keysym.scancode);
    if (e.type != SDL_KEYUP || !pressedThisFrame_.count(e.key.keysym.scancode)) return false;
    heldBack_.push_back(e);
    return true;
}

std::vector<SDL_Event> KeyTaps::releasesDue() {
    // Those held back in the frame that just ended wait one more: that frame is the one
    // that sees their keys down.
    std::vector<SDL_Event> due;
    due.swap(due_);
    due_.swap(heldBack_);
    pressedThisFrame_.clear();
    return due;
}

} // namespace ui
