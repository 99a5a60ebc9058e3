#include "ui/render/world_view.h"

#include "physics/rigid/rigid_world.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace ui {

using phys::Color;
using phys::Vec2;

void PositionSnapshot::capture(const phys::ParticleSet& set) {
    x = set.px;
    y = set.py;
    flags = set.flags;
}

Color particleColor(std::uint32_t flags, double invMass) {
    if (invMass == 0.0) return Color::hex(0x8a9099);          // fixed: anchors, walls
    if (flags & phys::kSleeping) return Color::hex(0x6c7fa3); // asleep: skipped by the step
    if (flags & phys::kProjectile)
        return (flags & phys::kNoDrag) ? Color::hex(0xe8f0ff, 0.85f) // vacuum reference shot
                                       : Color::hex(0xff8a1e);       // shell in the air
    if (flags & phys::kAttractor) return Color::hex(0xb07cf0);
    return Color::hex(0x3fb6c9);
}

Color springColor(double strain) {
    const Color rest = Color::hex(0xc9ccd2), stretched = Color::hex(0xe8473a),
                squeezed = Color::hex(0x3a7de8);
    // Full colour at 10 % strain: visible long before anything breaks.
    const float t = static_cast<float>(std::min(std::abs(strain) / 0.1, 1.0));
    const Color& to = strain > 0.0 ? stretched : squeezed;
    return {rest.r + (to.r - rest.r) * t, rest.g + (to.g - rest.g) * t,
            rest.b + (to.b - rest.b) * t, 1.0f};
}

Color modelColor(phys::ParticleModel model) {
    switch (model) {
    case phys::ParticleModel::ClosedForm: return Color::hex(0x3ce070); // exact, O(1)
    case phys::ParticleModel::Integrated: return Color::hex(0xff9b21);
    case phys::ParticleModel::Sleeping: return Color::hex(0x7d9bff);
    case phys::ParticleModel::Fixed: return Color::hex(0xb4bac2);
    }
    return Color::hex(0xffffff);
}

Vec2 drawnPosition(const phys::ParticleSet& set, std::size_t i, const WorldDrawOptions& o) {
    const Vec2 now{set.px[i], set.py[i]};
    const PositionSnapshot* prev = o.previous;
    // A slot that was dead (or reused) in the previous tick has nothing to blend from.
    if (!prev || i >= prev->x.size() || !(prev->flags[i] & phys::kAlive)) return now;
    const Vec2 before{prev->x[i], prev->y[i]};
    return before + (now - before) * o.alpha;
}

