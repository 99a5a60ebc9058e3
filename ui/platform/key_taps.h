// Dear ImGui 1.86 reads keys as a state sampled once a frame (io.KeysDown), so a key
// pressed and let go between two frames, a quick tap on a slow frame, is never seen as
// pressed: IsKeyPressed misses it. (ImGui 1.87 queues input for this reason.) KeyTaps
// keeps such a release back until ImGui has had a frame with the key down: the release
// is handed on at the start of the next frame instead.
#pragma once

#include <SDL.h>

#include <set>
#include <vector>

namespace ui {

class KeyTaps {
  public:
    /// True when `event` is the release of a key pressed since the last frame began: it
    /// is kept for the next frame and must not reach ImGui now.
    bool holdBack(const SDL_Event& event);
    /// At the start of a frame: the releases held back before the last one began, for
    /// ImGui now.
    std::vector<SDL_Event> releasesDue();

  private:
    std::set<SDL_Scancode> pressedThisFrame_;
    std::vector<SDL_Event> heldBack_, due_;
};

} // namespace ui
