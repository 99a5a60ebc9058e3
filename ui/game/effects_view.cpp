#include "ui/game/effects_view.h"

#include <algorithm>
#include <cmath>

namespace ui {

using game::Effects;
using phys::Color;
using phys::Vec2;

namespace {

const Color kCrust = Color::hex(0x2a1c12);
const Color kScorch = Color::hex(0x15100c, 0.85f);
const Color kFlashCore = Color::hex(0xfff6d8);
const Color kFlashGlow = Color::hex(0xffa630);
const Color kSmoke = Color::hex(0x6b6b6b);
const Color kSpray = Color::hex(0xffffff);
const Color kSprayEdge = Color::hex(0x1d6fb0); ///< a darker rim, so spray reads over sky and water
const Color kGold = Color::hex(0xffc93c);
const Color kMissText = Color::hex(0xffffff);
/// The exact (closed-form) path after a shot an integrator flew: pale cyan, apart from the
/// trails and the white miss marker.
const Color kExactPath = Color::hex(0x9be7ff);
/// Colours by tint: earth, wood, stone, steel, water.
const Color kTints[] = {Color::hex(0x5a3e26), Color::hex(0xb07a45), Color::hex(0x8f8a80),
                        Color::hex(0x7d8791), Color::hex(0xd8f0ff)};

Color tintColor(std::uint8_t t) {
    return kTints[std::min<std::size_t>(t, std::size(kTints) - 1)];
}

} // namespace

void drawGroundMarks(Renderer2D& r, const Effects& fx, const game::Match& m) {
    const double px = r.camera().metres(1.0);
    const auto& ground = m.terrain().points();
    for (const game::CraterMark& c : fx.craters()) {
        // The carved edge: the ground's samples within the crater's reach, as a dark crust
        // over the grass band, and a scorched core where the charge went off.
        std::vector<Vec2> edge;
        for (const Vec2 p : ground)
            if (std::abs(p.x - c.center.x) <= c.radius * 1.25) edge.push_back(p);
        if (edge.size() > 1) {
            r.polyline(edge, kCrust, 9.0f);
            std::vector<Vec2> core;
            for (const Vec2 p : edge)
                if (std::abs(p.x - c.center.x) <= c.radius * 0.8)
                    core.push_back(p + Vec2{0.0, -1.5 * px});
            if (core.size() > 1) r.polyline(core, kScorch, 4.0f);
        }
    }
    // Scattered soil: a small clod where each piece came down.
    for (const game::Speck& s : fx.specks()) {
        const double h = std::max(s.size, 2.0 * px);
        const Vec2 q[] = {s.where + Vec2{-h, 0.0}, s.where + Vec2{h, 0.0},
                          s.where + Vec2{0.6 * h, 0.9 * h}, s.where + Vec2{-0.6 * h, 0.9 * h}};
        r.fillConvex(q, tintColor(0));
    }
}

void drawEffectsLayer(Renderer2D& r, const Effects& fx) {
    const double px = r.camera().metres(1.0);
    // Smoke first (behind the pieces), fading and spreading as it ages.
    for (const game::Smoke& s : fx.smoke()) {
        const double life = fx.def().smokeSeconds;
        const float a = static_cast<float>(0.45 * (1.0 - s.age / life));
        r.fillCircle(s.position, s.radius, kSmoke.withAlpha(a), 2.0f);
    }
    const phys::ParticleSet& ps = fx.pieces();
    for (std::size_t i = 0; i < ps.flags.size(); ++i) {
        if (!(ps.flags[i] & phys::kAlive)) continue;
        const auto id = static_cast<phys::ParticleId>(i);
        const Vec2 p{ps.px[i], ps.py[i]};
        const double h = std::max(ps.radius[i], 1.5 * px);
        const game::PieceKind kind = fx.kind(id);
        if (kind == game::PieceKind::Splinter) {
            // A spinning sliver: its angle turns with its age, each at its own rate.
            const double a =
                fx.pieceAge(id) * (6.0 + static_cast<double>(i % 7)) + static_cast<double>(i);
            const Vec2 d = Vec2{std::cos(a), std::sin(a)} * (2.5 * h);
            r.line(p - d, p + d, tintColor(fx.tint(id)), 2.0f);
            continue;
        }
        if (kind == game::PieceKind::Spray) {
            const double e = h + px;
            const Vec2 rim[] = {p + Vec2{-e, -e}, p + Vec2{e, -e}, p + Vec2{e, e}, p + Vec2{-e, e}};
            r.fillConvex(rim, kSprayEdge);
        }
        Color c = kind == game::PieceKind::Spray ? kSpray : tintColor(fx.tint(id));
        if (kind == game::PieceKind::Dust) c = Color::hex(0xa08c70, 0.7f);
        const Vec2 q[] = {p + Vec2{-h, -h}, p + Vec2{h, -h}, p + Vec2{h, h}, p + Vec2{-h, h}};
        r.fillConvex(q, c);
    }
    for (const game::Flash& f : fx.flashes()) {
        const double t = f.age / fx.def().flashSeconds; // 0 .. 1
        const auto fade = static_cast<float>(1.0 - t);
        r.fillCircle(f.where, f.radius * (0.7 + 0.6 * t), kFlashGlow.withAlpha(0.75f * fade), 6.0f);
        r.fillCircle(f.where, f.radius * 0.5 * (0.7 + 0.6 * t), kFlashCore.withAlpha(fade), 3.0f);
    }
    for (const game::Ripple& w : fx.ripples()) {
        const double t = w.age / 1.2;
        // Never under a few pixels, so a splash seen from far is still a splash.
        const double radius = (0.5 + 2.5 * t) * w.strength + 0.3;
        const auto minPx = static_cast<float>(5.0 + 18.0 * t);
        const auto fade = static_cast<float>(0.9 * (1 - t));
        r.strokeCircle(w.where, radius, kSprayEdge.withAlpha(fade), 4.0f, minPx);
        r.strokeCircle(w.where, radius, kSpray.withAlpha(fade), 2.0f, minPx);
    }
}

void drawShotFeedback(Renderer2D& r, const Effects& fx) {
    for (const game::ShotNote& n : fx.feedback().notes()) {
        const float fade = static_cast<float>(std::min(1.0, 3.0 * (1.0 - n.age / n.life)));
        switch (n.kind) {
        case game::ShotNote::Kind::Miss:
            // At the landing point, a marker; what it says is the HUD's verdict (hud.cpp), in
            // one place that covers nothing.
            r.strokeCircle(n.where, r.camera().metres(6.0), kMissText.withAlpha(0.8f * fade), 2.0f);
            break;
        case game::ShotNote::Kind::Verdict: // its text is the HUD's (hud.cpp)
            break;
        case game::ShotNote::Kind::Exact:
            // The exact path beside the flown one's trail, and where it met the ground; the
            // verdict (hud.cpp) says by how much they differ.
            if (const auto& exact = fx.feedback().exactPath()) {
                r.polyline(exact->points, kExactPath.withAlpha(0.85f * fade), 2.0f);
                r.strokeCircle(n.where, r.camera().metres(5.0), kExactPath.withAlpha(fade), 2.0f);
            }
            break;
        case game::ShotNote::Kind::Hit: {
            // A hit marker: four ticks around the point, opening as it fades.
            const double s = r.camera().metres(8.0 + 14.0 * n.age / n.life);
            const double k = r.camera().metres(7.0);
            for (const Vec2 d : {Vec2{1, 1}, Vec2{-1, 1}, Vec2{1, -1}, Vec2{-1, -1}}) {
                const Vec2 u = d * (1.0 / std::sqrt(2.0));
                r.line(n.where + u * s, n.where + u * (s + k), Color::hex(0xffffff, fade), 3.0f);
            }
            break;
        }
        }
    }
}

} // namespace ui
