// Section index
//   palette      colours of the scene and the HUD
//   camera       levelCamera
//   scenery      sky, hills, terrain, water, obstacles
//   things       blocks, ropes, blobs, particles, cannons, targets
//   effects      trails, preview, hint (the rest: ui/game/effects_view.cpp)
//   HUD          panels in pixel space, wind arrow, power bar, stars, results card
#include "ui/game/match_view.h"
#include "ui/game/weapon_look.h"

#include "game/ai.h"
#include "ui/game/effects_view.h"
#include "physics/integrators.h"
#include "physics/rigid/rigid_world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <unordered_map>

namespace ui {

namespace {

using game::Match;
using phys::Vec2;
constexpr double kDeg = std::numbers::pi / 180.0;

// ---- palette ------------------------------------------------------------------------
const Color kSkyTop = Color::hex(0x2f6db5);
const Color kSkyHorizon = Color::hex(0xcfe7f5);
const Color kMoonSkyTop = Color::hex(0x05060d);
const Color kMoonSkyHorizon = Color::hex(0x1d2236);
const Color kHillFar = Color::hex(0x9dbdb6);
const Color kHillNear = Color::hex(0x7aa58a);
const Color kGrass = Color::hex(0x5c9e3f);
const Color kGrassLight = Color::hex(0x8fd468);
const Color kSoilTop = Color::hex(0x7a5a3a);
const Color kSoilDeep = Color::hex(0x4a3423);
const Color kRegolith = Color::hex(0x9a9aa2);
const Color kRegolithDeep = Color::hex(0x4a4a52);
const Color kWater = Color::hex(0x2a7fc4, 0.55f);
const Color kWaterLine = Color::hex(0xbfe6ff, 0.9f);
const Color kSteel = Color::hex(0x5d6670);
const Color kSteelLight = Color::hex(0x9aa6b2);
const Color kIron = Color::hex(0x2b2f35);
const Color kWood = Color::hex(0x9a6b3f);
const Color kStone = Color::hex(0x9c978c);
const Color kRope = Color::hex(0xc9a86b);
const Color kBlob = Color::hex(0xe35d9b, 0.85f);
const Color kTargetRed = Color::hex(0xd8322e);
const Color kTargetWhite = Color::hex(0xf4f1ea);
const Color kHit = Color::hex(0x8a8a8a);
const Color kShell = Color::hex(0x1b1d21);
const Color kPreview = Color::hex(0xffffff, 0.85f);
const Color kHint = Color::hex(0xffcf3a);
const Color kPanel = Color::hex(0x0e1420, 0.8f);
const Color kPanelEdge = Color::hex(0xffffff, 0.12f);
const Color kText = Color::hex(0xf3efe6);
const Color kTextDim = Color::hex(0xb9c2cf);
const Color kGold = Color::hex(0xffc93c);
const Color kNotice = Color::hex(0xffb27a); ///< a refused command: warm, not alarming
/// One colour per cannon / player, so shells, trails and HUD rows match their cannon.
const Color kTeams[] = {Color::hex(0x3b82f6), Color::hex(0xef4444), Color::hex(0x22c55e),
                        Color::hex(0xf59e0b), Color::hex(0xa855f7), Color::hex(0x14b8a6),
                        Color::hex(0xec4899), Color::hex(0x84cc16)};
Color team(int i) { return kTeams[static_cast<std::size_t>(i) % std::size(kTeams)]; }

Color mix(Color a, Color b, float t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t,
            a.a + (b.a - a.a) * t};
}
Color darker(Color c, float f = 0.65f) { return {c.r * f, c.g * f, c.b * f, c.a}; }

bool lowGravity(const Match& m) { return m.world().def().forces.gravity.y > -5.0; }

// ---- pixel-space helpers for the HUD ---------------------------------------------------
/// The HUD is laid out in pixels; the renderer draws in world units, so convert.
/// The HUD is designed for 1280x720 and scaled by `u` to the picture, so a 640x360
/// frame shows the same layout at half size.
struct HudSpace {
    Renderer2D& r;
    double u = 1.0;
    Vec2 w(double x, double y) const { return r.camera().toWorld({x * u, y * u}); }
    double metres(double designPx) const { return r.camera().metres(designPx * u); }
    void rect(double x0, double y0, double x1, double y1, Color c) const {
        const Vec2 q[] = {w(x0, y1), w(x1, y1), w(x1, y0), w(x0, y0)};
        r.fillConvex(q, c);
    }
    /// A panel: a rectangle with its corners cut (one convex octagon, so a translucent
    /// fill never overlaps itself) and a faint top rim.
    void panel(double x0, double y0, double x1, double y1, Color c = kPanel) const {
        const double k = 5.0;
        const Vec2 q[] = {w(x0 + k, y1), w(x1 - k, y1), w(x1, y1 - k), w(x1, y0 + k),
                          w(x1 - k, y0), w(x0 + k, y0), w(x0, y0 + k), w(x0, y1 - k)};
        r.fillConvex(q, c);
        r.line(w(x0 + k, y0 + 0.5), w(x1 - k, y0 + 0.5), kPanelEdge, static_cast<float>(u));
    }
    void text(double x, double y, const std::string& s, Color c, float scale = 1.0f,
              float alignX = 0.0f) const {
        r.screenLabel({x * u, y * u}, s, c, scale * static_cast<float>(u), alignX);
    }
};

/// A five-pointed star (not convex: a pentagon and five triangles).
void star(Renderer2D& r, Vec2 c, double outer, Color fill) {
    const double inner = outer * 0.42;
    Vec2 o[5], in[5];
    for (int k = 0; k < 5; ++k) {
        const double a = std::numbers::pi / 2 + k * 2 * std::numbers::pi / 5;
        const double b = a + std::numbers::pi / 5;
        o[k] = c + Vec2{std::cos(a), std::sin(a)} * outer;
        in[k] = c + Vec2{std::cos(b), std::sin(b)} * inner;
    }
    r.fillConvex(in, fill);
    for (int k = 0; k < 5; ++k) {
        const Vec2 tri[] = {o[k], in[(k + 4) % 5], in[k]};
        r.fillConvex(tri, fill);
    }
}

// ---- scenery ----------------------------------------------------------------------------
void drawSky(Renderer2D& r, const Match& m, double groundTop) {
    const Camera& c = r.camera();
    const Vec2 lo = c.visibleMin(), hi = c.visibleMax();
    const bool space = lowGravity(m);
    const Color top = space ? kMoonSkyTop : kSkyTop, horizon = space ? kMoonSkyHorizon : kSkyHorizon;
    // The gradient runs from the ground to 1.5 screen heights up, so zooming shows more
    // of it rather than stretching it.
    const double gradientTop = groundTop + 1.2 * (hi.y - lo.y);
    r.fillRectGradient({lo.x, lo.y}, {hi.x, groundTop}, horizon, horizon);
    r.fillRectGradient({lo.x, groundTop}, {hi.x, gradientTop}, horizon, top);
    if (hi.y > gradientTop) r.fillRectGradient({lo.x, gradientTop}, {hi.x, hi.y}, top, top);
    const double span = hi.x - lo.x, height = hi.y - lo.y;
    if (space) {
        // Stars at fixed hashed places in the level (not the screen), and the Earth.
        for (int k = 0; k < 90; ++k) {
            const double fx = std::fmod(k * 0.6180339887, 1.0), fy = std::fmod(k * 0.7548776662, 1.0);
            const Vec2 p{lo.x + fx * span, groundTop + 0.15 * height + fy * 0.85 * height};
            r.point(p, k % 7 == 0 ? 2.5f : 1.5f, Color::hex(0xffffff, 0.55f + 0.4f * (k % 3) / 2.0f));
        }
        const Vec2 earth{lo.x + 0.8 * span, lo.y + 0.8 * height};
        const double er = 0.05 * height;
        r.fillCircle(earth, er * 1.15, Color::hex(0x6fb7ff, 0.18f));
        r.fillCircle(earth, er, Color::hex(0x2c6fc0));
        r.fillCircle(earth + Vec2{-0.3 * er, 0.2 * er}, 0.45 * er, Color::hex(0x4e9a4a));
        r.fillCircle(earth + Vec2{0.35 * er, -0.3 * er}, 0.3 * er, Color::hex(0x4e9a4a));
        return;
    }
    // Sun and clouds, placed relative to the view so every level has them.
    const Vec2 sun{lo.x + 0.12 * span, lo.y + 0.82 * height};
    const double sr = 0.045 * height;
    r.fillCircle(sun, sr * 1.9, Color::hex(0xfff4c2, 0.18f));
    r.fillCircle(sun, sr * 1.35, Color::hex(0xfff4c2, 0.3f));
    r.fillCircle(sun, sr, Color::hex(0xfff7d6));
    const double cloudX[] = {0.3, 0.55, 0.78, 0.93};
    const double cloudY[] = {0.8, 0.88, 0.76, 0.9};
    for (int k = 0; k < 4; ++k) {
        const Vec2 cl{lo.x + cloudX[k] * span, lo.y + cloudY[k] * height};
        const double s = 0.03 * height * (k % 2 ? 1.0 : 1.3);
        const Color white = Color::hex(0xffffff, 0.85f);
        r.fillCircle(cl + Vec2{-1.5 * s, -0.3 * s}, 0.8 * s, white);
        r.fillCircle(cl + Vec2{1.5 * s, -0.3 * s}, 0.85 * s, white);
        r.fillCircle(cl + Vec2{0.4 * s, 0.5 * s}, 1.0 * s, white);
        r.fillCircle(cl, 1.2 * s, white);
    }
}

/// Hills far behind the playfield: sums of sines, filled down to the ground's base.
void drawHills(Renderer2D& r, double base, double height, double phase, Color color) {
    const Camera& c = r.camera();
    const double x0 = c.visibleMin().x - 1.0, x1 = c.visibleMax().x + 1.0;
    const int n = 80;
    const double k = 2 * std::numbers::pi / (x1 - x0);
    Vec2 prev{};
    for (int i = 0; i <= n; ++i) {
        const double x = x0 + (x1 - x0) * i / n;
        const double y = base + height * (0.6 + 0.25 * std::sin(2.3 * k * x + phase) +
                                          0.15 * std::sin(5.1 * k * x + 2.0 * phase));
        const Vec2 p{x, y};
        if (i > 0) {
            const Vec2 quad[] = {{prev.x, base}, {p.x, base}, p, prev};
            r.fillConvex(quad, color);
        }
        prev = p;
    }
}

void drawTerrain(Renderer2D& r, const Match& m) {
    const Camera& c = r.camera();
    const double bottom = c.visibleMin().y - 1.0;
    const bool space = lowGravity(m);
    const Color top = space ? kRegolith : kSoilTop, deep = space ? kRegolithDeep : kSoilDeep;
    const double x0 = c.visibleMin().x - 1.0, x1 = c.visibleMax().x + 1.0;
    // The heightfield, continued flat beyond its ends so the view has no holes.
    const auto& field = m.terrain().points();
    std::vector<Vec2> pts;
    pts.reserve(field.size() + 2);
    if (x0 < field.front().x) pts.push_back({x0, field.front().y});
    for (const Vec2 p : field)
        if (p.x >= x0 - 1.0 && p.x <= x1 + 1.0) pts.push_back(p);
    if (x1 > field.back().x) pts.push_back({x1, field.back().y});
    // Soil: one quad per sample span, shaded from the surface down over 12 m.
    for (std::size_t i = 1; i < pts.size(); ++i) {
        const Vec2 a = pts[i - 1], b = pts[i];
        const double depth = 12.0;
        const Vec2 la{a.x, std::max(bottom, a.y - depth)}, lb{b.x, std::max(bottom, b.y - depth)};
        r.triangle(a, la, lb, top, deep, deep);
        r.triangle(a, lb, b, top, deep, top);
        if (la.y > bottom || lb.y > bottom) {
            const Vec2 q[] = {{a.x, bottom}, {b.x, bottom}, lb, la};
            r.fillConvex(q, deep);
        }
    }
    // The surface: a grass (or dust) band and a bright edge.
    r.polyline(pts, space ? Color::hex(0x6f6f78) : kGrass, 7.0f);
    r.polyline(pts, space ? Color::hex(0xc8c8d0) : kGrassLight, 2.0f);
}

void drawWater(Renderer2D& r, const Match& m) {
    const phys::ForceDef& f = m.world().def().forces;
    if (!f.water) return;
    const Camera& c = r.camera();
    const double wl = f.waterLevel;
    if (wl < c.visibleMin().y) return;
    // Water fills only what lies between the ground and the water line, span by span
    // (a span the surface crosses gets the part below it), so dry land stays dry.
    const auto& pts = m.terrain().points();
    const double t = m.time(); // waves move with simulated time, not wall time
    auto wave = [&](double x) { return wl + 0.12 * std::sin(0.6 * x + 1.7 * t); };
    for (std::size_t i = 1; i < pts.size(); ++i) {
        Vec2 a = pts[i - 1], b = pts[i];
        if (a.y >= wl && b.y >= wl) continue;
        if (a.y >= wl) a = a + (b - a) * ((a.y - wl) / (a.y - b.y));
        if (b.y >= wl) b = b + (a - b) * ((b.y - wl) / (b.y - a.y));
        r.triangle(a, b, {b.x, wl}, Color::hex(0x1c5f99, 0.7f), Color::hex(0x1c5f99, 0.7f), kWater);
        r.triangle(a, {b.x, wl}, {a.x, wl}, Color::hex(0x1c5f99, 0.7f), kWater, kWater);
        r.line({a.x, wave(a.x)}, {b.x, wave(b.x)}, kWaterLine, 2.0f);
    }
}

// Left and right of the level's bounds (a view zoomed or panned past them): shaded, the
// edge drawn, for nothing there is reached, spawned or scored. (Above and below, the sky
// and the soil say enough; the home view stays within the sides where it can.)
void drawOutsideTheLevel(Renderer2D& r, const Match& m) {
    const Camera& c = r.camera();
    const Vec2 lo = c.visibleMin(), hi = c.visibleMax();
    const double left = m.level().worldMin.x, right = m.level().worldMax.x;
    const Color shade = Color::hex(0x000000, 0.35f), edge = Color::hex(0xffffff, 0.35f);
    if (lo.x < left) {
        r.fillRectGradient(lo, {std::min(left, hi.x), hi.y}, shade, shade);
        if (left < hi.x) r.line({left, lo.y}, {left, hi.y}, edge, 1.5f);
    }
    if (hi.x > right) {
        r.fillRectGradient({std::max(right, lo.x), lo.y}, hi, shade, shade);
        if (right > lo.x) r.line({right, lo.y}, {right, hi.y}, edge, 1.5f);
    }
}

void drawObstacles(Renderer2D& r, const Match& m) {
    for (const game::Obstacle& o : m.level().obstacles) {
        switch (o.shape) {
        case game::Obstacle::Shape::Polyline:
            r.polyline(o.points, darker(kSteel, 0.8f), 8.0f);
            r.polyline(o.points, kSteelLight, 2.5f);
            break;
        case game::Obstacle::Shape::Polygon:
            r.fillConvex(o.points, kSteel);
            r.polyline(o.points, kSteelLight, 2.0f, true);
            break;
        case game::Obstacle::Shape::Circle:
            r.fillCircle(o.center, o.radius, kSteel);
            r.strokeCircle(o.center, o.radius, kSteelLight, 2.0f);
            break;
        }
    }
}

// ---- things -----------------------------------------------------------------------------
Color materialColor(const std::string& material) {
    if (material == "stone" || material == "concrete") return kStone;
    if (material == "steel" || material == "iron" || material == "metal") return kSteel;
    if (material == "ice" || material == "glass") return Color::hex(0xa9dcf2, 0.9f);
    if (material == "rubber") return Color::hex(0x39403a);
    return kWood;
}

void drawBlocks(Renderer2D& r, const Match& m) {
    std::unordered_map<std::uint64_t, const game::BlockState*> byBody;
    for (const game::BlockState& b : m.blocks())
        byBody[(std::uint64_t{b.body.index} << 32) | b.body.generation] = &b;
    m.rigid().forEachShape([&](const phys::RigidShapeView& s) {
        if (s.type == phys::BodyType::Static) return; // obstacles and terrain: drawn above
        const auto it = byBody.find((std::uint64_t{s.body.index} << 32) | s.body.generation);
        const game::BlockState* block = it == byBody.end() ? nullptr : it->second;
        Color fill = block ? materialColor(block->def.material) : kWood;
        if (block && block->toppled) fill = mix(fill, kHit, 0.6f);
        if (s.kind == phys::RigidShapeView::Kind::Polygon) {
            r.fillConvex(s.vertices, fill);
            // Planks read as wood: a lighter bevel inside the outline.
            r.polyline(s.vertices, darker(fill, 0.55f), 2.0f, true);
            if (block && block->def.target && !block->toppled) {
                Vec2 c{};
                for (Vec2 v : s.vertices) c = c + v;
                c = c * (1.0 / static_cast<double>(s.vertices.size()));
                const double rad = 0.3 * std::min(block->def.size.x, block->def.size.y);
                r.fillCircle(c, rad, kTargetWhite);
                r.fillCircle(c, rad * 0.6, kTargetRed);
            }
        } else if (s.kind == phys::RigidShapeView::Kind::Circle) {
            r.fillCircle(s.center, s.radius, fill);
            r.line(s.center, s.center + Vec2{std::cos(s.angle), std::sin(s.angle)} * s.radius,
                   darker(fill, 0.5f), 2.0f);
        }
    });
}

void drawRopes(Renderer2D& r, const Match& m) {
    const phys::World& w = m.world();
    const phys::ParticleSet& ps = w.particles;
    for (const phys::DistanceConstraint& c : w.constraints) {
        if (!ps.alive(c.a)) continue;
        const Vec2 b = c.b == phys::kNoParticle ? c.anchor : ps.position(c.b);
        r.line(ps.position(c.a), b, darker(kRope, 0.6f), 5.0f);
        r.line(ps.position(c.a), b, kRope, 2.5f);
    }
}

void drawBlobs(Renderer2D& r, const Match& m) {
    const phys::ParticleSet& ps = m.world().particles;
    for (const game::BlobState& b : m.blobs()) {
        if (!ps.alive(b.center)) continue;
        // The ring particles were added right after the centre (Match::buildWorld).
        const int n = b.def.points;
        const Vec2 c = ps.position(b.center);
        const Color fill = b.toppled ? mix(kBlob, kHit, 0.6f) : kBlob;
        std::vector<Vec2> ring;
        for (int i = 1; i <= n; ++i) {
            const auto id = b.center + static_cast<phys::ParticleId>(i);
            if (ps.alive(id)) ring.push_back(ps.position(id));
        }
        for (std::size_t i = 0; i < ring.size(); ++i) {
            const Vec2 tri[] = {c, ring[i], ring[(i + 1) % ring.size()]};
            r.fillConvex(tri, fill);
        }
        r.polyline(ring, darker(fill, 0.6f), 3.0f, true);
        // Eyes: it is a creature, and a face shows which way it is squashed.
        const double rad = b.def.radius;
        for (double sx : {-0.3, 0.3}) {
            r.fillCircle(c + Vec2{sx * rad, 0.25 * rad}, 0.16 * rad, kTargetWhite);
            r.fillCircle(c + Vec2{sx * rad + 0.04 * rad, 0.22 * rad}, 0.08 * rad, kIron);
        }
        if (b.def.target && !b.toppled) r.strokeCircle(c, rad * 1.25, kTargetRed, 2.0f);
    }
}

/// Particles that are not ropes, blobs or the shell: sandbox spawns and fragments.
void drawLooseParticles(Renderer2D& r, const Match& m, std::optional<phys::ParticleId> shell) {
    const phys::ParticleSet& ps = m.world().particles;
    std::vector<bool> owned(ps.slots(), false);
    for (const phys::DistanceConstraint& c : m.world().constraints) {
        if (c.a < owned.size()) owned[c.a] = true;
        if (c.b < owned.size()) owned[c.b] = true;
    }
    for (const game::BlobState& b : m.blobs())
        for (int i = 0; i <= b.def.points; ++i)
            if (b.center + static_cast<phys::ParticleId>(i) < owned.size())
                owned[b.center + static_cast<phys::ParticleId>(i)] = true;
    const double minR = r.camera().metres(2.0);
    for (std::size_t i = 0; i < ps.slots(); ++i) {
        if (!(ps.flags[i] & phys::kAlive) || owned[i]) continue;
        if (shell && *shell == i) continue;
        const Vec2 p{ps.px[i], ps.py[i]};
        const Color col = (ps.flags[i] & phys::kSleeping) ? Color::hex(0x7c8794)
                          : (ps.flags[i] & phys::kProjectile) ? Color::hex(0x3a3f47)
                                                              : Color::hex(0xe8b04a);
        r.fillCircle(p, std::max(ps.radius[i], minR), col);
    }
}

void drawCannon(Renderer2D& r, const Match& m, int index, double angleDeg, bool active) {
    const game::CannonState& cs = m.cannons()[static_cast<std::size_t>(index)];
    const Vec2 pivot = cs.def.position;
    const double ground = m.terrain().heightAt(pivot.x);
    const Color colour = cs.hitPoints <= 0 ? kHit : team(index);
    const double k = cannonDrawScale(r.camera());
    // A stone pedestal from the ground up to the pivot, so a cannon on a cliff stands on it.
    if (pivot.y - 0.6 * k > ground) {
        const Vec2 q[] = {{pivot.x - 1.0 * k, ground - 0.5}, {pivot.x + 1.0 * k, ground - 0.5},
                          {pivot.x + 0.75 * k, pivot.y - 0.5 * k}, {pivot.x - 0.75 * k, pivot.y - 0.5 * k}};
        r.fillConvex(q, kStone);
        r.polyline(q, darker(kStone, 0.6f), 1.5f, true);
        for (double y = ground + 1.5 * k; y < pivot.y - 0.8 * k; y += 1.5 * k)
            r.line({pivot.x - 0.85 * k, y}, {pivot.x + 0.85 * k, y}, darker(kStone, 0.75f), 1.0f);
    }
    const double a = angleDeg * kDeg;
    const Vec2 dir{std::cos(a), std::sin(a)}, side = phys::perp(dir);
    const Vec2 breech = pivot - dir * (0.45 * k), muzzle = pivot + dir * (1.5 * k);
    const Vec2 barrel[] = {breech + side * (0.36 * k), breech - side * (0.36 * k),
                           muzzle - side * (0.24 * k), muzzle + side * (0.24 * k)};
    r.fillConvex(barrel, kIron);
    const Vec2 band[] = {pivot + dir * (0.35 * k) + side * (0.33 * k), pivot + dir * (0.35 * k) - side * (0.33 * k),
                         pivot + dir * (0.6 * k) - side * (0.31 * k), pivot + dir * (0.6 * k) + side * (0.31 * k)};
    r.fillConvex(band, colour);
    const Vec2 ring[] = {muzzle - dir * (0.2 * k) + side * (0.31 * k), muzzle - dir * (0.2 * k) - side * (0.31 * k),
                         muzzle - side * (0.31 * k), muzzle + side * (0.31 * k)};
    r.fillConvex(ring, Color::hex(0x4a5058));
    r.fillCircle(breech, 0.36 * k, kIron);
    // Carriage (team colour) and wheel.
    const Vec2 carriage[] = {{pivot.x - 1.0 * k, pivot.y - 0.55 * k}, {pivot.x + 1.0 * k, pivot.y - 0.55 * k},
                             {pivot.x + 0.45 * k, pivot.y + 0.05 * k}, {pivot.x - 0.45 * k, pivot.y + 0.05 * k}};
    r.fillConvex(carriage, darker(colour, 0.8f));
    const Vec2 wheel{pivot.x, pivot.y - 0.35 * k};
    r.fillCircle(wheel, 0.5 * k, Color::hex(0x5a3d24));
    r.strokeCircle(wheel, 0.45 * k, Color::hex(0x2b1d12), 2.0f);
    r.fillCircle(wheel, 0.1 * k, kIron);
    if (active && !m.over()) r.strokeCircle(pivot, 2.2 * k, colour.withAlpha(0.6f), 2.5f);
    // Hit points in a duel: pips over the cannon.
    if (m.level().mode == game::Mode::Duel) {
        for (int p = 0; p < game::kCannonHitPoints; ++p) {
            const Vec2 at = pivot + Vec2{(p - 1) * 0.8 * k, 2.8 * k};
            r.fillCircle(at, 0.32 * k, Color::hex(0x111111, 0.6f));
            r.fillCircle(at, 0.24 * k, p < cs.hitPoints ? Color::hex(0x4ade80) : Color::hex(0x3f3f46));
        }
    }
}

void drawTarget(Renderer2D& r, const game::TargetState& t) {
    const Vec2 c = t.position;
    // Never under 6 px, so a far target is still a bullseye and not a dot.
    const double rad = std::max(t.def.radius, r.camera().metres(6.0));
    const bool moving = !t.def.path.empty();
    if (moving) {
        // Its rail, so the player can lead the shot.
        std::vector<Vec2> path{t.def.position};
        path.insert(path.end(), t.def.path.begin(), t.def.path.end());
        r.polyline(path, Color::hex(0xffffff, 0.35f), 2.0f);
    } else {
        r.line(c - Vec2{0.0, rad}, c - Vec2{0.0, rad * 1.8}, Color::hex(0x5a3d24), 3.0f);
    }
    const Color red = t.hit ? kHit : kTargetRed, white = t.hit ? Color::hex(0xc8c8c8) : kTargetWhite;
    r.fillCircle(c, rad, red);
    r.fillCircle(c, rad * 0.72, white);
    r.fillCircle(c, rad * 0.45, red);
    r.fillCircle(c, rad * 0.2, white);
    r.strokeCircle(c, rad, darker(red, 0.6f), 1.5f);
    if (t.hit) {
        r.line(c + Vec2{-rad, -rad} * 0.7, c + Vec2{rad, rad} * 0.7, Color::hex(0x444444), 3.0f);
        r.line(c + Vec2{-rad, rad} * 0.7, c + Vec2{rad, -rad} * 0.7, Color::hex(0x444444), 3.0f);
    }
}

// ---- HUD --------------------------------------------------------------------------------
std::string playerName(const Match& m, const MatchViewOptions& o, int i) {
    if (static_cast<std::size_t>(i) < o.playerNames.size()) return o.playerNames[static_cast<std::size_t>(i)];
    return defaultPlayerName(m.cannons()[static_cast<std::size_t>(i)].def.player);
}

void drawWindArrow(const HudSpace& s, double cx, double y, double wind) {
    char text[48];
    if (std::abs(wind) < 0.05)
        std::snprintf(text, sizeof text, "calm");
    else
        std::snprintf(text, sizeof text, "%.1f m/s %s", std::abs(wind), wind > 0 ? "->" : "<-");
    s.panel(cx - 90, y, cx + 90, y + 56);
    s.text(cx, y + 5, "WIND", kTextDim, 0.8f, 0.5f);
    // Arrow length grows with the wind up to 15 m/s.
    const double len = std::abs(wind) < 0.05 ? 0.0 : 24.0 + std::min(std::abs(wind), 15.0) / 15.0 * 100.0;
    const double sign = wind >= 0 ? 1.0 : -1.0;
    if (len > 1.0) {
        const Color c = std::abs(wind) > 8 ? Color::hex(0xff8a65) : Color::hex(0x9be7ff);
        s.r.arrow(s.w(cx - sign * len / 2, y + 29), s.w(cx + sign * len / 2, y + 29), c,
                  static_cast<float>(4.0 * s.u), static_cast<float>(13.0 * s.u));
    }
    s.text(cx, y + 36, text, kText, 0.85f, 0.5f);
}

void drawPowerBar(const HudSpace& s, double x, double y, double w, double fraction, Color colour,
                  std::optional<double> charge) {
    s.rect(x, y, x + w, y + 12, Color::hex(0x000000, 0.45f));
    const double f = std::clamp(fraction, 0.0, 1.0);
    // Green to red as power rises.
    const Color fill = mix(Color::hex(0x4ade80), Color::hex(0xef4444), static_cast<float>(f));
    s.rect(x + 2, y + 2, x + 2 + (w - 4) * f, y + 10, charge ? fill : mix(fill, colour, 0.3f));
    for (int k = 1; k < 4; ++k)
        s.rect(x + w * k / 4.0, y + 1, x + w * k / 4.0 + 1, y + 11, Color::hex(0xffffff, 0.25f));
}

void drawHud(Renderer2D& r, const Match& m, const MatchViewOptions& o, const PendingAim& aim) {
    const Camera& c = r.camera();
    const double u = hudScale(c.width, c.height);
    const HudSpace s{r, u};
    const double W = c.width / u, H = c.height / u; // the canvas in design pixels
    const game::CannonState& cs = m.cannon();
    const int cur = m.currentPlayer();
    const bool duel = m.level().mode == game::Mode::Duel;

    // Top left: level, mode, turn, score.
    s.panel(12, 12, 330, duel ? 112 : 96);
    s.text(24, 18, m.level().name, kText, 1.1f);
    char line[128];
    std::snprintf(line, sizeof line, "%s", game::modeName(m.level().mode));
    s.text(318, 21, line, kTextDim, 0.8f, 1.0f);
    if (duel) {
        for (int i = 0; i < static_cast<int>(m.cannons().size()) && i < 2; ++i) {
            const auto& ci = m.cannons()[static_cast<std::size_t>(i)];
            const double yy = 46 + 22 * i;
            r.fillCircle(s.w(30, yy + 9), s.metres(5), team(i));
            std::snprintf(line, sizeof line, "%s%s   HP %d", playerName(m, o, i).c_str(),
                          i == cur && !m.over() ? "  (to fire)" : "", ci.hitPoints);
            s.text(42, yy, line, i == cur ? kText : kTextDim, 0.9f);
        }
        std::snprintf(line, sizeof line, "shots fired %d", m.shotsFired());
        s.text(24, 90, line, kTextDim, 0.8f);
    } else if (m.sandbox()) {
        s.text(24, 44, "no score, no shot budget", kGold, 1.0f);
        std::snprintf(line, sizeof line, "shots fired %d   %zu particles   %zu blocks", m.shotsFired(),
                      m.world().particles.count(), m.blocks().size());
        s.text(24, 68, line, kText, 0.9f);
    } else {
        std::snprintf(line, sizeof line, "score %d / %d", m.score(), m.maxScore());
        s.text(24, 44, line, kGold, 1.0f);
        if (m.assisted()) s.text(318, 44, "assisted: 2 stars at most", kTextDim, 0.8f, 1.0f);
        std::snprintf(line, sizeof line, "shots left %d", cs.shotsLeft);
        s.text(24, 68, line, kText, 0.9f);
        // Shot pips.
        for (int k = 0; k < std::min(cs.shotsLeft, 12); ++k)
            r.fillCircle(s.w(140 + 14 * k, 77), s.metres(4.5), kShell.withAlpha(0.9f));
        for (int k = 0; k < std::min(cs.shotsLeft, 12); ++k)
            r.fillCircle(s.w(139 + 14 * k, 76), s.metres(1.6), Color::hex(0x9aa0aa));
    }

    drawWindArrow(s, W / 2, 12, m.wind());
    if (!o.banner.empty()) {
        // Wide enough for the line: the HUD font averages under 8 design px a character.
        const double half = std::max(120.0, 4.0 * static_cast<double>(o.banner.size()) + 14.0);
        s.panel(W / 2 - half, 76, W / 2 + half, 106, Color::hex(0x000000, 0.55f));
        s.text(W / 2, 81, o.banner, kGold, 1.0f, 0.5f);
    }

    // Bottom left: the aim of the cannon whose turn it is.
    const double y0 = H - 118;
    s.panel(12, y0, 330, H - 12);
    r.fillCircle(s.w(28, y0 + 18), s.metres(6), team(cur));
    s.text(40, y0 + 8, playerName(m, o, cur), kText, 1.0f);
    std::snprintf(line, sizeof line, "angle %.1f deg", aim.angleDeg);
    s.text(24, y0 + 34, line, kText, 0.95f);
    std::snprintf(line, sizeof line, "power %.1f / %.0f m/s", aim.speedMps, cs.def.maxSpeedMps);
    s.text(170, y0 + 34, line, kText, 0.95f);
    const double shown = o.charge ? *o.charge * cs.def.maxSpeedMps : aim.speedMps;
    drawPowerBar(s, 24, y0 + 60, 294, shown / cs.def.maxSpeedMps, team(cur), o.charge);
    const game::Ammo ammo = m.selectedAmmo();
    const int left = cs.projectile < cs.ammoLeft.size() ? cs.ammoLeft[cs.projectile] : -1;
    std::snprintf(line, sizeof line, "%zu/%zu  %s  %.3g kg  %.0f mm%s", cs.projectile + 1,
                  cs.def.projectiles.size(), ammo.preset.name ? ammo.preset.name : "?",
                  ammo.preset.mass, ammo.preset.diameter * 1000.0,
                  left >= 0 ? ("  x" + std::to_string(left)).c_str() : "");
    s.text(24, y0 + 80, line, kTextDim, 0.85f);
    if (ammo.weapon) s.text(24, y0 + 96, weaponHudLine(ammo), kTextDim, 0.75f);

    // Bottom right: the physics the shot is under (what the level teaches).
    const phys::WorldDef& d = m.world().def();
    std::snprintf(line, sizeof line, "g %.2f m/s^2   drag %s   %s %.0f Hz   t %.1f s",
                  -d.forces.gravity.y, d.forces.drag == phys::DragModel::None ? "off" : "on",
                  phys::info(d.integrator).name, 1.0 / d.tickSeconds, m.time());
    s.panel(W - 460, H - 40, W - 12, H - 12, Color::hex(0x0e1420, 0.55f));
    s.text(W - 24, H - 36, line, kTextDim, 0.8f, 1.0f);
    if (!o.notice.empty()) {
        s.panel(W - 460, H - 74, W - 12, H - 46, Color::hex(0x0e1420, 0.75f));
        s.text(W - 24, H - 70, o.notice, kNotice, 0.8f, 1.0f);
    }

    // The match is over: a results card with the stars.
    if (m.over()) {
        s.panel(W / 2 - 210, H / 2 - 110, W / 2 + 210, H / 2 + 80, Color::hex(0x0e1420, 0.85f));
        if (duel) {
            const int win = m.winner();
            const std::string who = win < 0 ? std::string("Draw") : playerName(m, o, win) + " wins!";
            s.text(W / 2, H / 2 - 90, who, win < 0 ? kText : team(win), 1.8f, 0.5f);
        } else {
            s.text(W / 2, H / 2 - 95, m.stars() > 0 ? "Level complete!" : "Out of shots", kText, 1.6f, 0.5f);
            for (int k = 0; k < 3; ++k) {
                const Vec2 p = s.w(W / 2 + (k - 1) * 70, H / 2 - 20);
                star(r, p, s.metres(30), Color::hex(0x000000, 0.4f));
                star(r, p, s.metres(26), k < m.stars() ? kGold : Color::hex(0x3a4150));
            }
            std::snprintf(line, sizeof line, "score %d / %d   shots %d", m.score(), m.maxScore(),
                          m.shotsFired());
            s.text(W / 2, H / 2 + 28, line, kText, 1.1f, 0.5f);
            if (m.assisted())
                s.text(W / 2, H / 2 + 52, "assisted (full preview or hint): no third star", kTextDim, 0.9f, 0.5f);
        }
    }
}

} // namespace

