// Section index
//   palette      colours of the scene (shared ones: ui/game/palette.h)
//   scenery      sky, hills, terrain, water, obstacles
//   things       blocks, ropes, blobs, particles, cannons, targets (cloth:
//                ui/game/cloth_view.cpp)
//   effects      trails, preview, hint (the rest: ui/game/effects_view.cpp)
//   layout       the objects the player must see, as drawn (the HUD: ui/game/hud.cpp;
//                the level's framing: ui/game/level_camera.cpp)
#include "ui/game/match_view.h"
#include "ui/game/weapon_look.h"

#include "game/ai.h"
#include "ui/game/cloth_view.h"
#include "ui/game/effects_view.h"
#include "ui/game/palette.h"
#include "ui/game/screen_layout.h"
#include "physics/integrators.h"
#include "physics/rigid/rigid_world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <unordered_map>

namespace ui {

namespace {

using namespace palette;
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
const Color kPreview = Color::hex(0xffffff, 0.85f);
const Color kHint = Color::hex(0xffcf3a);

bool lowGravity(const Match& m) { return m.world().def().forces.gravity.y > -5.0; }

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

/// Particles that are not ropes, blobs, cloth or the shell: sandbox spawns and fragments.
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
    markClothParticles(m, owned);
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
    const double rad = targetDrawRadius(t, r.camera());
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

} // namespace

double targetDrawRadius(const game::TargetState& t, const Camera& camera) {
    return std::max(t.def.radius, camera.metres(6.0));
}

double shellDrawRadius(double radius, const Camera& camera) {
    return std::max(radius, camera.metres(4.0));
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

// ---- MatchView ------------------------------------------------------------------------------
void MatchView::reset() {
    hud_.reset();
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
    drawCloths(r, m);
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
    if (aiming && o.rubberBand) {
        // The rubber band: from the cannon to the pointer, thicker the harder it pulls.
        const Vec2 pivot = cs.def.position, end = r.camera().toWorld(*o.rubberBand);
        const float pull = static_cast<float>(std::clamp(aim.speedMps / cs.def.maxSpeedMps, 0.0, 1.0));
        r.line(pivot, end, Color::hex(0x000000, 0.35f), 5.0f + 3.0f * pull);
        r.line(pivot, end, team(m.currentPlayer()).withAlpha(0.9f), 2.5f + 2.0f * pull);
        r.strokeCircle(end, r.camera().metres(7.0), Color::hex(0xffffff, 0.9f), 2.0f);
    }
    drawLooseParticles(r, m, shell);
    if (shell) {
        const phys::ParticleSet& ps = m.world().particles;
        const Vec2 p = ps.position(*shell);
        const double rad = shellDrawRadius(ps.radius[*shell], r.camera());
        r.fillCircle(p, rad * kShellGlow, Color::hex(0xffffff, 0.35f));
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
    addObjects(r, m, o);
    if (o.hud) hud_.draw(r, m, o, aim, effects_);
}

Vec2 turnedHalf(const game::Match& m, const game::BlockState& b) {
    const double a = m.rigid().state(b.body).angle;
    const double c = std::abs(std::cos(a)), s = std::abs(std::sin(a));
    const Vec2 h = 0.5 * b.def.size;
    return {c * h.x + s * h.y, s * h.x + c * h.y};
}

void MatchView::addObjects(const Renderer2D& r, const Match& m, const MatchViewOptions& o) const {
    if (!o.layout) return;
    const Camera& c = r.camera();
    auto add = [&](const char* kind, Vec2 lo, Vec2 hi) {
        const Vec2 a = c.toPixel({lo.x, hi.y}) + o.layoutOffset, b = c.toPixel({hi.x, lo.y}) + o.layoutOffset;
        PixelRect p{a.x, a.y, b.x, b.y};
        if (o.layoutClip) {
            if (!p.overlaps(*o.layoutClip)) return;
            p = {std::max(p.x0, o.layoutClip->x0), std::max(p.y0, o.layoutClip->y0),
                 std::min(p.x1, o.layoutClip->x1), std::min(p.y1, o.layoutClip->y1)};
        }
        o.layout->addObject(kind, o.layoutView, p);
    };
    for (const game::TargetState& t : m.targets()) {
        if (t.hit) continue;
        const double rad = targetDrawRadius(t, c);
        add("target", t.position - Vec2{rad, rad}, t.position + Vec2{rad, rad});
    }
    for (const game::BlockState& b : m.blocks()) {
        if (!b.def.target || b.toppled || !m.rigid().alive(b.body)) continue;
        const Vec2 p = m.rigid().state(b.body).position, h = turnedHalf(m, b);
        add("target", p - h, p + h);
    }
    for (const game::BlobState& b : m.blobs()) {
        if (!b.def.target || b.toppled || !m.world().particles.alive(b.center)) continue;
        const Vec2 p = m.world().particles.position(b.center);
        const double rad = 1.25 * b.def.radius;
        add("target", p - Vec2{rad, rad}, p + Vec2{rad, rad});
    }
    const double k = cannonDrawScale(c);
    const bool duel = m.level().mode == game::Mode::Duel;
    for (const game::CannonState& cs : m.cannons()) {
        const Vec2 p = cs.def.position;
        // The barrel turns about the pivot; the wheel hangs under it; a duel's pips over it.
        add("cannon", p - Vec2{1.6 * k, 0.9 * k}, p + Vec2{1.6 * k, duel ? 3.15 * k : 1.6 * k});
    }
    if (const auto shell = m.shell()) {
        const phys::ParticleSet& ps = m.world().particles;
        const double rad = kShellGlow * shellDrawRadius(ps.radius[*shell], c);
        add("shell", ps.position(*shell) - Vec2{rad, rad}, ps.position(*shell) + Vec2{rad, rad});
    }
    for (const game::Flash& f : effects_.flashes()) {
        if (f.age >= effects_.def().flashSeconds) continue;
        add("impact", f.where - Vec2{f.radius, f.radius}, f.where + Vec2{f.radius, f.radius});
    }
}

} // namespace ui
