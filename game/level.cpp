#include "game/level.h"

#include "game/files/json_reader.h"
#include "game/material_names.h"
#include "game/settings.h"
#include "game/shape_rules.h"
#include "game/terrain.h"
#include "game/weapons.h"
#include "physics/forces.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace game {

const char* modeName(Mode m) {
    switch (m) {
    case Mode::Practice: return "practice";
    case Mode::Duel: return "duel";
    case Mode::Sandbox: return "sandbox";
    }
    return "?";
}

namespace {

// Limits that keep a hostile file from asking for absurd work or memory.
constexpr double kMaxCoordinate = 1e5;   // m
constexpr std::size_t kMaxTerrainPoints = 20000;
constexpr std::size_t kMaxObstacles = 1000;
constexpr std::size_t kMaxCannons = 8;
constexpr std::size_t kMaxTargets = 200;
constexpr std::size_t kMaxBlocks = 2000;
constexpr std::size_t kMaxRopes = 100;
constexpr std::size_t kMaxBlobs = 100;
constexpr std::size_t kMaxObstaclePoints = 20000; // all obstacles together
// Rope segments in all ropes together: the rods of a rope are solved iteratively each
// tick and cost ~4.6 ms per 1000 segments per tick (docs/robustness.md); 1000 keeps
// 600 ticks of the fullest level within a few seconds.
constexpr long long kMaxRopeSegments = 1000;
constexpr double kMinTerrainStep = 1e-3;          // m between terrain points
constexpr double kBlockOverlapSlack = 0.02;       // m two blocks may share

/// The surface materials the match knows: its table holds the built-in materials and
/// one per projectile preset (Match's constructor builds the same).
const phys::MaterialTable& surfaceTable() {
    static const phys::MaterialTable table = [] {
        phys::MaterialTable t;
        for (const auto& p : phys::projectilePresets()) projectileMaterial(t, p);
        return t;
    }();
    return table;
}

std::string surfaceMaterial(const Node& n) {
    const std::string name = n.string(64);
    if (!surfaceMaterialFromName(surfaceTable(), name))
        n.fail("expected a surface material (one of " + surfaceMaterialNames(surfaceTable()) +
               "), got " + nlohmann::json(name).dump());
    return name;
}

std::vector<Vec2> points(const Node& n, std::size_t minCount, std::size_t maxCount) {
    std::vector<Vec2> out;
    for (const Node& p : n.elements(maxCount, minCount)) out.push_back(p.vec2(kMaxCoordinate));
    return out;
}

// Twice the signed area: > 0 for counter-clockwise.
double signedArea2(const std::vector<Vec2>& poly) {
    double a = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i)
        a += phys::cross(poly[i], poly[(i + 1) % poly.size()]);
    return a;
}

void requireConvex(const Node& n, std::vector<Vec2>& poly) {
    if (signedArea2(poly) < 0.0) std::reverse(poly.begin(), poly.end());
    if (const std::string why = polygonProblem(poly); !why.empty())
        n.fail("expected a simple convex polygon, but " + why);
    if (!(signedArea2(poly) > 1e-12)) n.fail("expected a polygon with non-zero area");
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()], c = poly[(i + 2) % poly.size()];
        if (phys::cross(b - a, c - b) < 0.0)
            n.fail("expected a convex polygon, but it turns the other way at vertex " +
                   std::to_string((i + 1) % poly.size()));
    }
}

LevelPhysics readPhysics(const Node& n) {
    LevelPhysics p;
    if (n.has("planet") && n.has("gravity")) n.fail("give \"gravity\" or \"planet\", not both");
    if (auto planet = n.find("planet")) {
        const std::string name = planet->choice({"earth", "moon", "mars", "jupiter"});
        p.gravity = *phys::gravityFromPlanet(name);
    }
    p.gravity = n.number("gravity", p.gravity, 0.0, 1000.0, "m/s^2");
    p.airDensity = n.number("air_density", p.airDensity, 0.0, 100.0, "kg/m^3");
    p.drag = n.boolean("drag", p.drag);
    if (auto wind = n.find("wind")) {
        if (wind->json().is_number()) {
            p.windMin = p.windMax = wind->number(-100.0, 100.0, "m/s");
        } else {
            p.windMin = wind->number("min", -100.0, 100.0, "m/s");
            p.windMax = wind->number("max", -100.0, 100.0, "m/s");
            if (p.windMin > p.windMax) wind->fail("expected min <= max");
            wind->finish();
        }
    }
    if (auto w = n.find("water_level")) {
        p.water = true;
        p.waterLevel = w->number(-kMaxCoordinate, kMaxCoordinate, "m");
    }
    n.finish();
    return p;
}