namespace {

/// The lowest point of what the player aims at or fires from (cannons, targets, blocks,
/// blobs), m; infinity where there is none.
double lowestThingStanding(const Match& m) {
    const game::Level& l = m.level();
    double lowest = INFINITY;
    for (const auto& c : m.cannons())
        lowest = std::min(lowest, c.def.position.y - game::kCannonRadius);
    for (const auto& t : m.targets())
        lowest = std::min(lowest, t.position.y - t.def.radius);
    for (const auto& b : l.blocks)
        lowest = std::min(lowest, b.position.y - 0.5 * b.size.y);
    for (const auto& b : l.blobs)
        lowest = std::min(lowest, b.center.y - b.radius);
    return lowest;
}

} // namespace

double coveredBottom(const PixelRect& panel, double width, double height) {
    if (!(height > 0.0)) return 0.0;
    double top = height - 118.0 * hudScale(width, height); // the aim readout's
    if (panel.y1 >= 0.9 * height) top = std::min(top, panel.y0);
    return std::clamp((height - top) / height, 0.0, 1.0);
}

double cannonDrawScale(const Camera& camera) {
    return std::max(1.0, 24.0 / (1.5 * camera.pixelsPerMetre));
}

Color teamColor(int index) { return team(index); }
Color targetRed() { return kTargetRed; }
Color targetWhite() { return kTargetWhite; }

