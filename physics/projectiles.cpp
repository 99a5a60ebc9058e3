#include "physics/projectiles.h"

namespace phys {

namespace {

// Sources (published specifications and measurements):
// - cannonball: a 12-pounder round shot, 12 lb = 5.443 kg of cast iron; at 7200 kg/m^3
//   that is a 113 mm sphere (historical 12-pdr shot: 4.4-4.5 in). Its material is the
//   lecture's steel bearing (the nearest measured hard metal ball). Cd 0.47: smooth
//   sphere, subcritical Reynolds number (Hoerner, Fluid-Dynamic Drag, 1965); it rises
//   towards ~0.9 near Mach 1, which the game does not model.
// - golf ball: Rules of Golf (USGA/R&A): mass <= 45.93 g, diameter >= 42.67 mm.
//   Cd 0.25: dimpled ball at driver speeds (Bearman & Harvey, Golf ball aerodynamics,
//   Aeronautical Quarterly 27, 1976).
// - tennis ball: ITF Rules of Tennis, 56.0-59.4 g, 6.54-6.86 cm (mid values).
//   Cd 0.55: Mehta & Pallis, The aerodynamics of a tennis ball, Sports Engineering 4,
//   2001 (0.55-0.6 for new balls).
// - baseball: MLB Official Rules 3.01, 5-5.25 oz (142-149 g), 9-9.25 in circumference
//   (7.3-7.5 cm). Cd 0.35: Adair, The Physics of Baseball (0.3-0.5 over game speeds).
// - billiard ball: WPA equipment specifications, 2 1/4 in (57.15 mm), 156-170 g.
//   Cd 0.47 (smooth sphere).
// - steel ball: a 1 in (25.4 mm) bearing ball, 7850 kg/m^3 -> 67.4 g. Cd 0.47.
// - glass marble: a 5/8 in (15.9 mm) marble, soda-lime glass 2500 kg/m^3 -> 5.2 g.
//   Cd 0.47.
// - hand ball: USHA (American handball) ball, 1 7/8 in (47.6 mm), 2.3 oz (65 g).
//   Cd 0.47.
// - wooden ball: a 2 in (50.8 mm) hardwood ball, maple 700 kg/m^3 -> 48.0 g; its
//   material is the lecture's wooden ball. Cd 0.47. Last in the table, so the materials
//   made per preset before it keep their ids.
constexpr ProjectilePreset kPresets[] = {
    {"cannonball", material::kSteelBearing, 12.0 * 0.45359237, 0.113, 0.47}, // 12 lb
    {"golf-ball", material::kGolf, 0.04593, 0.04267, 0.25},
    {"tennis-ball", material::kTennis, 0.0577, 0.067, 0.55},
    {"baseball", material::kBaseball, 0.145, 0.074, 0.35},
    {"billiard-ball", material::kBilliard, 0.17, 0.05715, 0.47},
    {"steel-ball", material::kSteelBearing, 0.0674, 0.0254, 0.47},
    {"glass-marble", material::kGlassMarble, 0.0052, 0.0159, 0.47},
    {"hand-ball", material::kHandBall, 0.065, 0.0476, 0.47},
    {"wooden-ball", material::kWooden, 0.0480, 0.0508, 0.47},
};

} // namespace

std::span<const ProjectilePreset> projectilePresets() {
    return kPresets;
}

std::optional<ProjectilePreset> projectileFromName(std::string_view name) {
    for (const auto& p : kPresets)
        if (name == p.name) return p;
    return std::nullopt;
}

std::string projectileNameList() {
    std::string out;
    for (const auto& p : kPresets) {
        if (!out.empty()) out += ", ";
        out += p.name;
    }
    return out;
}

ParticleDef particleDef(const ProjectilePreset& p, Vec2 position, Vec2 velocity) {
    ParticleDef d;
    d.position = position;
    d.velocity = velocity;
    d.mass = p.mass;
    d.radius = 0.5 * p.diameter;
    d.dragCoefficient = p.dragCoefficient;
    d.material = p.material;
    return d;
}

} // namespace phys
