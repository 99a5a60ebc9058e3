// The level editor inside the game screen: the editor view (editor_screen.h) kept while
// its level is played (a playtest) or the level select is shown, and the mouse and keys
// while it is on screen. The game screen moves between it and play.
#pragma once

#include "game/level.h"
#include "ui/game/camera_control.h"
#include "ui/game/editor_screen.h"

#include <memory>
#include <optional>
#include <string>

union SDL_Event;

namespace ui {

class ImGuiLayer;

class EditorFlow {
  public:
    /// The editor, while it is on screen (null otherwise).
    LevelEditorView* onScreen() { return editing_ ? view_.get() : nullptr; }
    /// The editor holds a level (on screen or not).
    LevelEditorView* held() { return view_.get(); }
    const LevelEditorView* held() const { return view_.get(); }
    bool editing() const { return editing_; }
    /// The match in play is the editor's level (the editor waits behind it).
    bool playtest() const { return playtest_; }

    /// Edits `level`; Save As writes into `mapsFolder`.
    void open(game::Level level, const std::string& mapsFolder);
    /// Back to the editor from its playtest (or from the level select).
    void resume();
    /// The level select over it: the editor keeps its level.
    void leave() { editing_ = false; }
    /// Play is over for its level: a level played now is not the editor's.
    void endPlaytest() { editing_ = playtest_ = false; }
    /// Writes the level being made as `mapsFolder`/playtest.json (played from there, through
    /// the loader, so what is played is what the file says); the file, or nullopt with the
    /// reason in `error` when the level does not pass check or cannot be written.
    std::optional<std::string> writePlaytest(const std::string& mapsFolder, std::string& error);
    /// The playtest started from the file written.
    void startPlaytest() { editing_ = false, playtest_ = true; }

    /// A mouse event while the editor is on screen: a press on a handle takes it, motion
    /// drags it, release lets go; the wheel and a right drag move `camera`. The panel on
    /// the left takes the mouse over it.
    void mouse(const SDL_Event& e, const ImGuiLayer& imgui, CameraControl& camera,
               phys::Vec2 pixelsPerPoint, int windowWidth);

  private:
    std::unique_ptr<LevelEditorView> view_;
    bool editing_ = false;  ///< the editor is on screen
    bool playtest_ = false; ///< the match in play is the editor's level
};

} // namespace ui