std::string defaultPlayerName(const std::string& player) {
    if (player == "cpu") return "Computer";
    return "Player " + player;
}

// ---- camera -------------------------------------------------------------------------------
Camera levelCamera(const Match& m, int width, int height, double coveredBottom) {
    const game::Level& l = m.level();
    double ground = INFINITY, top = -INFINITY;
    for (const Vec2 p : m.terrain().points()) ground = std::min(ground, p.y), top = std::max(top, p.y);
    for (const auto& c : m.cannons()) top = std::max(top, c.def.position.y + 3.0);
    for (const auto& t : m.targets()) top = std::max(top, t.position.y + t.def.radius + 2.0);
    for (const auto& b : l.blocks) top = std::max(top, b.position.y + b.size.y + 2.0);
    for (const auto& o : l.obstacles)
        for (const Vec2 p : o.points) top = std::max(top, p.y + 2.0);
    // The width: from the leftmost to the rightmost thing to see, with room around them,
    // within the level's bounds.
    double left = INFINITY, right = -INFINITY;
    auto see = [&](Vec2 p) { left = std::min(left, p.x), right = std::max(right, p.x); };
    for (const auto& c : m.cannons()) see(c.def.position);
    for (const auto& t : m.targets()) {
        see(t.position);
        for (const Vec2 p : t.def.path) see(p);
    }
    for (const auto& b : l.blocks) see(b.position);
    for (const auto& r : l.ropes) see(r.from), see(r.to);
    for (const auto& b : l.blobs) see(b.center);
    const double margin = 0.08 * (right - left) + 8.0;
    const double xMin = std::max(l.worldMin.x, left - margin);
    const double xMax = std::min(l.worldMax.x, right + margin);
    const double aspect = static_cast<double>(height) / width;
    // The whole width of the level, with a band of soil under the lowest ground (the
    // bottom HUD sits on it) and the sky above for the arcs. When the things to see are
    // taller than the width allows, the height decides and the view is centred on x.
    // The soil is deeper where the panels along the bottom reach higher: what stands
    // lowest (a cannon, a target, a block, a blob: not a pit's floor) is 3 % of the
    // height above them.
    const double lowest = lowestThingStanding(m);
    const double clear = std::isfinite(coveredBottom) ? std::min(coveredBottom, 0.5) + 0.03 : 0.0;
    auto soilFor = [&](double visible) {
        const double standing = std::isfinite(lowest) ? std::max(0.0, lowest - ground) : 0.0;
        return std::max(0.22, clear - standing / visible);
    };
    const double widthHeight = (xMax - xMin) * aspect;
    double visibleHeight = widthHeight, soilFraction = 0.22;
    for (int pass = 0; pass < 2; ++pass) { // the soil sets the height, which sets the soil
        soilFraction = std::max(soilFraction, soilFor(visibleHeight));
        // Room for the things to see above the soil, whatever its depth.
        const double needed = std::max((top - ground) * 1.35 + soilFraction * widthHeight,
                                       (top - ground) / (1.0 - soilFraction));
        visibleHeight = std::max(widthHeight, needed);
    }
    Camera cam;
    cam.width = width;
    cam.height = height;
    cam.pixelsPerMetre = height / visibleHeight;
    const double bottom = ground - soilFraction * visibleHeight;
    cam.center = {0.5 * (xMin + xMax), bottom + 0.5 * visibleHeight};
    // A view wider than the things to see (the height decided) slides inside the level's
    // bounds where they are wide enough: what lies outside them cannot be reached (a
    // sandbox spawn there is refused), so it is not shown as if it were ground and sky.
    // [xMin, xMax] stays in view: it lies within the bounds and is no wider than the view.
    const double halfWidth = 0.5 * width / cam.pixelsPerMetre;
    if (l.worldMax.x - l.worldMin.x >= 2.0 * halfWidth)
        cam.center.x = std::clamp(cam.center.x, l.worldMin.x + halfWidth, l.worldMax.x - halfWidth);
    return cam;
}