Obstacle readObstacle(const Node& n) {
    Obstacle o;
    const std::string shape = n.at("shape").choice({"polyline", "polygon", "circle"});
    if (auto m = n.find("material")) o.material = surfaceMaterial(*m);
    if (shape == "circle") {
        o.shape = Obstacle::Shape::Circle;
        o.center = n.at("center").vec2(kMaxCoordinate);
        o.radius = n.number("radius", 1e-3, 1e4, "m");
    } else if (shape == "polyline") {
        o.shape = Obstacle::Shape::Polyline;
        const Node pts = n.at("points");
        o.points = points(pts, 2, 1000);
        if (const std::string why = polylineProblem(o.points); !why.empty())
            pts.fail("expected a polyline that can be simulated, but " + why);
    } else {
        o.shape = Obstacle::Shape::Polygon;
        const Node pts = n.at("points");
        o.points = points(pts, 3, 8);
        requireConvex(pts, o.points);
    }
    n.finish();
    return o;
}

Cannon readCannon(const Node& n) {
    Cannon c;
    c.position = n.at("position").vec2(kMaxCoordinate);
    c.angleDeg = n.number("angle_deg", c.angleDeg, -180.0, 180.0, "degrees");
    c.maxSpeedMps = n.number("max_speed_mps", c.maxSpeedMps, 1.0, 2000.0, "m/s");
    c.speedMps = n.number("speed_mps", std::min(c.speedMps, c.maxSpeedMps), 0.0, c.maxSpeedMps,
                          "m/s (at most max_speed_mps)");
    c.player = n.has("player") ? n.at("player").choice({"1", "2", "cpu"}) : "1";
    if (auto list = n.find("projectiles")) {
        for (const Node& p : list->elements(16, 1)) {
            const auto [name, count] = readProjectileEntry(p);
            // The same lookup the match fires with, so every weapon it knows passes; an
            // unknown or empty name used to pass here and crash on the first shot.
            if (!knownProjectile(name))
                p.fail("expected a weapon (" + weaponNameList() + ") or a projectile preset (" +
                       phys::projectileNameList() + "), got " + nlohmann::json(name).dump());
            c.projectiles.push_back(name);
            c.projectileCounts.push_back(count);
        }
    } else {
        c.projectiles = {"cannonball"};
        c.projectileCounts = {-1};
    }
    n.finish();
    return c;
}

Target readTarget(const Node& n) {
    Target t;
    t.position = n.at("position").vec2(kMaxCoordinate);
    t.radius = n.number("radius", t.radius, 0.05, 100.0, "m");
    t.points = static_cast<int>(n.integer("points", t.points, 1, 100000));
    if (auto path = n.find("path")) {
        t.path = points(*path, 2, 64);
        t.speedMps = n.number("speed_mps", 0.01, 500.0, "m/s");
    }
    n.finish();
    return t;
}

Block readBlock(const Node& n) {
    Block b;
    b.position = n.at("position").vec2(kMaxCoordinate);
    const Node size = n.at("size");
    b.size = size.vec2(1000.0);
    if (!(b.size.x > 0.0 && b.size.y > 0.0)) size.fail("expected a width and height > 0 m");
    if (const std::string why = blockSizeProblem(b.size); !why.empty()) size.fail(why);
    b.angleDeg = n.number("angle_deg", b.angleDeg, -360.0, 360.0, "degrees");
    if (auto m = n.find("material")) {
        b.material = m->string(64);
        if (!blockMaterialFromName(b.material))
            m->fail("expected a block material (one of " + blockMaterialNames() + "), got " +
                    nlohmann::json(b.material).dump());
    }
    b.density = n.number("density", b.density, 1.0, 30000.0, "kg/m^3");
    b.target = n.boolean("target", b.target);
    n.finish();
    return b;
}

/// True when `p` lies inside block `b` (in the block's own frame), with a small margin.
bool insideBlock(const Block& b, Vec2 p) {
    const double a = -b.angleDeg * std::numbers::pi / 180.0;
    const Vec2 d = p - b.position;
    const Vec2 local{d.x * std::cos(a) - d.y * std::sin(a), d.x * std::sin(a) + d.y * std::cos(a)};
    return std::abs(local.x) <= 0.5 * b.size.x + 1e-6 && std::abs(local.y) <= 0.5 * b.size.y + 1e-6;
}

