// Which model flies a shell: the closed form p0 + v0 t + g t^2/2 (under the `auto` model,
// where only gravity reaches it: no air drag on it, no point gravity, no water) or the
// chosen integrator. The aim readout names it before the shot, the `fired` event after.
#pragma once

#include "physics/particles.h"
#include "physics/world.h"

#include <string>

namespace game {

class Match;

/// The name the `fired` event carries: "closed-form", or the integrator's canonical name
/// as `set integrator` lists it first ("explicit-euler", "symplectic-euler", ...).
inline constexpr const char* kClosedFormModel = "closed-form";

/// True when the world's model rule puts a shell fired as `shell` on the closed form for
/// its whole flight in the open. Water counts against it: the integrator takes the shell
/// over near the surface, so it is what finishes the flight.
bool flownByClosedForm(const phys::WorldDef& world, const phys::ParticleDef& shell);

/// "closed-form" or the integrator's canonical name, for a shell fired as `shell`.
std::string shotModelName(const phys::WorldDef& world, const phys::ParticleDef& shell);

/// The same for the shell the current cannon would fire now (its selected projectile).
std::string shotModelName(const Match& match);

/// For people: "closed form (exact)" or "explicit Euler", "velocity Verlet", "RK4", ...
std::string shotModelLabel(const std::string& modelName);

} // namespace game