// ---- MatchView ------------------------------------------------------------------------------
void MatchView::reset() {
    current_ = {};
    old_.clear();
    trailShell_ = phys::kNoParticle;
    trailShot_ = -1;
    effects_.reset();
    previewKey_ = hintKey_ = {};
    preview_.clear();
    hint_.reset();
    ghosts_.clear();
}

void MatchView::observe(const Match& m) {
    effects_.observe(m);
    if (ghostsShown_)
        ghosts_.observe(m.world());
    else
        ghosts_.clear();
    const auto shell = m.shell();
    if (!shell) {
        trailShell_ = phys::kNoParticle;
        return;
    }
    // A new shot: the previous trail joins the faded ones.
    if (m.shotsFired() != trailShot_) {
        if (current_.points.size() > 1) old_.push_back(std::move(current_));
        if (old_.size() > 3) old_.erase(old_.begin());
        current_ = {};
        current_.player = m.currentPlayer();
        trailShot_ = m.shotsFired();
    }
    trailShell_ = *shell;
    const Vec2 p = m.world().particles.position(*shell);
    if (current_.points.empty() || length(p - current_.points.back()) > 0.05)
        current_.points.push_back(p);
}

void MatchView::drawTrails(Renderer2D& r, const Match& m) {
    for (std::size_t i = 0; i < old_.size(); ++i) {
        const float a = 0.2f + 0.15f * static_cast<float>(i);
        r.polyline(old_[i].points, team(old_[i].player).withAlpha(a), 2.0f);
    }
    if (current_.points.size() > 1) {
        std::vector<Vec2> pts = current_.points;
        if (const auto shell = m.shell()) pts.push_back(m.world().particles.position(*shell));
        r.polyline(pts, Color::hex(0xffffff, 0.55f), 4.0f);
        r.polyline(pts, team(current_.player).withAlpha(0.9f), 2.0f);
    }
}

