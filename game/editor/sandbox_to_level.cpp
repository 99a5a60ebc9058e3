#include "game/editor/sandbox_to_level.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace game::editor {

using phys::Vec2;

namespace {

/// An angle in degrees within [-180, 180), as the level format keeps it.
double wrappedDegrees(double radians) {
    double deg = std::remainder(radians * 180.0 / std::numbers::pi, 360.0);
    if (deg >= 180.0) deg -= 360.0;
    return deg;
}

bool groundCarved(const Match& match) {
    return std::any_of(match.events().begin(), match.events().end(),
                       [](const GameEvent& e) { return e.kind == EventKind::Crater; });
}

/// The blocks still in the world where they are now, and for each block of the match
/// its index among them (-1 when it is gone), for the ropes' ties.
std::vector<Block> blocksNow(const Match& match, std::vector<int>& newIndex) {
    std::vector<Block> out;
    for (const BlockState& b : match.blocks()) {
        if (!match.rigid().alive(b.body)) {
            newIndex.push_back(-1);
            continue;
        }
        const phys::RigidBodyState s = match.rigid().state(b.body);
        Block now = b.def;
        now.position = s.position;
        now.angleDeg = wrappedDegrees(s.angle);
        newIndex.push_back(static_cast<int>(out.size()));
        out.push_back(now);
    }
    return out;
}

std::vector<Rope> ropesNow(const Match& match, const std::vector<int>& blockIndex) {
    const phys::ParticleSet& set = match.world().particles;
    std::vector<Rope> out;
    for (const RopeState& r : match.ropes()) {
        if (!set.alive(r.first) || !set.alive(r.last)) continue; // burst apart
        Rope now = r.def;
        now.from = set.position(r.first);
        now.to = set.position(r.last);
        const double span = phys::length(now.to - now.from);
        if (!(span > 0.0)) continue;
        // Same links: the length (1 + sag) * span stays, over the new span.
        const double length = (1.0 + r.def.sag) * phys::length(r.def.to - r.def.from);
        now.sag = std::clamp(length / span - 1.0, 0.0, 2.0);
        for (int* tie : {&now.fromBlock, &now.toBlock})
            if (*tie >= 0) *tie = blockIndex[static_cast<std::size_t>(*tie)];
        out.push_back(now);
    }
    return out;
}

std::vector<Blob> blobsNow(const Match& match) {
    const phys::ParticleSet& set = match.world().particles;
    std::vector<Blob> out;
    for (const BlobState& b : match.blobs()) {
        if (!set.alive(b.center)) continue;
        Blob now = b.def;
        now.center = set.position(b.center);
        out.push_back(now);
    }
    return out;
}

} // namespace

Level sandboxToLevel(const Match& match) {
    Level l = match.level();
    l.file.clear();
    l.contentHash.clear();
    l.mode = Mode::Sandbox;
    if (l.name.size() + 6 <= 80) l.name += " scene";
    const phys::ForceDef& f = match.world().def().forces;
    l.physics.gravity = -f.gravity.y;
    l.physics.drag = f.drag != phys::DragModel::None;
    l.physics.airDensity = f.airDensity;
    if (groundCarved(match)) l.terrain.points = match.terrain().points();
    std::vector<int> blockIndex;
    l.blocks = blocksNow(match, blockIndex);
    l.ropes = ropesNow(match, blockIndex);
    l.blobs = blobsNow(match);
    return l;
}

} // namespace game::editor
