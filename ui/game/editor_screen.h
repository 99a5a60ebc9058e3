// The level editor in the window: the level drawn as it will play (a match of it at its
// first tick, through the same MatchView the game uses) under the editor's handles,
// a panel of tools, properties and the loader's verdict, and the mouse and keys that
// become game::editor::LevelEditor calls. The game screen owns it and plays the level
// when asked (ui/game/game_screen.*).
//
// Section index
//   EditorRequests   what the panel or a key asked the game screen for
//   LevelEditorView  tools, pointer gestures, keys, drawing, the panel
#pragma once

#include "game/editor/level_editor.h"
#include "game/match.h"
#include "ui/game/match_view.h"
#include "ui/render/camera.h"
#include "ui/render/renderer2d.h"

#include <SDL.h>

#include <memory>
#include <optional>
#include <string>

namespace ui {

/// What the editor asks of the screen that holds it.
struct EditorRequests {
    bool play = false;  ///< play the level now (it passes check)
    bool close = false; ///< back to the level select screen (the editor stays open)
};

/// Width of the editor's panel on the left, px; the world is framed right of it.
inline constexpr float kEditorPanelWidth = 340.0f;

class LevelEditorView {
  public:
    enum class Tool { Select, Terrain, Cannon, Target, Block, Rope, Blob };

    /// Edits `level`; Save As writes into `mapsFolder` (the player's maps folder).
    LevelEditorView(game::Level level, std::string mapsFolder);

    game::editor::LevelEditor& editor() { return editor_; }
    const game::editor::LevelEditor& editor() const { return editor_; }
    Tool tool() const { return tool_; }
    void choose(Tool tool);
    const game::editor::Item& selection() const { return selected_; }
    bool snap() const { return snap_; }
    /// What the last action said (saved where, refused why).
    const std::string& status() const { return status_; }

    /// A camera that shows the whole world right of the panel.
    Camera framing(int width, int height) const;

    // Pointer gestures with the left button, in world metres; `reach` is how far from a
    // handle a press still takes it (a few pixels at the current zoom).
    void press(phys::Vec2 at, double reach);
    void move(phys::Vec2 at, double reach);
    void lift();
    bool dragging() const { return dragging_; }
    /// A key the panel did not take. Returns what it asks of the screen.
    EditorRequests key(SDL_Keycode key, bool ctrl, bool shift);

    /// Saves to the file the level came from (Save As for a new one). "" or why not.
    std::string save();
    /// Saves as `name` (".json" added) in the maps folder. "" or why not.
    std::string saveAs(const std::string& name);

    /// Draws the level as it will play and the handles over it (flushed).
    void drawWorld(Renderer2D& renderer, const Camera& camera);
    /// The editor's panel (tools, undo, save, play, the verdict, properties).
    EditorRequests panel();

  private:
    phys::Vec2 snapped(phys::Vec2 p) const;
    void startDrag(const game::editor::Item& item, phys::Vec2 at);
    void deleteSelected();
    void tieRopeEnd();
    void refreshPreview();
    void drawHandles(Renderer2D& r, const Camera& camera) const;
    void toolButtons();
    void fileButtons(EditorRequests& out);
    void verdict();

    game::editor::LevelEditor editor_;
    std::string mapsFolder_;
    Tool tool_ = Tool::Select;
    bool snap_ = true;
    float gridMetres_ = 0.5f;
    game::editor::Item selected_;
    game::editor::Item hovered_;
    bool dragging_ = false;
    phys::Vec2 grabOffset_;      ///< item position minus the pointer when the drag began
    bool widgetGesture_ = false; ///< a panel field is being edited (one undo step)
    char saveName_[64] = "";
    std::string status_;
    // The level as it will play: a match of the last state that passed check.
    std::unique_ptr<game::Match> preview_;
    game::Level previewOf_;
    MatchView previewView_;
};

} // namespace ui