std::size_t launchArcPoints(const std::vector<Vec2>& path, double tickSeconds,
                            double metresPerPixel) {
    const double leastLength = kPreviewArcPixels * metresPerPixel;
    double run = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) {
        run += length(path[i] - path[i - 1]);
        if (static_cast<double>(i) * tickSeconds >= kPreviewArcSeconds && run >= leastLength)
            return i + 1;
    }
    return path.size();
}

void MatchView::drawPreview(Renderer2D& r, const Match& m, const PendingAim& aim, bool full) {
    const phys::WorldDef& d = m.world().def();
    const AimKey key{aim.angleDeg, aim.speedMps, m.wind(), d.forces.gravity.y, d.tickSeconds,
                     m.currentPlayer(), m.shotsFired(), static_cast<int>(d.integrator),
                     static_cast<int>(m.cannon().projectile), static_cast<int>(d.forces.drag)};
    if (!(key == previewKey_) || full != previewFull_) {
        // The launch arc alone unless the full path is asked for (an assist). Its length
        // on screen follows the zoom, so the path is kept long enough for any zoom and
        // cut where it is drawn.
        preview_ = full ? m.previewTrajectory(aim.angleDeg, aim.speedMps)
                        : m.previewTrajectory(aim.angleDeg, aim.speedMps, kPreviewArcMostSeconds);
        previewKey_ = key;
        previewFull_ = full;
    }
    const std::size_t shown =
        full ? preview_.size() : launchArcPoints(preview_, d.tickSeconds, r.camera().metres(1.0));
    // Dots every ~6 px of path, fading with distance, so it reads as a guide not a line.
    double run = 0.0, next = 0.0;
    const double spacing = r.camera().metres(9.0);
    for (std::size_t i = 1; i < shown; ++i) {
        run += length(preview_[i] - preview_[i - 1]);
        if (run < next) continue;
        next = run + spacing;
        const float fade =
            std::max(0.25f, 1.0f - static_cast<float>(i) / static_cast<float>(shown));
        r.point(preview_[i], 4.0f, kPreview.withAlpha(0.85f * fade));
    }
    if (!preview_.empty() && full) r.strokeCircle(preview_.back(), r.camera().metres(7.0), kPreview, 2.0f);
}

