// Where a shell first lands, against where the exact path would have: the `landed`
// event's closed_form_error_m. The exact path is the closed form under uniform gravity
// (Rabin, Introduction to Game Development, 4.3): p(t) = p0 + v0 t + g t^2/2. Its first
// touch of a surface is found by conservative advancement (Mirtich, "Impulse-based
// Dynamic Simulation of Rigid Body Systems", ch. 3): at each time step by the clearance
// over a bound on the speed, |v0| + |g| t, so the path never steps through the surface.
#pragma once

#include "physics/collision/shapes.h"
#include "physics/rigid/rigid_world.h"
#include "physics/vec2.h"

#include <functional>
#include <optional>

namespace game {

/// A shell as it left the muzzle.
struct ShellLaunch {
    phys::Vec2 position; ///< m
    phys::Vec2 velocity; ///< m/s
    double radius = 0.0; ///< m
};

/// The first time in [0, maxSeconds] at which the exact path's centre comes within the
/// radius of a surface, given as the clearance of a centre from it (distance from the
/// surface to the centre less the radius, m; at most `reach` when farther). None when it
/// never does.
std::optional<double> firstTouchTime(const ShellLaunch& launch, phys::Vec2 gravity,
                                     double maxSeconds, double reach,
                                     const std::function<double(phys::Vec2)>& clearance);

/// Signed distance along x from the exact path's centre at `exactTime` to the flown
/// shell's centre when it touched, positive when the flown shell landed beyond (farther
/// in the direction of fire).
double landingErrorAlongX(const ShellLaunch& launch, phys::Vec2 gravity, double exactTime,
                          phys::Vec2 flownCentre);

/// closed_form_error_m for a first contact with the static shapes (terrain, walls,
/// obstacles): the exact path's first touch of any of them, as the ground is one surface
/// made of many segments (a shell landing 0.7 m long may touch the next segment); none
/// when the exact path meets none of them within maxSeconds.
std::optional<double> closedFormErrorOnShapes(const phys::StaticShapes& shapes,
                                              const ShellLaunch& launch, phys::Vec2 gravity,
                                              phys::Vec2 flownCentre, double maxSeconds);

/// The same for a Box2D body as it is now.
std::optional<double> closedFormErrorOnBody(const phys::RigidWorld& rigid, phys::BodyId body,
                                            const ShellLaunch& launch, phys::Vec2 gravity,
                                            phys::Vec2 flownCentre, double maxSeconds);

/// Where on the chord from `from` to `to` a circle of `radius` first touches the body
/// (bisection on the clearance): the flown shell's centre at a contact the coupling
/// reports at the tick's end.
phys::Vec2 firstTouchOnChord(const phys::RigidWorld& rigid, phys::BodyId body, phys::Vec2 from,
                             phys::Vec2 to, double radius);

} // namespace game