Rope readRope(const Node& n, const std::vector<Block>& blocks) {
    Rope r;
    r.from = n.at("from").vec2(kMaxCoordinate);
    r.to = n.at("to").vec2(kMaxCoordinate);
    if (r.from == r.to) n.fail("expected \"from\" and \"to\" to be different points");
    r.segments = static_cast<int>(n.integer("segments", r.segments, 1, 200));
    r.sag = n.number("sag", r.sag, 0.0, 2.0, "(fraction of the span)");
    r.pinFrom = n.boolean("pin_from", r.pinFrom);
    r.pinTo = n.boolean("pin_to", r.pinTo);
    r.massPerSegment = n.number("mass_per_segment", r.massPerSegment, 1e-3, 1e4, "kg");
    auto tie = [&](const char* key, const char* end, Vec2 point, int& index) {
        const auto node = n.find(key);
        if (!node) return;
        if (blocks.empty()) node->fail("expected no \"" + std::string(key) + "\": the level has no blocks");
        index = static_cast<int>(node->integer(0, static_cast<long long>(blocks.size()) - 1));
        if (!insideBlock(blocks[static_cast<std::size_t>(index)], point))
            node->fail("expected \"" + std::string(end) + "\" to lie inside block " +
                       std::to_string(index) + " (the rope is tied there)");
    };
    tie("from_block", "from", r.from, r.fromBlock);
    tie("to_block", "to", r.to, r.toBlock);
    n.finish();
    return r;
}

Blob readBlob(const Node& n) {
    Blob b;
    b.center = n.at("center").vec2(kMaxCoordinate);
    b.radius = n.number("radius", b.radius, 0.05, 100.0, "m");
    b.points = static_cast<int>(n.integer("points", b.points, 3, 64));
    b.stiffness = n.number("stiffness", b.stiffness, 1.0, 1e7, "N/m");
    b.mass = n.number("mass", b.mass, 1e-3, 1e5, "kg");
    b.target = n.boolean("target", b.target);
    n.finish();
    return b;
}

bool inside(const Level& l, Vec2 p) {
    return p.x >= l.worldMin.x && p.x <= l.worldMax.x && p.y >= l.worldMin.y && p.y <= l.worldMax.y;
}

/// The format, the name, the texts and the mode.
void readHeader(const Node& root, Level& l) {
    l.format = static_cast<int>(root.at("format").integer(1, 1000));
    if (l.format != kLevelFormat)
        root.at("format").fail("this game reads level format " + std::to_string(kLevelFormat) +
                               ", got format " + std::to_string(l.format));
    l.name = root.at("name").string(80);
    if (l.name.empty()) root.at("name").fail("expected a non-empty name");
    l.description = root.string("description", "");
    l.lesson = root.string("lesson", "");
    const std::string mode = root.has("mode")
                                 ? root.at("mode").choice({"practice", "duel", "sandbox"})
                                 : "practice";
    l.mode = mode == "duel" ? Mode::Duel : mode == "sandbox" ? Mode::Sandbox : Mode::Practice;
}

/// The world's bounds and physics, the terrain and the obstacles: what does not move.
void readStage(const Node& root, Level& l) {
    if (auto world = root.find("world")) {
        l.worldMin = world->at("min").vec2(kMaxCoordinate);
        l.worldMax = world->at("max").vec2(kMaxCoordinate);
        if (!(l.worldMax.x > l.worldMin.x && l.worldMax.y > l.worldMin.y))
            world->fail("expected max to be above and to the right of min");
        world->finish();
    }
    if (auto p = root.find("physics")) l.physics = readPhysics(*p);

    const Node terrain = root.at("terrain");
    const Node tp = terrain.at("points");
    l.terrain.points = points(tp, 2, kMaxTerrainPoints);
    for (std::size_t i = 1; i < l.terrain.points.size(); ++i)
        if (!(l.terrain.points[i].x > l.terrain.points[i - 1].x))
            tp.elements(kMaxTerrainPoints)[i].fail(
                "expected x to increase from point to point (a heightfield), but it does not");
        else if (l.terrain.points[i].x - l.terrain.points[i - 1].x < kMinTerrainStep)
            tp.elements(kMaxTerrainPoints)[i].fail(
                "expected x to increase by at least 1 mm from the previous point");
    l.terrain.destructible = terrain.boolean("destructible", l.terrain.destructible);
    if (auto m = terrain.find("material")) l.terrain.material = surfaceMaterial(*m);
    terrain.finish();

    if (auto list = root.find("obstacles")) {
        std::size_t total = 0;
        for (const Node& n : list->elements(kMaxObstacles)) {
            l.obstacles.push_back(readObstacle(n));
            total += l.obstacles.back().points.size();
            if (total > kMaxObstaclePoints)
                n.fail("expected at most " + std::to_string(kMaxObstaclePoints) +
                       " points in all obstacles together");
        }
    }
}

/// Placement: everything that moves or is hit starts inside the world and above the
/// ground (a cannon below it fires into rock; a target below it cannot be reached).
class Placement {
public:
    explicit Placement(const Level& l) : level_(l), ground_(l.terrain.points) {}
    void check(const Node& n, Vec2 p, const char* what) const {
        if (!inside(level_, p)) n.fail("expected a point inside the world bounds");
        if (p.y < ground_.heightAt(p.x) - 1e-6)
            n.fail(std::string("expected ") + what + " above the ground, but the ground there is at y = " +
                   std::to_string(ground_.heightAt(p.x)).substr(0, 8) + " m");
    }

private:
    const Level& level_;
    Heightfield ground_;
};

