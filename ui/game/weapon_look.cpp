#include "ui/game/weapon_look.h"

#include "game/weapon_text.h"
#include "game/weapons.h"

#include "ui/platform/imgui_layer.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

namespace ui {

namespace {

using phys::Color;
using phys::Vec2;

enum class Mark { Dots, Ring, Band, Fuse, Fins, Skirt, Tip, Glue };

struct Look {
    const char* weapon;
    Color body;
    Mark mark;
};

// One row per weapon of game/weapons.cpp.
const Look kLooks[] = {
    {"cluster", Color::hex(0x8f4fd0), Mark::Dots}, {"bouncer", Color::hex(0xe0483a), Mark::Ring},
    {"roller", Color::hex(0x4a6a8a), Mark::Band},  {"grenade", Color::hex(0x4f6b2f), Mark::Fuse},
    {"mortar", Color::hex(0x8c2f39), Mark::Fins},  {"airburst", Color::hex(0xe8c23a), Mark::Skirt},
    {"digger", Color::hex(0x9a6a3a), Mark::Tip},   {"sticky", Color::hex(0x3fbf6a), Mark::Glue},
};

const Look* lookOf(const char* name) {
    if (!name) return nullptr;
    for (const Look& l : kLooks)
        if (std::strcmp(l.weapon, name) == 0) return &l;
    return nullptr;
}

void drawMark(Renderer2D& r, const game::Match& m, const Look& look, Vec2 p, Vec2 v, double rad) {
    const Vec2 dir = length(v) > 1e-9 ? v * (1.0 / length(v)) : Vec2{1.0, 0.0};
    const Vec2 side{-dir.y, dir.x};
    const game::Ammo& ammo = m.shellAmmo();
    r.fillCircle(p, rad, look.body);
    switch (look.mark) {
    case Mark::Dots: // the bomblets inside
        for (int k = 0; k < 4; ++k) {
            const double a = std::numbers::pi * (0.25 + 0.5 * k);
            r.fillCircle(p + Vec2{std::cos(a), std::sin(a)} * (0.45 * rad), 0.22 * rad,
                         Color::hex(0xf2e6ff));
        }
        break;
    case Mark::Ring:
        r.strokeCircle(p, rad * 1.25, Color::hex(0xffb0a0), 3.0f);
        break;
    case Mark::Band:
        r.line(p - side * rad, p + side * rad, Color::hex(0xd8e0e8), 3.0f);
        break;
    case Mark::Fuse: { // a ring that shrinks as the fuse burns down
        const double fuse = ammo.behaviour.fuseSeconds;
        const double left = fuse > 0.0 ? std::clamp(1.0 - m.flight().flown / fuse, 0.0, 1.0) : 1.0;
        r.strokeCircle(p, rad * (1.0 + 0.8 * left), Color::hex(0xffa030), 2.5f);
        r.fillCircle(p - dir * rad, 0.3 * rad, Color::hex(0xffe070));
        break;
    }
    case Mark::Fins:
        r.line(p - dir * rad, p - dir * (2.0 * rad) + side * rad, Color::hex(0x8a9099), 3.0f);
        r.line(p - dir * rad, p - dir * (2.0 * rad) - side * rad, Color::hex(0x8a9099), 3.0f);
        break;
    case Mark::Skirt: // the drag skirt, and the height it bursts at above the ground
        r.line(p - dir * rad + side * (1.4 * rad), p - dir * rad - side * (1.4 * rad),
               Color::hex(0xfff3b0), 3.0f);
        if (ammo.behaviour.airburstHeight > 0.0) {
            const double ground = m.terrain().heightAt(p.x);
            const Vec2 a{p.x, ground + ammo.behaviour.airburstHeight};
            r.line(a - Vec2{1.0, 0.0}, a + Vec2{1.0, 0.0}, Color::hex(0xe8c23a, 0.7f), 2.0f);
        }
        break;
    case Mark::Tip:
        r.triangle(p + dir * (2.0 * rad), p + side * rad, p - side * rad, Color::hex(0xd0d4d8),
                   Color::hex(0x80868c), Color::hex(0x80868c));
        break;
    case Mark::Glue:
        r.fillCircle(p, rad * 1.35, Color::hex(0x3fbf6a, 0.35f));
        if (m.flight().stuckTick) r.strokeCircle(p, rad * 1.6, Color::hex(0xffffff), 2.0f);
        break;
    }
}

} // namespace

void drawWeaponShell(Renderer2D& r, const game::Match& m, double radius) {
    const auto shell = m.shell();
    const Look* look = lookOf(m.shellAmmo().preset.name);
    if (!shell || !look || !m.shellAmmo().weapon) return;
    const phys::ParticleSet& ps = m.world().particles;
    drawMark(r, m, *look, ps.position(*shell), ps.velocity(*shell), radius);
    for (const phys::ParticleId f : m.flight().fragments)
        if (ps.alive(f)) drawMark(r, m, *look, ps.position(f), ps.velocity(f), 0.7 * radius);
}

std::string weaponHudLine(const game::Ammo& ammo) {
    const game::Weapon* w = ammo.preset.name ? game::weaponFromName(ammo.preset.name) : nullptr;
    return w ? w->summary : "";
}

namespace {

/// A ball's paint on its icon, by preset.
Color ballColour(const std::string& name) {
    if (name == "golf-ball") return Color::hex(0xf4f4f4);
    if (name == "tennis-ball") return Color::hex(0xd7e84a);
    if (name == "baseball") return Color::hex(0xf0ebe0);
    if (name == "billiard-ball") return Color::hex(0xd8322e);
    if (name == "steel-ball") return Color::hex(0xb8c0c8);
    if (name == "glass-marble") return Color::hex(0x7fc8e8);
    if (name == "hand-ball") return Color::hex(0x2f5fd0);
    if (name == "wooden-ball") return Color::hex(0x9a6b3f);
    return Color::hex(0x3a3f47); // the cannonball
}

ImU32 imColour(Color c, float alpha = 1.0f) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a * alpha));
}

