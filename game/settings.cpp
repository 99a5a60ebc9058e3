#include "game/settings.h"

#include <cmath>
#include <sstream>

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
};

std::string rangeText(const SettingInfo& s) {
    std::ostringstream o;
    o << "[" << s.min << ", " << s.max << "]" << (*s.unit ? " " : "") << s.unit;
    return o.str();
}

} // namespace

std::span<const SettingInfo> settings() { return kSettings; }

const SettingInfo* findSetting(const std::string& name) {
    for (const auto& s : kSettings)
        if (name == s.name) return &s;
    return nullptr;
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

std::string applySetting(phys::WorldDef& def, const std::string& name, const SettingValue& value) {
    const SettingInfo* s = findSetting(name);
    if (!s) {
        std::string known;
        for (const auto& k : kSettings) known += (known.empty() ? "" : ", ") + std::string(k.name);
        return "unknown setting \"" + name + "\" (settings: " + known + ")";
    }
    phys::WorldDef next = def;
    switch (s->kind) {
    case K::Number: {
        const double* d = std::get_if<double>(&value);
        if (!d || !std::isfinite(*d) || *d < s->min || *d > s->max)
            return std::string(s->name) + " expects a number in " + rangeText(*s) + ", got " +
                   describe(value);
        const std::string n = s->name;
        if (n == "tick_hz") next.tickSeconds = 1.0 / *d;
        else if (n == "substeps") {
            if (*d != std::floor(*d)) return "substeps expects a whole number, got " + describe(value);
            next.substeps = static_cast<int>(*d);
        } else if (n == "gravity") next.forces.gravity = {0.0, -*d};
        else if (n == "air_density") next.forces.airDensity = *d;
        else if (n == "wind") next.forces.wind = {*d, 0.0};
        break;
    }
    case K::Boolean: {
        const bool* b = std::get_if<bool>(&value);
        if (!b) return std::string(s->name) + " expects true or false, got " + describe(value);
        next.forces.drag = *b ? phys::DragModel::Quadratic : phys::DragModel::None;
        break;
    }
    case K::Choice: {
        const std::string* t = std::get_if<std::string>(&value);
        const std::string n = s->name;
        if (n == "integrator") {
            auto id = t ? phys::integratorFromName(*t) : std::nullopt;
            if (!id)
                return "integrator expects one of " + phys::integratorNameList() + ", got " +
                       describe(value);
            next.integrator = *id;
        } else if (n == "model") {
            if (!t || (*t != "auto" && *t != "integrate"))
                return "model expects \"auto\" or \"integrate\", got " + describe(value);
            next.model = *t == "auto" ? phys::ModelPolicy::Auto : phys::ModelPolicy::Integrate;
        } else if (n == "planet") {
            auto g = t ? phys::gravityFromPlanet(*t) : std::nullopt;
            if (!g) return "planet expects one of earth, moon, mars, jupiter, got " + describe(value);
            next.forces.gravity = {0.0, -*g};
        }
        break;
    }
    }
    if (std::string why = phys::validate(next); !why.empty()) return why;
    def = next;
    return "";
}

SettingValue readSetting(const phys::WorldDef& def, const std::string& name) {
    if (name == "integrator") return std::string(phys::info(def.integrator).name);
    if (name == "tick_hz") return 1.0 / def.tickSeconds;
    if (name == "substeps") return static_cast<double>(def.substeps);
    if (name == "gravity") return -def.forces.gravity.y;
    if (name == "planet") {
        for (const auto& p : phys::kGravityPresets)
            if (-def.forces.gravity.y == p.g) return std::string(p.name);
        return std::string("custom");
    }
    if (name == "air_density") return def.forces.airDensity;
    if (name == "drag") return def.forces.drag != phys::DragModel::None;
    if (name == "wind") return def.forces.wind.x;
    if (name == "model") return std::string(phys::modelPolicyName(def.model));
    return std::string("?");
}

} // namespace game
