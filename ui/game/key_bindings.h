// The game screen's keys as a table: which key does what, and when. The turn's own keys
// (aim, power, fire, projectiles) are the turn controls' (turn_controls.h), shared with
// the network duel; the replay viewer's are its own (replay_view.h); the help overlay
// lists them all (game_menus.h).
#pragma once

#include <SDL_keycode.h>

#include <optional>

namespace ui {

enum class GameKey {
    Screenshot,        ///< F12: the frame as a PNG
    BackToEditor,      ///< F4: from a playtest back to the editor
    Help,              ///< F1 or ?: the shortcuts
    Back,              ///< Esc: close what is open, else the pause menu
    Rewind,            ///< Backspace (held repeats): a second back, as a branch
    WatchLastShot,     ///< Z
    TogglePreview,     ///< P: the launch arc
    ToggleHint,        ///< H: the firing-solution hint
    ToggleFullPreview, ///< V: the whole path
    ToggleFollow,      ///< C: the camera follows the shell
    TogglePhysicsPanel, ///< F2
    ToggleStats,       ///< F6: the Stats window (compare, energy, charts)
    ToggleCost,        ///< F3: the cost in a corner (frame, physics time, what each model moves)
    NextMeasureTool,   ///< M: the measuring tools (probe, tape, stopwatch, off)
    ToggleCompare,     ///< X: every integrator fires the aim on screen, drawn with a legend
    StepTick,          ///< . : one tick, paused
    TogglePause,       ///< K
    Slower,            ///< [
    Faster,            ///< ]
    NormalSpeed,       ///< backslash
    Restart,           ///< R
    LevelSelect,       ///< L
    Home,              ///< Home: the level's framing again
};

/// Where a key acts.
enum class KeyScope {
    Always,   ///< on every screen of the game, menus and replays included
    Playtest, ///< while a level made in the editor is played
    Live,     ///< a live match with no menu open; held repeats act too
    Match,    ///< a live match with no menu open, once a press (repeats ignored)
};

struct KeyBinding {
    SDL_Keycode key;
    bool shift; ///< Shift must be held (the ? on the / key)
    GameKey action;
    KeyScope scope;
};

/// What `key` (with Shift held or not) does on the game screen, in the first binding
/// that names it; none for a key it leaves to the turn controls or the viewer.
std::optional<KeyBinding> gameKey(SDL_Keycode key, bool shift);

} // namespace ui
