#include "game/settings.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <sstream>
#include <string_view>

namespace game {

namespace {

using K = SettingInfo::Kind;
const SettingInfo kSettings[] = {
    {"integrator", "", "integration method (explicit-euler ... implicit-euler)", K::Choice},
    {"tick_hz", "Hz", "fixed ticks per simulated second", K::Number, 10.0, 2000.0},
    {"substeps", "", "integration sub-steps per tick", K::Number, 1.0, 64.0},
    {"gravity", "m/s^2", "downward gravity", K::Number, 0.0, 1000.0},
    {"planet", "", "gravity preset: earth, moon, mars, jupiter", K::Choice},
    {"air_density", "kg/m^3", "air density for drag", K::Number, 0.0, 100.0},
    {"drag", "", "quadratic air drag on or off", K::Boolean},
    {"wind", "m/s", "horizontal wind speed (+ blows to the right)", K::Number, -100.0, 100.0},
    {"model", "", "auto: the closed form wherever only gravity acts; integrate: every particle "
                  "through the integrator", K::Choice},
    {"contact_model", "",
     "impulse: a bounce at the time of impact with the pair's e; penalty: a damped spring "
     "while overlapping, its damping ratio giving e; none: nothing collides",
     K::Choice},
    {"continuous", "",
     "continuous collision detection (swept spheres: nothing tunnels); off: overlap tests "
     "at the end of each step, so a fast small ball passes a thin wall",
     K::Boolean},
    {"restitution.PROJECTILE", "",
     "the projectile's e against the rigid floor (measured as e = sqrt(h/H)): one of the "
     "measured presets, or e itself",
     K::ChoiceOrNumber, 0.0, 1.0, "a preset name"},
    {"pair.MATERIAL.MATERIAL", "",
     "e of a pair of materials (a projectile's name means its own material) in place of "
     "the rule e_a e_b; \"combine\" gives the pair back to the rule",
     K::ChoiceOrNumber, 0.0, 1.0},
};

constexpr std::string_view kRestitution = "restitution.PROJECTILE";
constexpr phys::ContactModel kContactModels[] = {phys::ContactModel::Impulse,
                                                 phys::ContactModel::Penalty,
                                                 phys::ContactModel::None};

std::string join(const std::vector<std::string>& names, const char* quote = "") {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + (quote + n + quote);
    return out;
}

std::string rangeText(const SettingInfo& s) {
    std::ostringstream o;
    o << "[" << s.min << ", " << s.max << "]" << (*s.unit ? " " : "") << s.unit;
    return o.str();
}

bool isFamily(const SettingInfo& s) { return std::strchr(s.name, '.') != nullptr; }
/// "restitution." of "restitution.PROJECTILE".
std::string_view familyPrefix(const SettingInfo& s) {
    const std::string_view n = s.name;
    return n.substr(0, n.find('.') + 1);
}

const phys::MaterialTable& builtInMaterials() {
    static const phys::MaterialTable table;
    return table;
}

/// What a pair setting may name: every built-in material, then every projectile whose
/// name is not already one (its own material is made under its name).
std::vector<std::string> pairMaterialNames() {
    std::vector<std::string> out;
    const phys::MaterialTable& t = builtInMaterials();
    for (std::size_t i = 0; i < t.size(); ++i) out.push_back(t[static_cast<phys::MaterialId>(i)].name);
    for (const auto& p : phys::projectilePresets())
        if (!t.find(p.name)) out.emplace_back(p.name);
    return out;
}

/// A concrete setting: its table entry and, for a family, what the name picks.
struct Target {
    const SettingInfo* info = nullptr;
    std::optional<phys::ProjectilePreset> projectile; ///< restitution.PROJECTILE
    std::string a, b;                                 ///< pair.MATERIAL.MATERIAL
};

std::optional<Target> target(const std::string& name) {
    for (const auto& s : kSettings) {
        if (!isFamily(s)) {
            if (name == s.name) return Target{&s, std::nullopt, {}, {}};
            continue;
        }
        const std::string_view prefix = familyPrefix(s);
        if (!name.starts_with(prefix)) continue;
        const std::string rest = name.substr(prefix.size());
        Target t{&s, std::nullopt, {}, {}};
        if (s.name == kRestitution) {
            t.projectile = phys::projectileFromName(rest);
            return t.projectile ? std::optional(t) : std::nullopt;
        }
        const auto dot = rest.find('.');
        if (dot == std::string::npos) return std::nullopt;
        t.a = rest.substr(0, dot);
        t.b = rest.substr(dot + 1);
        const auto names = pairMaterialNames();
        const auto known = [&](const std::string& n) {
            return std::find(names.begin(), names.end(), n) != names.end();
        };
        return known(t.a) && known(t.b) ? std::optional(t) : std::nullopt;
    }
    return std::nullopt;
}

std::string unknownSetting(const std::string& name) {
    for (const auto& s : kSettings)
        if (isFamily(s) && name.starts_with(familyPrefix(s)))
            return "unknown setting \"" + name + "\": " + s.name + " takes " +
                   (s.name == kRestitution ? "a projectile (" + phys::projectileNameList() + ")"
                                           : "two materials (" + join(pairMaterialNames()) + ")");
    std::string known;
    for (const auto& k : kSettings) known += (known.empty() ? "" : ", ") + std::string(k.name);
    return "unknown setting \"" + name + "\" (settings: " + known + ")";
}

/// "" when `v` has the type and range `s` takes, else the refusal, from the table.
std::string check(const SettingInfo& s, const std::string& name, const SettingValue& v) {
    const double* d = std::get_if<double>(&v);
    const std::string* text = std::get_if<std::string>(&v);
    const bool number = d && std::isfinite(*d) && *d >= s.min && *d <= s.max;
    const auto named = [&] {
        const auto names = settingChoices(s);
        return text && std::find(names.begin(), names.end(), *text) != names.end();
    };
    bool ok = false;
    switch (s.kind) {
    case K::Number: ok = number; break;
    case K::Boolean: ok = std::holds_alternative<bool>(v); break;
    case K::Choice: ok = named(); break;
    case K::ChoiceOrNumber: ok = number || named(); break;
    }
    return ok ? "" : name + " expects " + expectation(s) + ", got " + describe(v);
}

/// A material by the name a pair setting uses; a projectile's own is made if missing.
phys::MaterialId materialId(phys::MaterialTable& t, const std::string& name) {
    if (const auto id = t.find(name)) return *id;
    return projectileMaterial(t, phys::projectileFromName(name).value());
}
phys::MaterialId materialId(const phys::MaterialTable& t, const std::string& name) {
    if (const auto id = t.find(name)) return *id;
    return projectileMaterial(t, phys::projectileFromName(name).value());
}

/// Sets a value that check() has passed.
std::string set(LiveSettings& s, const Target& t, const SettingValue& v) {
    const std::string_view n = t.info->name;
    phys::WorldDef& w = s.world;
    const double* d = std::get_if<double>(&v);
    const std::string* text = std::get_if<std::string>(&v);
    if (n == "integrator") w.integrator = phys::integratorFromName(*text).value();
    else if (n == "tick_hz") w.tickSeconds = 1.0 / *d;
    else if (n == "substeps") {
        if (*d != std::floor(*d)) return "substeps expects a whole number, got " + describe(v);
        w.substeps = static_cast<int>(*d);
    } else if (n == "gravity") w.forces.gravity = {0.0, -*d};
    else if (n == "planet") w.forces.gravity = {0.0, -phys::gravityFromPlanet(*text).value()};
    else if (n == "air_density") w.forces.airDensity = *d;
    else if (n == "drag") w.forces.drag = std::get<bool>(v) ? phys::DragModel::Quadratic : phys::DragModel::None;
    else if (n == "wind") w.forces.wind = {*d, 0.0};
    else if (n == "model") w.model = *text == "auto" ? phys::ModelPolicy::Auto : phys::ModelPolicy::Integrate;
    else if (n == "contact_model") {
        for (phys::ContactModel m : kContactModels)
            if (*text == phys::contactModelName(m)) w.collision.model = m;
    } else if (n == "continuous") w.collision.continuous = std::get<bool>(v);
    else if (n == kRestitution) {
        double e = d ? *d : 0.0;
        for (const auto& p : phys::kRestitutionPresets)
            if (text && *text == p.name) e = p.restitution;
        s.materials.setRestitution(projectileMaterial(s.materials, *t.projectile), e);
    } else { // pair.MATERIAL.MATERIAL
        const phys::MaterialId a = materialId(s.materials, t.a), b = materialId(s.materials, t.b);
        if (text) {
            s.materials.clearPair(a, b);
        } else {
            phys::PairProperties p = s.materials.pair(a, b); // keeps the pair's friction
            p.restitution = *d;
            s.materials.setPair(a, b, p);
        }
    }
    return "";
}

} // namespace

std::span<const SettingInfo> settings() { return kSettings; }

const SettingInfo* findSetting(const std::string& name) {
    const auto t = target(name);
    return t ? t->info : nullptr;
}

std::vector<std::string> settingChoices(const SettingInfo& s) {
    const std::string_view n = s.name;
    std::vector<std::string> out;
    if (n == "integrator") {
        for (const auto& i : phys::integrators()) {
            out.emplace_back(i.name);
            if (i.alias) out.emplace_back(i.alias);
        }
    } else if (n == "planet") {
        for (const auto& p : phys::kGravityPresets) out.emplace_back(p.name);
    } else if (n == "model") {
        for (auto m : {phys::ModelPolicy::Auto, phys::ModelPolicy::Integrate})
            out.emplace_back(phys::modelPolicyName(m));
    } else if (n == "contact_model") {
        for (phys::ContactModel m : kContactModels) out.emplace_back(phys::contactModelName(m));
    } else if (n == kRestitution) {
        for (const auto& p : phys::kRestitutionPresets) out.emplace_back(p.name);
    } else if (isFamily(s)) { // pair.MATERIAL.MATERIAL
        out.emplace_back("combine");
    }
    return out;
}

std::string expectation(const SettingInfo& s) {
    switch (s.kind) {
    case K::Number: return "a number in " + rangeText(s);
    case K::Boolean: return "true or false";
    case K::Choice: return "one of " + join(settingChoices(s));
    case K::ChoiceOrNumber:
        return (s.choiceNoun ? std::string(s.choiceNoun) + " (" + join(settingChoices(s)) + ")"
                             : join(settingChoices(s), "\"")) +
               " or a number in " + rangeText(s);
    }
    return "?";
}

std::vector<std::string> settingNames(const LiveSettings& s) {
    std::vector<std::string> out;
    for (const auto& k : kSettings) {
        if (!isFamily(k)) out.emplace_back(k.name);
        else if (k.name == kRestitution)
            for (const auto& p : phys::projectilePresets()) out.push_back("restitution." + std::string(p.name));
        else
            for (const auto& o : s.materials.overrides())
                out.push_back("pair." + s.materials[o.a].name + "." + s.materials[o.b].name);
    }
    return out;
}

std::string describe(const SettingValue& v) {
    if (auto d = std::get_if<double>(&v)) {
        std::ostringstream o;
        o << *d;
        return o.str();
    }
    if (auto b = std::get_if<bool>(&v)) return *b ? "true" : "false";
    return "\"" + std::get<std::string>(v) + "\"";
}

std::string applySetting(LiveSettings& s, const std::string& name, const SettingValue& value) {
    const auto t = target(name);
    if (!t) return unknownSetting(name);
    if (std::string why = check(*t->info, name, value); !why.empty()) return why;
    LiveSettings next = s;
    if (std::string why = set(next, *t, value); !why.empty()) return why;
    if (std::string why = phys::validate(next.world); !why.empty()) return why;
    s = std::move(next);
    return "";
}

std::string applySetting(phys::WorldDef& def, const std::string& name, const SettingValue& value) {
    LiveSettings s{def, {}};
    std::string why = applySetting(s, name, value);
    if (why.empty()) def = s.world;
    return why;
}

SettingValue readSetting(const LiveSettings& s, const std::string& name) {
    const auto t = target(name);
    if (!t) return std::string("?");
    const std::string_view n = t->info->name;
    const phys::WorldDef& def = s.world;
    if (n == "integrator") return std::string(phys::info(def.integrator).name);
    if (n == "tick_hz") return 1.0 / def.tickSeconds;
    if (n == "substeps") return static_cast<double>(def.substeps);
    if (n == "gravity") return -def.forces.gravity.y;
    if (n == "planet") {
        for (const auto& p : phys::kGravityPresets)
            if (-def.forces.gravity.y == p.g) return std::string(p.name);
        return std::string("custom");
    }
    if (n == "air_density") return def.forces.airDensity;
    if (n == "drag") return def.forces.drag != phys::DragModel::None;
    if (n == "wind") return def.forces.wind.x;
    if (n == "model") return std::string(phys::modelPolicyName(def.model));
    if (n == "contact_model") return std::string(phys::contactModelName(def.collision.model));
    if (n == "continuous") return def.collision.continuous;
    if (n == kRestitution) {
        const double e = s.materials[projectileMaterial(s.materials, *t->projectile)].restitution;
        for (const auto& p : phys::kRestitutionPresets)
            if (p.restitution == e) return std::string(p.name);
        return e;
    }
    const phys::PairProperties* own =
        s.materials.pairOverride(materialId(s.materials, t->a), materialId(s.materials, t->b));
    if (own) return own->restitution;
    return std::string("combine");
}

SettingValue readSetting(const phys::WorldDef& def, const std::string& name) {
    return readSetting(LiveSettings{def, {}}, name);
}

phys::MaterialId projectileMaterial(phys::MaterialTable& table, const phys::ProjectilePreset& p) {
    if (const auto id = table.find(p.name)) return *id;
    phys::Material m = table[p.material];
    m.name = p.name;
    return table.add(m).value_or(p.material);
}

phys::MaterialId projectileMaterial(const phys::MaterialTable& table, const phys::ProjectilePreset& p) {
    return table.find(p.name).value_or(p.material);
}

namespace {
/// `text` as lines of at most `width` characters (words are not split), each after `indent`.
std::string wrapped(const std::string& text, const std::string& indent, std::size_t width = 86) {
    std::istringstream words(text);
    std::string out, line, word;
    while (words >> word) {
        if (!line.empty() && indent.size() + line.size() + 1 + word.size() > width) {
            out += indent + line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    return out + indent + line + "\n";
}
} // namespace

std::string settingsHelp() {
    std::string out;
    for (const auto& s : kSettings)
        out += "  " + std::string(s.name) + (*s.unit ? std::string(" (") + s.unit + ")" : "") +
               "\n" + wrapped(s.help, "      ") + wrapped("takes " + expectation(s), "      ");
    return out;
}

} // namespace game
