#include "ui/game/editor_panels.h"

#include "game/material_names.h"
#include "game/weapons.h"
#include "physics/forces.h"
#include "physics/projectiles.h"
#include "ui/platform/imgui_layer.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace ui {

namespace {

using game::editor::Item;
using game::editor::ItemKind;

// ---- widgets on doubles ----------------------------------------------------------------
bool number(const char* label, double& value, double step, const char* format = "%.3f") {
    return ImGui::InputDouble(label, &value, step, step * 10.0, format);
}

bool point(const char* label, phys::Vec2& p) {
    double xy[2] = {p.x, p.y};
    const bool changed =
        ImGui::InputScalarN(label, ImGuiDataType_Double, xy, 2, nullptr, nullptr, "%.3f");
    if (changed) p = {xy[0], xy[1]};
    return changed;
}

bool integer(const char* label, int& value, int step = 1) {
    return ImGui::InputInt(label, &value, step, step * 10);
}

bool text(const char* label, std::string& value, std::size_t capacity = 81) {
    std::vector<char> buffer(std::max(capacity, value.size() + 1), '\0');
    std::memcpy(buffer.data(), value.data(), value.size());
    if (!ImGui::InputText(label, buffer.data(), buffer.size())) return false;
    value = buffer.data();
    return true;
}

/// A combo over `choices`; the value may be one the list lacks (shown as it is).
bool choice(const char* label, std::string& value, const std::vector<std::string>& choices) {
    bool changed = false;
    if (ImGui::BeginCombo(label, value.c_str())) {
        for (const std::string& c : choices)
            if (ImGui::Selectable(c.c_str(), c == value)) value = c, changed = true;
        ImGui::EndCombo();
    }
    return changed;
}

std::vector<std::string> splitNames(const std::string& list) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < list.size()) {
        std::size_t end = list.find(", ", start);
        if (end == std::string::npos) end = list.size();
        out.push_back(list.substr(start, end - start));
        start = end + 2;
    }
    return out;
}

/// Everything a cannon may offer: the weapons, then the plain projectile presets.
const std::vector<std::string>& projectileNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const game::Weapon& w : game::weapons())
            n.emplace_back(w.name);
        for (const phys::ProjectilePreset& p : phys::projectilePresets())
            n.emplace_back(p.name);
        return n;
    }();
    return names;
}

// ---- the level ---------------------------------------------------------------------------
bool modeCombo(game::Level& level) {
    std::string mode = game::modeName(level.mode);
    if (!choice("mode", mode, {"practice", "duel", "sandbox"})) return false;
    level.mode = mode == "duel"      ? game::Mode::Duel
                 : mode == "sandbox" ? game::Mode::Sandbox
                                     : game::Mode::Practice;
    return true;
}

bool physicsFields(game::LevelPhysics& p) {
    bool changed = number("gravity (m/s^2)", p.gravity, 0.1);
    ImGui::TextDisabled("planet:");
    for (const char* planet : {"earth", "moon", "mars", "jupiter"}) {
        ImGui::SameLine();
        if (ImGui::SmallButton(planet))
            p.gravity = *phys::gravityFromPlanet(planet), changed = true;
    }
    changed |= number("air density (kg/m^3)", p.airDensity, 0.05);
    changed |= ImGui::Checkbox("air drag on shells", &p.drag);
    changed |= number("wind min (m/s)", p.windMin, 0.5);
    changed |= number("wind max (m/s)", p.windMax, 0.5);
    dimWrapped("each turn draws the wind in [min, max]");
    changed |= ImGui::Checkbox("water", &p.water);
    if (p.water) changed |= number("water level (m)", p.waterLevel, 0.5);
    return changed;
}

// ---- the items -----------------------------------------------------------------------------
bool cannonFields(game::Cannon& c) {
    bool changed = point("position", c.position);
    changed |= number("angle (deg)", c.angleDeg, 1.0, "%.1f");
    changed |= number("speed (m/s)", c.speedMps, 1.0, "%.1f");
    changed |= number("max speed (m/s)", c.maxSpeedMps, 1.0, "%.1f");
    changed |= choice("player", c.player, {"1", "2", "cpu"});
    dimWrapped("weapons (count -1 = unlimited)");
    c.projectileCounts.resize(c.projectiles.size(), -1);
    for (std::size_t i = 0; i < c.projectiles.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        ImGui::SetNextItemWidth(panelPx(130));
        changed |= choice("##weapon", c.projectiles[i], projectileNames());
        ImGui::SameLine();
        ImGui::SetNextItemWidth(panelPx(70));
        changed |= ImGui::InputInt("##count", &c.projectileCounts[i], 0, 0);
        ImGui::SameLine();
        if (c.projectiles.size() > 1 && ImGui::SmallButton("x")) {
            c.projectiles.erase(c.projectiles.begin() + static_cast<long>(i));
            c.projectileCounts.erase(c.projectileCounts.begin() + static_cast<long>(i));
            changed = true;
            ImGui::PopID();
            break;
        }
        ImGui::PopID();
    }
    if (c.projectiles.size() < 16 && ImGui::SmallButton("+ weapon")) {
        c.projectiles.push_back("cannonball");
        c.projectileCounts.push_back(-1);
        changed = true;
    }
    return changed;
}

