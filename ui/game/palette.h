// The colours the scene and the HUD share: text, panels, gold, the targets' paint and
// one colour per team, so shells, trails and HUD rows match their cannon.
#pragma once

#include "physics/debug_draw.h"

#include <cstddef>
#include <iterator>

namespace ui::palette {

using phys::Color;

inline constexpr Color kShell = Color::hex(0x1b1d21);
inline constexpr Color kPanel = Color::hex(0x0e1420, 0.8f);
inline constexpr Color kPanelEdge = Color::hex(0xffffff, 0.12f);
inline constexpr Color kText = Color::hex(0xf3efe6);
inline constexpr Color kTextDim = Color::hex(0xb9c2cf);
inline constexpr Color kGold = Color::hex(0xffc93c);
inline constexpr Color kNotice = Color::hex(0xffb27a); ///< a refused command: warm, not alarming
inline constexpr Color kTargetRed = Color::hex(0xd8322e);
inline constexpr Color kTargetWhite = Color::hex(0xf4f1ea);
inline constexpr Color kHit = Color::hex(0x8a8a8a);
inline constexpr Color kTeams[] = {Color::hex(0x3b82f6), Color::hex(0xef4444), Color::hex(0x22c55e),
                                   Color::hex(0xf59e0b), Color::hex(0xa855f7), Color::hex(0x14b8a6),
                                   Color::hex(0xec4899), Color::hex(0x84cc16)};

inline Color team(int i) { return kTeams[static_cast<std::size_t>(i) % std::size(kTeams)]; }

inline Color mix(Color a, Color b, float t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t,
            a.a + (b.a - a.a) * t};
}

inline Color darker(Color c, float f = 0.65f) { return {c.r * f, c.g * f, c.b * f, c.a}; }

} // namespace ui::palette