namespace {

bool finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

/// An arrow from segments, so any DebugDraw can show it; its head is at most `headMax` m.
/// A `clipped` arrow (longer than it is drawn) gets a second head behind the first.
void arrow(phys::DebugDraw& draw, Vec2 from, Vec2 to, Color color, double headMax,
           bool clipped = false) {
    const Vec2 d = to - from;
    const double len = phys::length(d);
    if (!(len > 1e-9) || !finite(from) || !finite(to)) return;
    const Vec2 u = d / len;
    const double head = std::min(0.3 * len, headMax);
    draw.segment(from, to, color);
    for (const Vec2 tip : {to, to - u * (0.6 * head)}) {
        draw.segment(tip, tip - u * head + phys::perp(u) * (0.5 * head), color);
        draw.segment(tip, tip - u * head - phys::perp(u) * (0.5 * head), color);
        if (!clipped) break;
    }
}

/// A "z" of half-size h centred at c: the sleeping marker.
void sleepMark(phys::DebugDraw& draw, Vec2 c, double h) {
    const Vec2 tl = c + Vec2{-h, h}, tr = c + Vec2{h, h}, bl = c + Vec2{-h, -h},
               br = c + Vec2{h, -h};
    draw.segment(tl, tr, kOverlaySleep);
    draw.segment(tr, bl, kOverlaySleep);
    draw.segment(bl, br, kOverlaySleep);
}

bool alive(const phys::ParticleSet& s, std::size_t i) { return (s.flags[i] & phys::kAlive) != 0; }

void drawCells(phys::DebugDraw& draw, const phys::World& world) {
    const phys::CollisionDef& def = world.def().collision;
    if (def.model == phys::ContactModel::None || def.broadPhase != phys::BroadPhase::Grid) return;
    phys::OccupiedCells cells;
    phys::occupiedCells(world.particles, def, cells);
    const double s = cells.cellSize;
    for (const phys::GridCell& c : cells.cells) {
        const double x0 = static_cast<double>(c.x) * s, y0 = static_cast<double>(c.y) * s;
        const std::array<Vec2, 4> q{Vec2{x0, y0}, Vec2{x0 + s, y0}, Vec2{x0 + s, y0 + s},
                                    Vec2{x0, y0 + s}};
        if (finite(q[0]) && finite(q[2])) draw.polygon(q, kOverlayCell);
    }
}

/// Sleeping shade and marker, and the model outline, of every Box2D body.
void drawBodies(phys::DebugDraw& draw, const phys::RigidWorld& rigid, const DebugOverlays& o,
                double px) {
    rigid.forEachShape([&](const phys::RigidShapeView& s) {
        if (s.type == phys::BodyType::Static) return; // terrain and walls: not a model
        Vec2 centre = s.center;
        if (s.kind == phys::RigidShapeView::Kind::Polygon && !s.vertices.empty()) {
            centre = {};
            for (const Vec2 v : s.vertices) centre += v;
            centre = centre / static_cast<double>(s.vertices.size());
        }
        if (!finite(centre)) return;
        const bool asleep = !s.awake;
        const bool polygon = s.kind == phys::RigidShapeView::Kind::Polygon;
        const bool circle = s.kind == phys::RigidShapeView::Kind::Circle;
        if (o.sleeping && asleep) {
            if (polygon) draw.solidPolygon(s.vertices, kOverlaySleepShade);
            if (circle) draw.solidCircle(s.center, s.radius, {}, kOverlaySleepShade);
            sleepMark(draw, centre, 5.0 * px);
        }
        if (o.models) {
            const Color c = asleep ? kOverlayRigidAsleep : kOverlayRigidAwake;
            if (polygon) draw.polygon(s.vertices, c);
            if (circle) draw.circle(s.center, s.radius + 1.5 * px, c);
        }
    });
}

void drawGhosts(phys::DebugDraw& draw, const phys::World& world, const WorldDrawOptions& o) {
    if (!o.ghosts) return;
    const phys::ParticleSet& set = world.particles;
    // The time the particles are drawn at: between the last two ticks when blending.
    const double t = world.time() - (o.previous ? (1.0 - o.alpha) * world.def().tickSeconds : 0.0);
    int followed = 0;
    for (std::size_t i = 0; i < set.slots(); ++i)
        followed += o.ghosts->launch(static_cast<phys::ParticleId>(i)) ? 1 : 0;
    for (std::size_t i = 0; i < set.slots(); ++i) {
        const auto id = static_cast<phys::ParticleId>(i);
        const auto launch = o.ghosts->launch(id);
        if (!launch || !alive(set, i)) continue;
        const auto ghost = o.ghosts->at(id, t);
        const Vec2 p = drawnPosition(set, i, o);
        if (!ghost || !finite(ghost->position) || !finite(p)) continue;
        // The exact parabola from the launch to now, then the ghost, then the error.
        constexpr int kSegments = 40;
        const double span = t - launch->time;
        Vec2 prev = launch->position;
        for (int k = 1; span > 0.0 && k <= kSegments; ++k) {
            const Vec2 next = phys::ballisticState(launch->position, launch->velocity,
                                                   o.ghosts->gravity(), span * k / kSegments)
                                  .position;
            if (!finite(next)) break;
            draw.segment(prev, next, kOverlayGhostPath);
            prev = next;
        }
        // At least as big on screen as a shell is drawn (4 px), so it reads when zoomed out.
        const double r = std::max({set.radius[i], o.minRadius, 4.0 * o.pixel});
        draw.solidCircle(ghost->position, r, {}, kOverlayGhostPath);
        draw.circle(ghost->position, r, kOverlayGhost);
        const double error = phys::length(p - ghost->position);
        if (error > o.pixel) draw.segment(ghost->position, p, kOverlayGhostError);
        if (followed <= 6) { // a few shells get their error written beside them
            char text[32];
            std::snprintf(text, sizeof text, "%.3g m", error);
            // Below and right of the ghost, clear of the velocity arrow ahead of the shell.
            draw.text(ghost->position + Vec2{r + 4.0 * o.pixel, -r - 2.0 * o.pixel}, text,
                      kOverlayGhost);
        }
    }
}

} // namespace

