// The level editor's model: a game::Level being edited, what is under a point of it,
// the edits a player makes (terrain points; cannons, targets, blocks, ropes and blobs
// placed, moved, deleted; any field changed), an undo stack of whole Level copies, and
// the verdict of the loader on the level as it stands. No window: the screen
// (ui/game/editor_screen.*) turns the mouse and the panels into these calls.
//
// Validation is the loader itself: the level is written with the level writer and read
// back with parseLevel, so the editor says exactly what `artillery check` would say,
// and what it saves is what the game loads.
//
// Section index
//   Item          what a point of the level hits (kind, index, which end of a rope)
//   newLevel      a blank level that passes check
//   LevelEditor   edits, gestures, undo/redo, validation, saving
#pragma once

#include "game/level.h"

#include <string>
#include <vector>

namespace game::editor {

/// What the editor can pick and move.
enum class ItemKind { None, TerrainPoint, Cannon, Target, Block, Rope, Blob };
const char* itemKindName(ItemKind kind);

/// One thing of the level: its kind and index in the level's list of that kind.
struct Item {
    ItemKind kind = ItemKind::None;
    int index = -1;
    /// Ropes: which end is meant (0 = from, 1 = to), or -1 for the whole rope.
    int end = -1;

    bool operator==(const Item&) const = default;
    explicit operator bool() const { return kind != ItemKind::None; }
};

/// A blank practice level that passes check: flat ground at 10 m across 200 x 100 m,
/// a cannon on the left and a target on the right.
Level newLevel();

/// How many undo steps are kept (each is a whole Level copy).
inline constexpr std::size_t kUndoDepth = 200;

class LevelEditor {
  public:
    explicit LevelEditor(Level level);

    const Level& level() const { return level_; }

    // --- validation ------------------------------------------------------------------
    /// "" when the level loads, else the loader's message (file, JSON path, what).
    const std::string& problem() const { return problem_; }
    bool valid() const { return problem_.empty(); }
    /// The level as the loader reads it back: the last state that passed (null when none
    /// has yet, e.g. a sandbox scene that does not load as it stands).
    const Level* checked() const { return everValid_ ? &checked_ : nullptr; }

    // --- looking ---------------------------------------------------------------------
    /// The item at `at`: the nearest handle the point is on (rope ends, cannons, targets,
    /// blobs, terrain points, each within `reach` m or its own radius; on a tie the
    /// object wins over the terrain point under it), else the top block it is inside,
    /// else a rope span within `reach`.
    Item hitTest(phys::Vec2 at, double reach) const;
    /// The top block `at` lies inside (the one hitTest picks), or -1: where a rope end
    /// let go there is tied.
    int blockAt(phys::Vec2 at) const;
    /// Where an item sits: its centre, position, or the rope end (a whole rope: its middle).
    phys::Vec2 positionOf(const Item& item) const;

    // --- edits (each one undo step) ------------------------------------------------------
    /// Adds a terrain point at `at`, between the points around its x (or at either end).
    /// Returns its index, or -1 (with why in `refusal()`) when a point has that x already.
    int addTerrainPoint(phys::Vec2 at);
    /// Places a new object of `kind` (Cannon, Target, Block, Rope, Blob) at `at` with the
    /// kind's defaults. Returns it.
    Item place(ItemKind kind, phys::Vec2 at);
    /// Moves an item to `to` as one step (see also the drag gesture below).
    void move(const Item& item, phys::Vec2 to);
    /// Deletes an item. A terrain keeps at least two points; a level at least one cannon.
    /// Ropes tied to a deleted block lose the tie (the end stays, pinned). False (and why
    /// in `refusal()`) when refused.
    bool remove(const Item& item);
    /// Any other change (a field in the panel): the whole level as edited.
    void change(const Level& edited);
    /// What the last refused edit said ("" after one that took effect).
    const std::string& refusal() const { return refusal_; }

    // --- gestures: many updates, one undo step --------------------------------------------
    /// Starts a gesture (a drag, a slider held): the state now is what undo returns to.
    void beginGesture();
    /// During a gesture: moves an item, or sets the whole level, without a new undo step.
    void dragTo(const Item& item, phys::Vec2 to);
    void update(const Level& edited);
    /// Ends the gesture: one undo step if anything changed.
    void endGesture();
    bool inGesture() const { return gesture_; }

    // --- history ---------------------------------------------------------------------
    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    void undo();
    void redo();

    // --- the file --------------------------------------------------------------------
    /// The file the level was loaded from or last saved to ("" for a new one).
    const std::string& file() const { return file_; }
    /// Changed since it was opened or saved.
    bool modified() const { return modified_; }
    /// Writes the level to `file` (atomically, with the level writer) when it is valid.
    /// "" on success (the editor now edits that file), else why not.
    std::string save(const std::string& file);

  private:
    void setItemPosition(Level& level, const Item& item, phys::Vec2 to) const;
    void pushUndo(Level before);
    void edited();
    void validate();

    Level level_;
    Level checked_;
    std::string file_;
    std::string problem_;
    std::string refusal_;
    std::vector<Level> undo_, redo_;
    bool gesture_ = false;
    Level gestureStart_;
    bool modified_ = false;
    bool everValid_ = false;
};

} // namespace game::editor
