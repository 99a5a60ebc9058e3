// What the material names in a level mean. The level check and the match look names up
// through these functions, so a name the check accepts is a name the match can build, and
// a name neither knows is refused when the level is loaded instead of silently replaced.
#pragma once

#include "physics/materials.h"
#include "physics/rigid/rigid_types.h"

#include <optional>
#include <string>

namespace game {

/// A block's rigid material ("wood", "stone", "steel"); density comes from the level.
std::optional<phys::RigidMaterial> blockMaterialFromName(const std::string& name);
/// The accepted block material names, comma-separated, for messages.
std::string blockMaterialNames();

/// A surface material for the terrain or an obstacle: "ground" (the terrain's default,
/// the table's earth), "steel" (an obstacle's default, the rigid reference floor), or any
/// name of the table.
std::optional<phys::MaterialId> surfaceMaterialFromName(const phys::MaterialTable& table,
                                                        const std::string& name);
/// The accepted surface material names of a table, comma-separated, for messages.
std::string surfaceMaterialNames(const phys::MaterialTable& table);

} // namespace game