void MatchView::drawHint(Renderer2D& r, const Match& m) {
    const phys::WorldDef& d = m.world().def();
    // A moving target's lead changes as it moves: aimed anew every quarter second.
    const auto target = game::chooseTarget(m);
    const bool moving = target && game::movingTargetAt(m, *target);
    const AimKey key{0.0, 0.0, m.wind(), d.forces.gravity.y, d.tickSeconds, m.currentPlayer(),
                     m.shotsFired(), static_cast<int>(d.integrator),
                     static_cast<int>(m.cannon().projectile), static_cast<int>(d.forces.drag),
                     moving ? std::floor(m.time() / 0.25) : 0.0};
    if (!(key == hintKey_)) {
        hintKey_ = key;
        hint_.reset();
        if (target) {
            const game::AimSolution s = game::aimToFireNow(m, *target);
            if (std::isfinite(s.missM)) {
                hint_ = PendingAim{s.angleDeg, s.speedMps};
                hintExact_ = s.exact;
            }
        }
    }
    if (!hint_) return;
    const Vec2 pivot = m.cannon().def.position;
    const double a = hint_->angleDeg * kDeg;
    const Vec2 dir{std::cos(a), std::sin(a)};
    r.line(pivot, pivot + dir * 5.0, kHint.withAlpha(0.85f), 3.0f);
    r.fillCircle(pivot + dir * 5.0, r.camera().metres(4.0), kHint);
    char text[64];
    std::snprintf(text, sizeof text, "%s %.1f deg  %.1f m/s", hintExact_ ? "solution" : "best trial",
                  hint_->angleDeg, hint_->speedMps);
    r.label(pivot + dir * 5.0, text, kHint, {8.0, -8.0}, 0.85f);
}