/// One projectile's icon in a square at `lo`, `size` across: the shell in its paint with
/// its mark, as it flies.
void icon(ImDrawList* draw, ImVec2 lo, float size, const std::string& name, bool spent) {
    const ImVec2 c(lo.x + 0.5f * size, lo.y + 0.45f * size);
    const float r = 0.28f * size;
    const float alpha = spent ? 0.35f : 1.0f;
    const Look* look = lookOf(name.c_str());
    draw->AddCircleFilled(c, r, imColour(look ? look->body : ballColour(name), alpha), 24);
    draw->AddCircle(c, r, IM_COL32(0, 0, 0, 140), 24, 1.5f);
    if (!look) return;
    const ImU32 mark = IM_COL32(255, 255, 255, static_cast<int>(200 * alpha));
    switch (look->mark) {
    case Mark::Dots:
        for (int k = 0; k < 4; ++k) {
            const float a = static_cast<float>(std::numbers::pi * (0.25 + 0.5 * k));
            draw->AddCircleFilled(ImVec2(c.x + 0.45f * r * std::cos(a), c.y + 0.45f * r * std::sin(a)),
                                  0.2f * r, mark);
        }
        break;
    case Mark::Ring: draw->AddCircle(c, 1.25f * r, mark, 24, 2.0f); break;
    case Mark::Band: draw->AddLine(ImVec2(c.x, c.y - r), ImVec2(c.x, c.y + r), mark, 2.5f); break;
    case Mark::Fuse: draw->AddLine(ImVec2(c.x + 0.6f * r, c.y - 0.6f * r), ImVec2(c.x + r, c.y - 1.3f * r), IM_COL32(255, 170, 50, 255), 2.5f); break;
    case Mark::Fins:
        draw->AddLine(ImVec2(c.x - r, c.y), ImVec2(c.x - 1.7f * r, c.y - 0.8f * r), mark, 2.0f);
        draw->AddLine(ImVec2(c.x - r, c.y), ImVec2(c.x - 1.7f * r, c.y + 0.8f * r), mark, 2.0f);
        break;
    case Mark::Skirt: draw->AddLine(ImVec2(c.x - 1.3f * r, c.y + r), ImVec2(c.x + 1.3f * r, c.y + r), mark, 2.5f); break;
    case Mark::Tip: draw->AddTriangleFilled(ImVec2(c.x + 1.7f * r, c.y), ImVec2(c.x + 0.7f * r, c.y - 0.7f * r), ImVec2(c.x + 0.7f * r, c.y + 0.7f * r), mark); break;
    case Mark::Glue: draw->AddCircle(c, 1.3f * r, IM_COL32(63, 191, 106, static_cast<int>(160 * alpha)), 24, 3.0f); break;
    }
}

