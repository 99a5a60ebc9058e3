#include "game/weapons.h"

#include <algorithm>

namespace game {

namespace {

using phys::ProjectilePreset;
namespace mat = phys::material;

Behaviour cluster() {
    Behaviour b;
    b.onImpact = OnImpact::Burst;
    b.apexFragments = 4;
    b.fragmentSpreadMps = 5.0;
    return b;
}
Behaviour bouncer() {
    Behaviour b;
    b.restitution = 0.9;
    b.burstAfterBounces = 3;
    b.burstAtRest = true; // should it come to rest first
    return b;
}
Behaviour roller() {
    Behaviour b;
    b.restitution = 0.05;
    b.friction = 0.05; // rolling resistance of a hard ball on earth
    b.burstAtRest = true;
    b.fuseSeconds = 12.0;
    return b;
}
Behaviour grenade() {
    Behaviour b;
    b.restitution = 0.5;
    b.fuseSeconds = 3.0;
    return b;
}
Behaviour shell() {
    Behaviour b;
    b.onImpact = OnImpact::Burst;
    return b;
}
Behaviour airburst() {
    Behaviour b = shell();
    b.airburstHeight = 5.0;
    return b;
}
Behaviour digger() {
    Behaviour b;
    b.onImpact = OnImpact::Dig;
    b.digLength = 10.0;
    b.digRadius = 1.0;
    return b;
}
Behaviour sticky() {
    Behaviour b;
    b.onImpact = OnImpact::Stick;
    b.restitution = 0.0;
    b.stickSeconds = 1.5;
    return b;
}

// Bodies: iron or steel shells (7200-7850 kg/m^3) except the light airburst shell
// (thin walled) and the rubber-skinned bouncer; Cd 0.47 for a smooth sphere (Hoerner),
// 0.2 for the finned mortar bomb, 1.1 for the airburst shell's drag skirt.
const Weapon kWeapons[] = {
    {"cluster", "splits into 4 bomblets at the top of its arc; each bursts where it lands",
     "apex: v_y = 0; fragments m/4 at v +/- 5 m/s, total momentum m v kept",
     ProjectilePreset{"cluster", mat::kSteelBearing, 6.0, 0.12, 0.47}, 2.5, 90.0, 1.5, cluster()},
    {"bouncer", "a rubber-skinned charge: bounces (e = 0.9) and bursts on its 3rd impact",
     "v_n' = -e v_n with e = 0.9; bursts at impact 3",
     ProjectilePreset{"bouncer", mat::kRubberBandBall, 0.5, 0.09, 0.47}, 3.0, 120.0, 2.0,
     bouncer()},
    {"roller", "lands softly (e = 0.05) and rolls along the ground; bursts when it stops",
     "a = -mu_r g cos(theta) - g sin(theta) along the ground, mu_r = 0.05",
     ProjectilePreset{"roller", mat::kSteelBearing, 3.0, 0.15, 0.47}, 3.0, 150.0, 2.0, roller()},
    {"grenade", "bounces (e = 0.5) until its 3 s fuse burns down, then bursts",
     "bursts at t = 3 s after firing, to the tick",
     ProjectilePreset{"grenade", mat::kSteelBearing, 0.6, 0.09, 0.47}, 3.5, 160.0, 2.5, grenade()},
    {"mortar", "a heavy finned bomb: 30 kg, Cd 0.2, flies almost as in vacuum",
     "drag a = rho Cd A v^2 / (2 m): k = rho Cd A / (2 m) = 8.2e-5 /m",
     ProjectilePreset{"mortar", mat::kSteelBearing, 30.0, 0.16, 0.2}, 5.0, 320.0, 3.5, shell()},
    {"airburst", "a light shell with a drag skirt: bursts 5 m above the ground on its way down",
     "k = rho Cd A / (2 m) = 0.0104 /m; bursts when y - ground(x) <= 5 m, v_y < 0",
     ProjectilePreset{"airburst", mat::kSteelBearing, 1.0, 0.14, 1.1}, 7.0, 120.0, 0.0, airburst()},
    {"digger", "a hardened tip: tunnels 10 m on along its path, then bursts",
     "tunnel from the impact point p0 to p0 + 10 m * v/|v|, 1 m wide",
     ProjectilePreset{"digger", mat::kSteelBearing, 8.0, 0.1, 0.3}, 3.0, 150.0, 2.0, digger()},
    {"sticky", "a sticky charge (e = 0): stops where it touches, bursts 1.5 s later",
     "e = 0 and no slip: v' = 0 at contact; bursts 1.5 s after",
     ProjectilePreset{"sticky", mat::kHollowHardPlastic, 1.5, 0.1, 0.47}, 3.0, 150.0, 2.0,
     sticky()},
};

} // namespace

std::span<const Weapon> weapons() {
    return kWeapons;
}

const Weapon* weaponFromName(std::string_view name) {
    for (const Weapon& w : kWeapons)
        if (name == w.name) return &w;
    return nullptr;
}

std::string weaponNameList() {
    std::string out;
    for (const Weapon& w : kWeapons)
        out += (out.empty() ? "" : ", ") + std::string(w.name);
    return out;
}

Ammo ammoOf(const Weapon& w) {
    Ammo a;
    a.preset = w.body;
    a.blastRadius = w.blastRadius;
    a.blastImpulse = w.blastImpulse;
    a.craterRadius = w.craterRadius;
    a.behaviour = w.behaviour;
    a.weapon = true;
    return a;
}

phys::MaterialId weaponMaterial(phys::MaterialTable& table, const Ammo& ammo) {
    if (const auto id = table.find(ammo.preset.name)) return *id;
    phys::Material m = table[ammo.preset.material];
    m.name = ammo.preset.name;
    if (ammo.behaviour.restitution >= 0.0) m.restitution = ammo.behaviour.restitution;
    if (ammo.behaviour.friction >= 0.0) {
        m.dynamicFriction = ammo.behaviour.friction;
        m.staticFriction = std::max(m.staticFriction, m.dynamicFriction);
    }
    return table.add(m).value_or(ammo.preset.material);
}

bool knownProjectile(std::string_view name) {
    return weaponFromName(name) != nullptr || phys::projectileFromName(name).has_value();
}

} // namespace game