bool targetFields(game::Target& t) {
    const phys::Vec2 before = t.position;
    bool changed = point("position", t.position);
    if (changed) // a moving target's path goes with it, as when it is dragged
        for (phys::Vec2& p : t.path)
            p += t.position - before;
    changed |= number("radius (m)", t.radius, 0.1);
    changed |= integer("points", t.points, 10);
    if (!t.path.empty()) {
        ImGui::TextDisabled("moves along %zu waypoints", t.path.size());
        changed |= number("speed (m/s)", t.speedMps, 0.5);
    }
    return changed;
}

bool blockFields(game::Block& b) {
    static const std::vector<std::string> materials = splitNames(game::blockMaterialNames());
    bool changed = point("centre", b.position);
    changed |= point("size (w, h)", b.size);
    changed |= number("angle (deg)", b.angleDeg, 5.0, "%.1f");
    changed |= choice("material", b.material, materials);
    changed |= number("density (kg/m^3)", b.density, 50.0, "%.0f");
    changed |= ImGui::Checkbox("target (knock it off)", &b.target);
    return changed;
}

bool ropeFields(game::Rope& r) {
    bool changed = point("from", r.from);
    changed |= point("to", r.to);
    changed |= integer("links", r.segments);
    changed |= number("sag (of the span)", r.sag, 0.05);
    changed |= ImGui::Checkbox("pin from", &r.pinFrom);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("pin to", &r.pinTo);
    changed |= number("mass per link (kg)", r.massPerSegment, 0.1);
    changed |= integer("tie from to block", r.fromBlock);
    changed |= integer("tie to to block", r.toBlock);
    dimWrapped("a tie names a block by index (-1: none)");
    return changed;
}

bool blobFields(game::Blob& b) {
    bool changed = point("centre", b.center);
    changed |= number("radius (m)", b.radius, 0.1);
    changed |= integer("points", b.points);
    changed |= number("stiffness (N/m)", b.stiffness, 50.0, "%.0f");
    changed |= number("mass (kg)", b.mass, 0.5);
    changed |= ImGui::Checkbox("target (knock it off)", &b.target);
    return changed;
}

} // namespace

bool levelPropertiesPanel(game::Level& level) {
    bool changed = text("name", level.name);
    changed |= text("description", level.description, 400);
    changed |= text("lesson", level.lesson, 200);
    changed |= modeCombo(level);
    changed |= integer("shots", level.shots);
    long long seed = static_cast<long long>(level.seed);
    if (ImGui::InputScalar("seed", ImGuiDataType_S64, &seed)) {
        level.seed = static_cast<std::uint64_t>(std::max(0ll, seed));
        changed = true;
    }
    if (ImGui::TreeNodeEx("physics", ImGuiTreeNodeFlags_DefaultOpen)) {
        changed |= physicsFields(level.physics);
        ImGui::TreePop();
    }
    if (ImGui::TreeNode("world and ground")) {
        changed |= point("world min", level.worldMin);
        changed |= point("world max", level.worldMax);
        changed |= ImGui::Checkbox("blasts carve the ground", &level.terrain.destructible);
        changed |= text("ground material", level.terrain.material, 65);
        ImGui::TreePop();
    }
    return changed;
}

bool itemPropertiesPanel(game::Level& level, const Item& item) {
    const auto i = static_cast<std::size_t>(item.index);
    ImGui::PushID(static_cast<int>(item.kind) * 100000 + item.index);
    bool changed = false;
    switch (item.kind) {
    case ItemKind::TerrainPoint:
        changed = point("x, y", level.terrain.points[i]);
        break;
    case ItemKind::Cannon:
        changed = cannonFields(level.cannons[i]);
        break;
    case ItemKind::Target:
        changed = targetFields(level.targets[i]);
        break;
    case ItemKind::Block:
        changed = blockFields(level.blocks[i]);
        break;
    case ItemKind::Rope:
        changed = ropeFields(level.ropes[i]);
        break;
    case ItemKind::Blob:
        changed = blobFields(level.blobs[i]);
        break;
    case ItemKind::None:
        break;
    }
    ImGui::PopID();
    return changed;
}

} // namespace ui
