#include "ui/game/weapon_look.h"

#include "game/weapon_text.h"
#include "game/weapons.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
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

std::optional<std::size_t> projectilePicker(const game::CannonState& c) {
    std::optional<std::size_t> chosen;
    const std::string current = game::projectileLabel(c, c.projectile);
    if (ImGui::BeginCombo("projectile", current.c_str())) {
        for (std::size_t i = 0; i < c.def.projectiles.size(); ++i) {
            const bool spent = i < c.ammoLeft.size() && c.ammoLeft[i] == 0;
            ImGui::BeginDisabled(spent);
            if (ImGui::Selectable(game::projectileLabel(c, i).c_str(), i == c.projectile) &&
                i != c.projectile)
                chosen = i;
            ImGui::EndDisabled();
            if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
                ImGui::SetTooltip("%s", game::projectileDescription(c.def.projectiles[i]).c_str());
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s",
                          game::projectileDescription(c.def.projectiles[c.projectile]).c_str());
    return chosen;
}

} // namespace ui
