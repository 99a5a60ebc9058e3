// The level editor's property panels: each is a function that edits a game::Level in
// place and returns true when a field changed (Dear ImGui's immediate mode); the editor
// screen turns the edited copy into an undo step. The panels check nothing themselves:
// the loader's verdict on the result is shown beside them.
#pragma once

#include "game/editor/level_editor.h"
#include "game/level.h"

namespace ui {

/// The level's own fields: name, description, mode, physics (gravity or a planet, air
/// density, drag, wind range, water), shots, seed, world bounds, the terrain's
/// destructibility and material.
bool levelPropertiesPanel(game::Level& level);

/// The fields of one item: a terrain point's x and y; a cannon's position, aim, player
/// and weapons with their counts; a target's position, radius, points; a block's size,
/// angle, material, density, target flag; a rope's ends, links, sag, pins, ties; a
/// blob's centre, radius, points, stiffness, mass, target flag.
bool itemPropertiesPanel(game::Level& level, const game::editor::Item& item);

} // namespace ui
