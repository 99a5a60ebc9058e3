#include "game/editor/level_editor.h"

#include "game/files/text_file.h"
#include "game/level_write.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace game::editor {

using phys::Vec2;

const char* itemKindName(ItemKind kind) {
    switch (kind) {
    case ItemKind::None:
        return "nothing";
    case ItemKind::TerrainPoint:
        return "terrain point";
    case ItemKind::Cannon:
        return "cannon";
    case ItemKind::Target:
        return "target";
    case ItemKind::Block:
        return "block";
    case ItemKind::Rope:
        return "rope";
    case ItemKind::Blob:
        return "blob";
    }
    return "?";
}

Level newLevel() {
    Level l;
    l.name = "New level";
    l.description = "Made in the level editor.";
    l.mode = Mode::Practice;
    l.worldMin = {0.0, 0.0};
    l.worldMax = {200.0, 100.0};
    for (int i = 0; i <= 10; ++i)
        l.terrain.points.push_back({20.0 * i, 10.0});
    Cannon c;
    c.position = {24.0, 10.0};
    c.projectiles = {"cannonball"};
    c.projectileCounts = {-1};
    l.cannons.push_back(c);
    Target t;
    t.position = {150.0, 12.0};
    l.targets.push_back(t);
    return l;
}

namespace {

double distanceToSegment(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double len2 = phys::dot(ab, ab);
    const double s = len2 > 0.0 ? std::clamp(phys::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return phys::length(p - (a + ab * s));
}

/// `p` in the frame of a block (centre, angle): inside when within half its size.
bool insideBlock(const Block& b, Vec2 p) {
    const double a = -b.angleDeg * std::numbers::pi / 180.0;
    const Vec2 d = p - b.position;
    const Vec2 local{d.x * std::cos(a) - d.y * std::sin(a), d.x * std::sin(a) + d.y * std::cos(a)};
    return std::abs(local.x) <= 0.5 * b.size.x && std::abs(local.y) <= 0.5 * b.size.y;
}

/// A cannon is drawn about this big: a click this close to its pivot takes it.
constexpr double kCannonReach = 1.5; // m

} // namespace

LevelEditor::LevelEditor(Level level) : level_(std::move(level)), file_(level_.file) {
    validate();
}

// ---- looking --------------------------------------------------------------------------
Item LevelEditor::hitTest(Vec2 at, double reach) const {
    // Point-like items: the one whose handle is nearest, among those the click is on.
    Item best;
    double bestDistance = INFINITY;
    auto consider = [&](Item item, Vec2 where, double radius) {
        const double d = phys::length(at - where);
        if (d <= std::max(radius, reach) && d < bestDistance) best = item, bestDistance = d;
    };
    for (std::size_t i = 0; i < level_.ropes.size(); ++i) {
        consider({ItemKind::Rope, static_cast<int>(i), 0}, level_.ropes[i].from, 0.0);
        consider({ItemKind::Rope, static_cast<int>(i), 1}, level_.ropes[i].to, 0.0);
    }
    for (std::size_t i = 0; i < level_.cannons.size(); ++i)
        consider({ItemKind::Cannon, static_cast<int>(i)}, level_.cannons[i].position, kCannonReach);
    for (std::size_t i = 0; i < level_.targets.size(); ++i)
        consider({ItemKind::Target, static_cast<int>(i)}, level_.targets[i].position,
                 level_.targets[i].radius);
    for (std::size_t i = 0; i < level_.blobs.size(); ++i)
        consider({ItemKind::Blob, static_cast<int>(i)}, level_.blobs[i].center,
                 level_.blobs[i].radius);
    // Last: a terrain point under an object (a cannon stands on one) loses the tie.
    for (std::size_t i = 0; i < level_.terrain.points.size(); ++i)
        consider({ItemKind::TerrainPoint, static_cast<int>(i)}, level_.terrain.points[i], 0.0);
    if (best) return best;
    if (const int block = blockAt(at); block >= 0) return {ItemKind::Block, block};
    for (std::size_t i = 0; i < level_.ropes.size(); ++i)
        if (distanceToSegment(at, level_.ropes[i].from, level_.ropes[i].to) <= reach)
            return {ItemKind::Rope, static_cast<int>(i), -1};
    return {};
}

int LevelEditor::blockAt(Vec2 at) const {
    for (std::size_t i = level_.blocks.size(); i-- > 0;)
        if (insideBlock(level_.blocks[i], at)) return static_cast<int>(i);
    return -1;
}

Vec2 LevelEditor::positionOf(const Item& item) const {
    const auto i = static_cast<std::size_t>(item.index);
    switch (item.kind) {
    case ItemKind::TerrainPoint:
        return level_.terrain.points[i];
    case ItemKind::Cannon:
        return level_.cannons[i].position;
    case ItemKind::Target:
        return level_.targets[i].position;
    case ItemKind::Block:
        return level_.blocks[i].position;
    case ItemKind::Blob:
        return level_.blobs[i].center;
    case ItemKind::Rope: {
        const Rope& r = level_.ropes[i];
        return item.end == 0 ? r.from : item.end == 1 ? r.to : (r.from + r.to) * 0.5;
    }
    case ItemKind::None:
        break;
    }
    return {};
}

// ---- edits ----------------------------------------------------------------------------
int LevelEditor::addTerrainPoint(Vec2 at) {
    refusal_.clear();
    std::vector<Vec2>& pts = level_.terrain.points;
    const auto after = std::find_if(pts.begin(), pts.end(), [&](Vec2 p) { return p.x >= at.x; });
    if (after != pts.end() && after->x == at.x) {
        refusal_ =
            "a terrain point has this x already (the ground is a heightfield: one height per x)";
        return -1;
    }
    Level before = level_;
    const auto index = static_cast<int>(after - pts.begin());
    pts.insert(after, at);
    pushUndo(std::move(before));
    edited();
    return index;
}

Item LevelEditor::place(ItemKind kind, Vec2 at) {
    refusal_.clear();
    Level before = level_;
    Item item{kind, -1, -1};
    const double middle = 0.5 * (level_.worldMin.x + level_.worldMax.x);
    switch (kind) {
    case ItemKind::Cannon: {
        Cannon c;
        c.position = at;
        c.angleDeg = at.x > middle ? 135.0 : 45.0; // aim across the level
        // The first cannon is the player's; a second one is the computer's (a duel).
        c.player = level_.cannons.empty() ? "1" : "cpu";
        if (!level_.cannons.empty()) {
            c.projectiles = level_.cannons.front().projectiles;
            c.projectileCounts = level_.cannons.front().projectileCounts;
        } else {
            c.projectiles = {"cannonball"};
            c.projectileCounts = {-1};
        }
        level_.cannons.push_back(c);
        item.index = static_cast<int>(level_.cannons.size()) - 1;
        break;
    }
    case ItemKind::Target: {
        Target t;
        t.position = at;
        level_.targets.push_back(t);
        item.index = static_cast<int>(level_.targets.size()) - 1;
        break;
    }
    case ItemKind::Block: {
        Block b;
        b.position = at;
        level_.blocks.push_back(b);
        item.index = static_cast<int>(level_.blocks.size()) - 1;
        break;
    }
    case ItemKind::Rope: {
        Rope r;
        r.from = at;
        r.to = at + Vec2{6.0, 0.0};
        r.segments = 12;
        r.sag = 0.1;
        level_.ropes.push_back(r);
        item.index = static_cast<int>(level_.ropes.size()) - 1;
        break;
    }
    case ItemKind::Blob: {
        Blob b;
        b.center = at;
        level_.blobs.push_back(b);
        item.index = static_cast<int>(level_.blobs.size()) - 1;
        break;
    }
    case ItemKind::TerrainPoint: {
        const int i = addTerrainPoint(at);
        return i < 0 ? Item{} : Item{ItemKind::TerrainPoint, i};
    }
    case ItemKind::None:
        return {};
    }
    pushUndo(std::move(before));
    edited();
    return item;
}

void LevelEditor::setItemPosition(Level& level, const Item& item, Vec2 to) const {
    const auto i = static_cast<std::size_t>(item.index);
    switch (item.kind) {
    case ItemKind::TerrainPoint:
        level.terrain.points[i] = to;
        break;
    case ItemKind::Cannon:
        level.cannons[i].position = to;
        break;
    case ItemKind::Target: {
        // A moving target's path goes with it.
        Target& t = level.targets[i];
        const Vec2 shift = to - t.position;
        t.position = to;
        for (Vec2& p : t.path)
            p += shift;
        break;
    }
    case ItemKind::Block: {
        // Rope ends tied to the block stay where they are tied on it.
        Block& b = level.blocks[i];
        const Vec2 shift = to - b.position;
        b.position = to;
        for (Rope& r : level.ropes) {
            if (r.fromBlock == item.index) r.from += shift;
            if (r.toBlock == item.index) r.to += shift;
        }
        break;
    }
    case ItemKind::Blob:
        level.blobs[i].center = to;
        break;
    case ItemKind::Rope: {
        Rope& r = level.ropes[i];
        if (item.end == 0)
            r.from = to;
        else if (item.end == 1)
            r.to = to;
        else {
            const Vec2 shift = to - (r.from + r.to) * 0.5;
            r.from += shift;
            r.to += shift;
        }
        break;
    }
    case ItemKind::None:
        break;
    }
}

void LevelEditor::move(const Item& item, Vec2 to) {
    refusal_.clear();
    if (!item) return;
    Level next = level_;
    setItemPosition(next, item, to);
    change(next);
}

bool LevelEditor::remove(const Item& item) {
    refusal_.clear();
    Level next = level_;
    switch (item.kind) {
    case ItemKind::TerrainPoint:
        if (next.terrain.points.size() <= 2) {
            refusal_ = "the terrain needs at least two points";
            return false;
        }
        next.terrain.points.erase(next.terrain.points.begin() + item.index);
        break;
    case ItemKind::Cannon:
        if (next.cannons.size() <= 1) {
            refusal_ = "a level needs at least one cannon";
            return false;
        }
        next.cannons.erase(next.cannons.begin() + item.index);
        break;
    case ItemKind::Target:
        next.targets.erase(next.targets.begin() + item.index);
        break;
    case ItemKind::Block:
        next.blocks.erase(next.blocks.begin() + item.index);
        // Ties name blocks by index: the deleted block's ties go, later ones shift down.
        for (Rope& r : next.ropes) {
            for (int* tie : {&r.fromBlock, &r.toBlock}) {
                if (*tie == item.index)
                    *tie = -1;
                else if (*tie > item.index)
                    --*tie;
            }
        }
        break;
    case ItemKind::Rope:
        next.ropes.erase(next.ropes.begin() + item.index);
        break;
    case ItemKind::Blob:
        next.blobs.erase(next.blobs.begin() + item.index);
        break;
    case ItemKind::None:
        return false;
    }
    change(next);
    return true;
}

void LevelEditor::change(const Level& edited) {
    if (edited == level_) return;
    Level before = level_;
    level_ = edited;
    if (!gesture_) pushUndo(std::move(before));
    this->edited();
}

// ---- gestures -------------------------------------------------------------------------
void LevelEditor::beginGesture() {
    if (gesture_) return;
    gesture_ = true;
    gestureStart_ = level_;
}

void LevelEditor::dragTo(const Item& item, Vec2 to) {
    if (!item) return;
    Level next = level_;
    setItemPosition(next, item, to);
    update(next);
}

void LevelEditor::update(const Level& edited) {
    if (!gesture_) beginGesture();
    if (edited == level_) return;
    level_ = edited;
    this->edited();
}

void LevelEditor::endGesture() {
    if (!gesture_) return;
    gesture_ = false;
    if (!(gestureStart_ == level_)) pushUndo(std::move(gestureStart_));
    gestureStart_ = Level();
}

// ---- history --------------------------------------------------------------------------
void LevelEditor::pushUndo(Level before) {
    undo_.push_back(std::move(before));
    if (undo_.size() > kUndoDepth) undo_.erase(undo_.begin());
    redo_.clear();
}

void LevelEditor::undo() {
    endGesture();
    if (undo_.empty()) return;
    redo_.push_back(std::move(level_));
    level_ = std::move(undo_.back());
    undo_.pop_back();
    edited();
}

void LevelEditor::redo() {
    endGesture();
    if (redo_.empty()) return;
    undo_.push_back(std::move(level_));
    level_ = std::move(redo_.back());
    redo_.pop_back();
    edited();
}

void LevelEditor::edited() {
    modified_ = true;
    validate();
}

// ---- validation and the file ------------------------------------------------------------
void LevelEditor::validate() {
    // The loader's verdict on the text the writer makes: the very check `artillery check`
    // runs, and the very file Save would write.
    const std::string name = file_.empty() ? std::string("(new level)") : file_;
    try {
        checked_ = parseLevel(name, levelToJson(level_));
        everValid_ = true;
        problem_.clear();
    } catch (const std::exception& e) {
        problem_ = e.what();
    }
}

std::string LevelEditor::save(const std::string& file) {
    if (!valid()) return "not saved: the level does not pass check: " + problem_;
    try {
        saveLevel(file, level_);
    } catch (const std::exception& e) {
        return std::string("not saved: ") + e.what();
    }
    file_ = file;
    level_.file = file;
    modified_ = false;
    validate();
    return "";
}

} // namespace game::editor