void readTargets(const Node& root, Level& l, const Placement& placed) {
    if (auto list = root.find("targets"))
        for (const Node& n : list->elements(kMaxTargets)) {
            l.targets.push_back(readTarget(n));
            placed.check(n.at("position"), l.targets.back().position, "the target's centre");
            if (auto path = n.find("path")) {
                const auto nodes = path->elements(64);
                for (std::size_t i = 0; i < nodes.size(); ++i)
                    placed.check(nodes[i], l.targets.back().path[i], "the target's path");
            }
        }
}

void readBlocks(const Node& root, Level& l, const Placement& placed) {
    const auto list = root.find("blocks");
    if (!list) return;
    const auto nodes = list->elements(kMaxBlocks);
    std::vector<Box> boxes;
    for (const Node& n : nodes) {
        l.blocks.push_back(readBlock(n));
        const Block& b = l.blocks.back();
        placed.check(n.at("position"), b.position, "the block's centre");
        boxes.push_back({b.position, b.size, b.angleDeg});
    }
    // Overlapping blocks are pushed apart by Box2D at up to its maximum correction
    // every step; many at one point make every step a dense n^2 contact solve.
    if (const auto [i, j] = firstOverlap(boxes, kBlockOverlapSlack); i >= 0)
        nodes[static_cast<std::size_t>(j)].fail("expected blocks not to overlap, but this one overlaps block " +
                                                std::to_string(i) + " by more than 2 cm");
}

void readRopesAndBlobs(const Node& root, Level& l, const Placement& placed) {
    if (auto list = root.find("ropes")) {
        long long segments = 0;
        for (const Node& n : list->elements(kMaxRopes)) {
            l.ropes.push_back(readRope(n, l.blocks));
            segments += l.ropes.back().segments;
            if (segments > kMaxRopeSegments)
                n.at("segments").fail("expected at most " + std::to_string(kMaxRopeSegments) +
                                      " segments in all ropes together (each costs simulation "
                                      "time every tick), got " + std::to_string(segments));
            placed.check(n.at("from"), l.ropes.back().from, "the rope's end");
            placed.check(n.at("to"), l.ropes.back().to, "the rope's end");
        }
    }
    if (auto list = root.find("blobs"))
        for (const Node& n : list->elements(kMaxBlobs)) {
            l.blobs.push_back(readBlob(n));
            placed.check(n.at("center"), l.blobs.back().center, "the blob's centre");
        }
}

/// Rules that span fields: a duel's two sides, a practice level's something to hit.
void checkModeRules(const Node& root, const Node& cannons, const Level& l) {
    if (l.mode == Mode::Duel) {
        bool two = false;
        for (const auto& c : l.cannons) two = two || c.player != l.cannons.front().player;
        if (l.cannons.size() < 2 || !two)
            cannons.fail("a duel needs at least two cannons with different \"player\"s");
    }
    if (l.mode == Mode::Practice) {
        bool anyTarget = !l.targets.empty();
        for (const auto& b : l.blocks) anyTarget = anyTarget || b.target;
        for (const auto& b : l.blobs) anyTarget = anyTarget || b.target;
        if (!anyTarget)
            root.fail("a practice level needs something to hit: \"targets\", or \"blocks\" or "
                      "\"blobs\" with \"target\": true");
    }
}

} // namespace

Level parseLevel(const std::string& file, const std::string& text) {
    const nlohmann::json doc = parseJson(file, text);
    const Node root(doc, file);
    if (!root.isObject()) root.fail("expected a level object { \"format\": 1, ... }");
    Level l;
    l.file = file;
    l.contentHash = contentHash(text);
    readHeader(root, l);
    readStage(root, l);
    const Node cannons = root.at("cannons");
    const auto cannonNodes = cannons.elements(kMaxCannons, 1);
    for (const Node& n : cannonNodes) l.cannons.push_back(readCannon(n));
    const Placement placed(l);
    for (std::size_t i = 0; i < l.cannons.size(); ++i)
        placed.check(cannonNodes[i].at("position"), l.cannons[i].position, "the cannon");
    readTargets(root, l, placed);
    readBlocks(root, l, placed);
    readRopesAndBlobs(root, l, placed);
    l.shots = static_cast<int>(root.integer("shots", l.shots, 1, 100));
    l.seed = static_cast<std::uint64_t>(root.integer("seed", 1, 0, 0x7fffffffffffffffll));
    checkModeRules(root, cannons, l);
    root.finish();
    return l;
}

Level loadLevel(const std::string& file) { return parseLevel(file, readFile(file)); }

} // namespace game
