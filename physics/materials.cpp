#include "physics/materials.h"

#include <cmath>

namespace phys {

namespace {

// Built-in materials, in the order of the ids in materials.h.
//
// Restitution: Claypool's "Game Physics" lecture, the measured restitution of balls
// dropped from 92 cm onto a floor, e = sqrt(h/H). Baseball is not in its table: 0.546 is the centre of the
// Major League Baseball specification (0.546 +- 0.032, ball fired at 58 mi/h against
// a wall of ash boards). "earth" (packed soil, the terrain of the game) is a game
// value, not a measurement.
// Friction: the lecture gives none. The values are typical textbook magnitudes for the
// surface against a hard floor (rubber high, polished steel and glass low), chosen so
// static >= dynamic; they are game values, not measurements.
const Material kBuiltIn[] = {
    {"default", 0.5, 0.5, 0.4},
    {"floor", 1.0, 0.6, 0.5},             // the rigid reference floor of the drop tests
    {"perfectly-elastic", 1.0, 0.0, 0.0}, // e = 1: kinetic energy kept
    {"perfectly-plastic", 0.0, 0.6, 0.5}, // e = 0: no bounce at all
    {"golf", 0.858, 0.35, 0.25},
    {"tennis", 0.712, 0.6, 0.5},
    {"billiard", 0.804, 0.2, 0.15},
    {"hand-ball", 0.752, 0.8, 0.6},
    {"wooden", 0.603, 0.5, 0.4},
    {"steel-bearing", 0.597, 0.25, 0.2},
    {"glass-marble", 0.658, 0.2, 0.15},
    {"rubber-band-ball", 0.828, 0.9, 0.7},
    {"hollow-hard-plastic", 0.688, 0.35, 0.3},
    {"baseball", 0.546, 0.5, 0.4},
    {"earth", 0.3, 0.8, 0.6},
};

} // namespace

const RestitutionPreset kRestitutionPresets[11] = {
    {material::kGolf, "golf", 0.858},
    {material::kTennis, "tennis", 0.712},
    {material::kBilliard, "billiard", 0.804},
    {material::kHandBall, "hand-ball", 0.752},
    {material::kWooden, "wooden", 0.603},
    {material::kSteelBearing, "steel-bearing", 0.597},
    {material::kGlassMarble, "glass-marble", 0.658},
    {material::kRubberBandBall, "rubber-band-ball", 0.828},
    {material::kHollowHardPlastic, "hollow-hard-plastic", 0.688},
    {material::kPerfectlyElastic, "perfectly-elastic", 1.0},
    {material::kPerfectlyPlastic, "perfectly-plastic", 0.0},
};

std::string validate(const Material& m) {
    if (m.name.empty()) return "material name must not be empty";
    if (!(m.restitution >= 0.0 && m.restitution <= 1.0))
        return "material '" + m.name + "': restitution must be in [0, 1]";
    if (!(m.staticFriction >= 0.0) || !std::isfinite(m.staticFriction))
        return "material '" + m.name + "': static friction must be finite and >= 0";
    if (!(m.dynamicFriction >= 0.0 && m.dynamicFriction <= m.staticFriction))
        return "material '" + m.name + "': dynamic friction must be in [0, static friction]";
    return {};
}

MaterialTable::MaterialTable() : materials_(std::begin(kBuiltIn), std::end(kBuiltIn)) {
    rebuild();
}

PairProperties MaterialTable::combine(const Material& a, const Material& b) {
    return {a.restitution * b.restitution, std::sqrt(a.staticFriction * b.staticFriction),
            std::sqrt(a.dynamicFriction * b.dynamicFriction)};
}

std::optional<MaterialId> MaterialTable::add(const Material& m) {
    if (!validate(m).empty() || find(m.name) || materials_.size() >= 0xffff) return std::nullopt;
    materials_.push_back(m);
    rebuild();
    return static_cast<MaterialId>(materials_.size() - 1);
}

namespace {
bool samePair(const MaterialTable::Override& o, MaterialId a, MaterialId b) {
    return (o.a == a && o.b == b) || (o.a == b && o.b == a);
}
} // namespace

void MaterialTable::setPair(MaterialId a, MaterialId b, const PairProperties& p) {
    for (auto& o : overrides_)
        if (samePair(o, a, b)) {
            o.p = p;
            rebuild();
            return;
        }
    overrides_.push_back({a, b, p});
    rebuild();
}

void MaterialTable::clearPair(MaterialId a, MaterialId b) {
    std::erase_if(overrides_, [&](const Override& o) { return samePair(o, a, b); });
    rebuild();
}

const PairProperties* MaterialTable::pairOverride(MaterialId a, MaterialId b) const {
    for (const auto& o : overrides_)
        if (samePair(o, a, b)) return &o.p;
    return nullptr;
}

bool MaterialTable::setRestitution(MaterialId id, double e) {
    if (id >= materials_.size() || !(e >= 0.0 && e <= 1.0)) return false;
    materials_[id].restitution = e;
    rebuild(); // the dense pair table caches e_a e_b: the next contact must see the new e
    return true;
}

std::optional<MaterialId> MaterialTable::find(std::string_view name) const {
    for (std::size_t i = 0; i < materials_.size(); ++i)
        if (materials_[i].name == name) return static_cast<MaterialId>(i);
    return std::nullopt;
}

std::string MaterialTable::nameList() const {
    std::string out;
    for (const auto& m : materials_) {
        if (!out.empty()) out += ", ";
        out += m.name;
    }
    return out;
}

// The dense table makes pair() one load per contact; it is rebuilt only when the
// table changes, never during a step.
void MaterialTable::rebuild() {
    const std::size_t n = materials_.size();
    mixed_.assign(n * n, {});
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            mixed_[i * n + j] = combine(materials_[i], materials_[j]);
    for (const auto& o : overrides_) {
        if (o.a >= n || o.b >= n) continue;
        mixed_[o.a * n + o.b] = o.p;
        mixed_[o.b * n + o.a] = o.p;
    }
}

} // namespace phys