void MatchView::draw(Renderer2D& r, const Match& m, const MatchViewOptions& o) {
    const game::CannonState& cs = m.cannon();
    const PendingAim aim = o.pending.value_or(PendingAim{cs.angleDeg, cs.speedMps});
    double groundTop = INFINITY;
    for (const Vec2 p : m.terrain().points()) groundTop = std::min(groundTop, p.y);

    drawSky(r, m, groundTop);
    if (!lowGravity(m)) {
        drawHills(r, groundTop - 2.0, 0.22 * (r.camera().visibleMax().y - groundTop), 0.7, kHillFar);
        drawHills(r, groundTop - 2.0, 0.12 * (r.camera().visibleMax().y - groundTop), 2.1, kHillNear);
    }
    drawTerrain(r, m);
    if (o.effects) drawGroundMarks(r, effects_, m);
    drawObstacles(r, m);
    drawRopes(r, m);
    drawBlocks(r, m);
    drawBlobs(r, m);
    for (const game::TargetState& t : m.targets()) drawTarget(r, t);

    const auto shell = m.shell();
    const bool aiming = !shell && !m.over();
    if (o.trails) drawTrails(r, m);
    if (aiming && o.trajectoryPreview) drawPreview(r, m, aim, o.fullPreview);
    if (aiming && o.solutionHint) drawHint(r, m);
    for (int i = 0; i < static_cast<int>(m.cannons().size()); ++i) {
        const bool active = i == m.currentPlayer();
        drawCannon(r, m, i, active ? aim.angleDeg : m.cannons()[static_cast<std::size_t>(i)].angleDeg,
                   active);
    }
    drawLooseParticles(r, m, shell);
    if (shell) {
        const phys::ParticleSet& ps = m.world().particles;
        const Vec2 p = ps.position(*shell);
        const double rad = std::max(ps.radius[*shell], r.camera().metres(4.0));
        r.fillCircle(p, rad * 1.6, Color::hex(0xffffff, 0.35f));
        r.fillCircle(p, rad, kShell);
        r.fillCircle(p + Vec2{-0.3, 0.3} * rad, rad * 0.35, Color::hex(0x8a9099));
        drawWeaponShell(r, m, rad);
    }
    drawWater(r, m);
    drawOutsideTheLevel(r, m);
    if (o.effects) {
        drawEffectsLayer(r, effects_);
        drawShotFeedback(r, effects_);
    }
    ghostsShown_ = o.overlays.ghosts;
    if (o.overlays.any()) {
        WorldDrawOptions w;
        w.overlays = o.overlays;
        w.pixel = r.camera().metres(1.0);
        w.minRadius = r.camera().metres(2.0); // as the loose particles are drawn
        w.ghosts = &ghosts_;
        w.rigid = &m.rigid();
        drawOverlays(r, m.world(), w);
    }
    if (o.hud) drawHud(r, m, o, aim);
}

} // namespace ui