void drawOverlays(phys::DebugDraw& draw, const phys::World& world, const WorldDrawOptions& o) {
    const DebugOverlays& v = o.overlays;
    if (!v.any()) return;
    const phys::ParticleSet& set = world.particles;
    const double px = o.pixel > 0.0 ? o.pixel : 0.02;
    auto radiusOf = [&](std::size_t i) { return std::max(set.radius[i], o.minRadius); };

    // Back to front: the grid behind everything, then states, then vectors, contacts on top.
    if (v.cells) drawCells(draw, world);
    if (o.rigid && (v.sleeping || v.models)) drawBodies(draw, *o.rigid, v, px);
    if (v.sleeping || v.models) {
        for (std::size_t i = 0; i < set.slots(); ++i) {
            if (!alive(set, i)) continue;
            const Vec2 p = drawnPosition(set, i, o);
            if (!finite(p)) continue;
            const double r = radiusOf(i);
            if (v.sleeping && (set.flags[i] & phys::kSleeping)) {
                draw.solidCircle(p, r, {}, kOverlaySleepShade);
                const double h = std::max(0.5 * r, 3.0 * px);
                sleepMark(draw, p + Vec2{r, r}, h);
            }
            if (v.models)
                draw.circle(p, r + 1.5 * px, modelColor(phys::modelOf(set.flags[i], set.invMass[i])));
        }
    }
    if (v.ghosts) drawGhosts(draw, world, o);
    if (v.forces) {
        std::vector<Vec2> forces;
        phys::netForces(world, forces);
        const double g = phys::length(world.def().forces.gravity);
        const double gRef = g > 0.0 ? g : 9.81;
        for (std::size_t i = 0; i < set.slots(); ++i) {
            if (!alive(set, i) || !(set.invMass[i] > 0.0)) continue;
            const Vec2 p = drawnPosition(set, i, o);
            // F / (m |g|): in weights, so a pebble's arrow reads as well as a cannonball's;
            // past kMaxWeights (a light link on a stiff spring) it is clipped, double-headed.
            const Vec2 inWeights = forces[i] * (set.invMass[i] / gRef);
            const double weights = phys::length(inWeights);
            const bool clipped = weights > DebugOverlays::kMaxWeights;
            const Vec2 shown = clipped ? inWeights * (DebugOverlays::kMaxWeights / weights) : inWeights;
            arrow(draw, p, p + shown * (v.weightArrowPixels * px), kOverlayForce, 10.0 * px, clipped);
        }
    }
    if (v.velocities) {
        for (std::size_t i = 0; i < set.slots(); ++i) {
            if (!alive(set, i) || set.invMass[i] == 0.0) continue;
            const Vec2 p = drawnPosition(set, i, o);
            const Vec2 tip = p + set.velocity(static_cast<phys::ParticleId>(i)) * v.velocityScale;
            arrow(draw, p, tip, kOverlayVelocity, 10.0 * px);
        }
    }
    if (v.contacts) {
        // 30 cm, but 5 to 12 px on screen: a stack seen from afar stays readable.
        const double normalLength = std::clamp(0.3, 5.0 * px, 12.0 * px);
        std::vector<phys::ContactMark> marks;
        phys::contactMarks(world, o.rigid, marks);
        for (const phys::ContactMark& c : marks) {
            if (!finite(c.point) || !finite(c.normal)) continue;
            draw.point(c.point, 4.0f, kOverlayContact);
            arrow(draw, c.point, c.point + c.normal * normalLength, kOverlayContact, 4.0 * px);
        }
    }
}

void drawWorld(phys::DebugDraw& draw, const phys::World& world, const WorldDrawOptions& o) {
    const phys::ParticleSet& set = world.particles;

    if (o.springs) {
        for (const phys::Spring& s : world.springs) {
            if (s.broken || !set.alive(s.a)) continue;
            const Vec2 a = drawnPosition(set, s.a, o);
            const bool toParticle = s.b != phys::kNoParticle;
            if (toParticle && !set.alive(s.b)) continue;
            const Vec2 b = toParticle ? drawnPosition(set, s.b, o) : s.anchor;
            if (!finite(a) || !finite(b)) continue;
            const double len = phys::length(a - b);
            const double strain = s.restLength > 0.0 ? (len - s.restLength) / s.restLength : 0.0;
            draw.segment(a, b, springColor(strain));
        }
    }

    for (std::size_t i = 0; i < set.slots(); ++i) {
        if (!(set.flags[i] & phys::kAlive)) continue;
        const Vec2 p = drawnPosition(set, i, o);
        const double r = std::max(set.radius[i], o.minRadius);
        if (!finite(p) || !std::isfinite(r)) continue;
        draw.solidCircle(p, r, {}, particleColor(set.flags[i], set.invMass[i]));
    }

    drawOverlays(draw, world, o);
}

} // namespace ui
