// The sandbox's tools in the window: a palette of what to spawn, a hand that
// grabs and drags, and a button that turns any level into a sandbox. Every gesture
// becomes a game::Command (sandbox, spawn, grab, drag, release), so a sandbox session
// is recorded and replayed like a match; the mouse only decides where and when.
#pragma once

#include "game/command.h"
#include "game/match.h"
#include "ui/render/renderer2d.h"

#include <optional>
#include <string>
#include <vector>

namespace ui {

class SandboxTools {
  public:
    enum class Tool { Cannon, Hand, Spawn };
    /// Picks a tool (and for Spawn, what it makes), as the panel's buttons do.
    void choose(Tool tool, std::string kind = "block") {
        tool_ = tool;
        kind_ = std::move(kind);
    }

    /// The "Sandbox" panel; returns the commands its buttons asked for.
    std::vector<game::Command> panel(const game::Match& match);
    /// True once after the panel's "Save as level" was pressed: the screen opens the
    /// scene in the level editor (game/editor/sandbox_to_level.h).
    bool takeSaveAsLevel() {
        const bool asked = saveAsLevel_;
        saveAsLevel_ = false;
        return asked;
    }
    /// True when the left mouse belongs to a sandbox tool rather than to the cannon.
    bool active(const game::Match& match) const { return match.sandbox() && tool_ != Tool::Cannon; }

    // Pointer gestures in world coordinates (m); each returns the commands to submit.
    std::vector<game::Command> press(phys::Vec2 at);
    std::vector<game::Command> move(phys::Vec2 at);
    std::vector<game::Command> lift(phys::Vec2 at);

    /// What is being drawn but not yet made (a rope from its anchor), and the hand.
    void draw(Renderer2D& renderer, const game::Match& match) const;

  private:
    Tool tool_ = Tool::Spawn;
    std::string kind_ = "block"; ///< what Spawn makes
    float size_ = 0.0f;          ///< m, 0 = the kind's default
    std::optional<phys::Vec2> anchor_;  ///< a rope or spring being drawn from here
    phys::Vec2 pointer_;
    bool holding_ = false;
    phys::Vec2 lastDrag_;
    bool saveAsLevel_ = false;
};

} // namespace ui