/// The bar's key for projectile `name`: its weapon's fixed number ("1" .. "8"), or Tab
/// for a ball.
std::string barKey(const std::string& name) {
    const auto key = game::keyOfProjectile(name);
    return key ? std::to_string(*key) : "Tab";
}

} // namespace

std::optional<std::size_t> projectileBar(const game::CannonState& c) {
    std::optional<std::size_t> chosen;
    const float size = panelPx(44);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    for (std::size_t i = 0; i < c.def.projectiles.size(); ++i) {
        const std::string& name = c.def.projectiles[i];
        const int left = i < c.ammoLeft.size() ? c.ammoLeft[i] : -1;
        const bool spent = left == 0;
        if (i > 0) ImGui::SameLine(0.0f, panelPx(4));
        ImGui::PushID(static_cast<int>(i));
        const ImVec2 lo = ImGui::GetCursorScreenPos();
        ImGui::BeginDisabled(spent);
        if (ImGui::InvisibleButton("projectile", ImVec2(size, size)) && i != c.projectile) chosen = i;
        ImGui::EndDisabled();
        const bool hovered = ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled);
        const ImVec2 hi(lo.x + size, lo.y + size);
        draw->AddRectFilled(lo, hi, i == c.projectile ? IM_COL32(60, 70, 96, 255)
                                    : hovered        ? IM_COL32(44, 52, 72, 255)
                                                     : IM_COL32(28, 34, 48, 255),
                            panelPx(5));
        if (i == c.projectile) draw->AddRect(lo, hi, IM_COL32(255, 201, 60, 255), panelPx(5), 0, 2.0f);
        icon(draw, lo, size, name, spent);
        // The key in the corner, the shots left in the other.
        // In a smaller type than the icon's, so "Tab" sits in the corner clear of the ball.
        const float keySize = 0.75f * ImGui::GetFontSize();
        draw->AddText(ImGui::GetFont(), keySize, ImVec2(lo.x + panelPx(3), lo.y + size - keySize - panelPx(1)),
                      IM_COL32(185, 194, 207, 255), barKey(name).c_str());
        if (left >= 0) {
            char count[16];
            std::snprintf(count, sizeof count, "x%d", left);
            const float w = ImGui::CalcTextSize(count).x;
            draw->AddText(ImVec2(hi.x - w - panelPx(3), lo.y + panelPx(1)), IM_COL32(243, 239, 230, 255), count);
        }
        if (hovered) {
            ImGui::BeginTooltip();
            ImGui::PushTextWrapPos(panelPx(380));
            ImGui::TextUnformatted(game::projectileLabel(c, i).c_str());
            ImGui::TextUnformatted(game::projectileDescription(name).c_str());
            ImGui::PopTextWrapPos();
            ImGui::EndTooltip();
        }
        ImGui::PopID();
    }
    return chosen;
}

std::optional<std::size_t> weaponByKey(const game::CannonState& c, int number, std::string& why) {
    const auto name = game::weaponOnKey(number);
    if (!name) return std::nullopt;
    for (std::size_t i = 0; i < c.def.projectiles.size(); ++i)
        if (c.def.projectiles[i] == *name) return i;
    why = "select: this level has no " + *name; // as the match refuses a select of it
    return std::nullopt;
}

std::optional<std::size_t> nextBall(const game::CannonState& c) {
    const std::size_t n = c.def.projectiles.size();
    bool anyBall = false;
    for (const std::string& name : c.def.projectiles) anyBall = anyBall || !game::weaponFromName(name);
    for (std::size_t k = 1; k <= n; ++k) {
        const std::size_t i = (c.projectile + k) % n;
        const bool ball = !game::weaponFromName(c.def.projectiles[i]);
        const bool spent = i < c.ammoLeft.size() && c.ammoLeft[i] == 0;
        if ((ball || !anyBall) && !spent && i != c.projectile) return i;
    }
    return std::nullopt;
}

} // namespace ui
