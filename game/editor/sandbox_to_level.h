// A sandbox scene as a level: what the player built in a sandbox match, saved so it can
// be edited and played again. The level the match was opened with, plus what was
// spawned, each where it is now:
//  - blocks at their body's current position and angle (toppled or not), their size,
//    material and density as made;
//  - ropes between where their end particles are now, with the same links and pins,
//    their sag the slack their length leaves over the new span; ties to blocks kept;
//  - blobs round again about where their centre particle is now;
//  - the ground as carved, when a blast carved it (its resampled heightfield);
//  - gravity, drag and air density as set now (the live settings).
// Loose particles (balls, projectiles, cloth, springs) are left out: a level has no
// place for them. The result has the sandbox mode and no file; it may not pass check
// (something spawned may have come to rest in the ground): the editor shows why.
#pragma once

#include "game/level.h"
#include "game/match.h"

namespace game::editor {

Level sandboxToLevel(const Match& match);

} // namespace game::editor
