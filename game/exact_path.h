// The exact path beside the flown one: after a shot flown by an integrator where a closed
// form exists (gravity alone), the parabola p0 + v0 t + g t^2/2 from the same muzzle
// state (Rabin, Introduction to Game Development, 4.3) up to where it met the same
// surface, and the verdict's words for the difference: "explicit Euler, 30 Hz: 0.70 m long
// of the exact path". A view of the match's `landed` event: it reads, never writes.
#pragma once

#include "physics/vec2.h"

#include <optional>
#include <string>
#include <vector>

namespace game {

class Match;
struct GameEvent;

struct ExactPath {
    std::string model;              ///< the integrator that flew the shell (canonical name)
    double tickHz = 0.0;            ///< its rate, ticks per second
    int substeps = 1;               ///< sub-steps per tick
    double errorM = 0.0;            ///< closed_form_error_m: + the flown shell landed beyond
    /// The flown shell's energy 1/2 v^2 + |g| y (per kg, y from the level's 0) the tick
    /// before it landed, relative to the launch's: the closed form keeps it, explicit
    /// Euler gains |g|^2 h t / 2 by then, symplectic Euler loses as much.
    double energyChange = 0.0;
    phys::Vec2 flownLanding;        ///< the flown shell's centre at its first contact, m
    phys::Vec2 exactLanding;        ///< the exact path's centre where it met that surface, m
    std::vector<phys::Vec2> points; ///< the exact path from the muzzle to exactLanding, m
};

/// The comparison for a `landed` event of a shot flown by `model`; none when the closed
/// form flew it or none exists (the event has no closed_form_error_m).
std::optional<ExactPath> exactPathOf(const Match& match, const GameEvent& landed,
                                     const std::string& model);

/// "explicit Euler, 30 Hz: 0.69 m long of the exact path; energy +1.5 %" ("short" when it
/// landed before, "on the exact path" when it rounds to 0.00 m).
std::string exactPathText(const ExactPath& path);

} // namespace game
