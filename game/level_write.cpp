#include "game/level_write.h"

#include "game/files/json_reader.h"

#include <nlohmann/json.hpp>

namespace game {

namespace {

using nlohmann::ordered_json;

ordered_json point(Vec2 p) {
    return ordered_json::array({p.x, p.y});
}

ordered_json points(const std::vector<Vec2>& ps) {
    ordered_json out = ordered_json::array();
    for (const Vec2 p : ps)
        out.push_back(point(p));
    return out;
}

ordered_json physicsJson(const LevelPhysics& p) {
    ordered_json j;
    j["gravity"] = p.gravity;
    j["air_density"] = p.airDensity;
    j["drag"] = p.drag;
    // A range draws a new wind each turn; equal ends are one steady wind.
    if (p.windMin == p.windMax)
        j["wind"] = p.windMin;
    else
        j["wind"] = {{"min", p.windMin}, {"max", p.windMax}};
    if (p.water) j["water_level"] = p.waterLevel;
    return j;
}

ordered_json obstacleJson(const Obstacle& o) {
    ordered_json j;
    switch (o.shape) {
    case Obstacle::Shape::Polyline:
        j["shape"] = "polyline";
        j["points"] = points(o.points);
        break;
    case Obstacle::Shape::Polygon:
        j["shape"] = "polygon";
        j["points"] = points(o.points);
        break;
    case Obstacle::Shape::Circle:
        j["shape"] = "circle";
        j["center"] = point(o.center);
        j["radius"] = o.radius;
        break;
    }
    j["material"] = o.material;
    return j;
}

ordered_json cannonJson(const Cannon& c) {
    ordered_json j;
    j["position"] = point(c.position);
    j["angle_deg"] = c.angleDeg;
    j["max_speed_mps"] = c.maxSpeedMps;
    j["speed_mps"] = c.speedMps;
    j["player"] = c.player;
    ordered_json list = ordered_json::array();
    for (std::size_t i = 0; i < c.projectiles.size(); ++i) {
        const int count = i < c.projectileCounts.size() ? c.projectileCounts[i] : -1;
        // A bare name fires without limit; a counted entry carries its count.
        if (count < 0)
            list.push_back(c.projectiles[i]);
        else
            list.push_back({{"name", c.projectiles[i]}, {"count", count}});
    }
    j["projectiles"] = list;
    return j;
}

ordered_json targetJson(const Target& t) {
    ordered_json j;
    j["position"] = point(t.position);
    j["radius"] = t.radius;
    j["points"] = t.points;
    if (!t.path.empty()) {
        j["path"] = points(t.path);
        j["speed_mps"] = t.speedMps;
    }
    return j;
}

ordered_json blockJson(const Block& b) {
    ordered_json j;
    j["position"] = point(b.position);
    j["size"] = point(b.size);
    j["angle_deg"] = b.angleDeg;
    j["material"] = b.material;
    j["density"] = b.density;
    j["target"] = b.target;
    return j;
}

ordered_json ropeJson(const Rope& r) {
    ordered_json j;
    j["from"] = point(r.from);
    j["to"] = point(r.to);
    j["segments"] = r.segments;
    j["sag"] = r.sag;
    j["pin_from"] = r.pinFrom;
    j["pin_to"] = r.pinTo;
    j["mass_per_segment"] = r.massPerSegment;
    if (r.fromBlock >= 0) j["from_block"] = r.fromBlock;
    if (r.toBlock >= 0) j["to_block"] = r.toBlock;
    return j;
}

ordered_json blobJson(const Blob& b) {
    ordered_json j;
    j["center"] = point(b.center);
    j["radius"] = b.radius;
    j["points"] = b.points;
    j["stiffness"] = b.stiffness;
    j["mass"] = b.mass;
    j["target"] = b.target;
    return j;
}

bool isNumberArray(const ordered_json& j) {
    if (!j.is_array() || j.empty()) return false;
    for (const auto& e : j)
        if (!e.is_number()) return false;
    return true;
}

/// JSON with two-space indentation, except that a point ([x, y]) stays on one line and
/// a list of points puts four to a line: a terrain of 400 points reads as 100 lines.
void print(const ordered_json& j, int indent, std::string& out) {
    const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
    const std::string close(static_cast<std::size_t>(indent), ' ');
    if (isNumberArray(j)) {
        out += '[';
        for (std::size_t i = 0; i < j.size(); ++i)
            out += (i ? ", " : "") + j[i].dump();
        out += ']';
    } else if (j.is_array() && !j.empty() && isNumberArray(j.front())) {
        out += "[\n" + pad;
        for (std::size_t i = 0; i < j.size(); ++i) {
            if (i) out += i % 4 == 0 ? ",\n" + pad : ", ";
            print(j[i], indent + 2, out);
        }
        out += "\n" + close + ']';
    } else if (j.is_array() && !j.empty()) {
        out += '[';
        for (std::size_t i = 0; i < j.size(); ++i) {
            out += (i ? ",\n" : "\n") + pad;
            print(j[i], indent + 2, out);
        }
        out += "\n" + close + ']';
    } else if (j.is_object() && !j.empty()) {
        out += '{';
        bool first = true;
        for (auto it = j.begin(); it != j.end(); ++it) {
            out += (first ? "\n" : ",\n") + pad + ordered_json(it.key()).dump() + ": ";
            print(it.value(), indent + 2, out);
            first = false;
        }
        out += "\n" + close + '}';
    } else {
        out += j.dump();
    }
}

template <class T, class F> ordered_json array(const std::vector<T>& items, F toJson) {
    ordered_json out = ordered_json::array();
    for (const T& item : items)
        out.push_back(toJson(item));
    return out;
}

} // namespace

std::string levelToJson(const Level& l) {
    ordered_json j;
    j["format"] = kLevelFormat;
    j["name"] = l.name;
    j["mode"] = modeName(l.mode);
    if (!l.lesson.empty()) j["lesson"] = l.lesson;
    if (!l.description.empty()) j["description"] = l.description;
    j["world"] = {{"min", point(l.worldMin)}, {"max", point(l.worldMax)}};
    j["physics"] = physicsJson(l.physics);
    j["terrain"] = {{"points", points(l.terrain.points)},
                    {"destructible", l.terrain.destructible},
                    {"material", l.terrain.material}};
    if (!l.obstacles.empty()) j["obstacles"] = array(l.obstacles, obstacleJson);
    j["cannons"] = array(l.cannons, cannonJson);
    if (!l.targets.empty()) j["targets"] = array(l.targets, targetJson);
    if (!l.blocks.empty()) j["blocks"] = array(l.blocks, blockJson);
    if (!l.ropes.empty()) j["ropes"] = array(l.ropes, ropeJson);
    if (!l.blobs.empty()) j["blobs"] = array(l.blobs, blobJson);
    j["shots"] = l.shots;
    j["seed"] = l.seed;
    std::string out;
    print(j, 0, out);
    return out + "\n";
}

void saveLevel(const std::string& file, const Level& level) {
    writeFileAtomically(file, levelToJson(level));
}

} // namespace game
