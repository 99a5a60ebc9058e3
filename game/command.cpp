#include "game/command.h"

#include "game/files/json_reader.h"
#include "physics/projectiles.h"

namespace game {

const char* commandName(CommandKind k) {
    switch (k) {
    case CommandKind::Aim: return "aim";
    case CommandKind::Power: return "power";
    case CommandKind::Select: return "select";
    case CommandKind::Fire: return "fire";
    case CommandKind::EndTurn: return "end_turn";
    case CommandKind::Set: return "set";
    case CommandKind::Sandbox: return "sandbox";
    case CommandKind::Spawn: return "spawn";
    case CommandKind::Grab: return "grab";
    case CommandKind::Drag: return "drag";
    case CommandKind::Release: return "release";
    case CommandKind::Assist: return "assist";
    }
    return "?";
}

const std::vector<std::string>& spawnKinds() {
    static const std::vector<std::string> kinds = [] {
        std::vector<std::string> k{"block", "rope", "cloth", "blob", "spring"};
        for (const auto& p : phys::projectilePresets()) k.emplace_back(p.name);
        return k;
    }();
    return kinds;
}

const std::vector<std::string>& assistKinds() {
    static const std::vector<std::string> kinds{"preview", "hint"};
    return kinds;
}

namespace {

/// Largest coordinate a sandbox command may name, m (the level checks its own bounds).
constexpr double kMaxCoordinate = 1e6;

Command readCommand(const Node& n) {
    Command c;
    c.tick = static_cast<std::uint64_t>(n.at("tick").integer(0, kMaxCommandTick));
    const std::string cmd =
        n.at("cmd").choice({"aim", "power", "select", "fire", "end_turn", "set", "sandbox", "spawn",
                            "grab", "drag", "release", "assist"});
    if (cmd == "aim") {
        c.kind = CommandKind::Aim;
        c.number = n.number("angle_deg", -180.0, 180.0, "degrees");
    } else if (cmd == "power") {
        c.kind = CommandKind::Power;
        c.number = n.number("speed_mps", 0.0, 2000.0, "m/s");
    } else if (cmd == "select") {
        c.kind = CommandKind::Select;
        c.text = n.at("projectile").string(64);
    } else if (cmd == "fire") {
        c.kind = CommandKind::Fire;
    } else if (cmd == "end_turn") {
        c.kind = CommandKind::EndTurn;
    } else if (cmd == "sandbox") {
        c.kind = CommandKind::Sandbox;
    } else if (cmd == "spawn") {
        c.kind = CommandKind::Spawn;
        c.text = n.at("what").choice(spawnKinds());
        c.at = n.at("at").vec2(kMaxCoordinate);
        if (c.text == "rope" || c.text == "spring") {
            c.to = n.at("to").vec2(kMaxCoordinate);
            if (c.to == c.at) n.at("to").fail("expected a point other than \"at\"");
        }
        c.number = n.number("size", 0.0, 0.0, 20.0, "m");
    } else if (cmd == "grab" || cmd == "drag") {
        c.kind = cmd == "grab" ? CommandKind::Grab : CommandKind::Drag;
        c.at = n.at("at").vec2(kMaxCoordinate);
    } else if (cmd == "release") {
        c.kind = CommandKind::Release;
    } else if (cmd == "assist") {
        c.kind = CommandKind::Assist;
        c.text = n.at("what").choice(assistKinds());
    } else {
        c.kind = CommandKind::Set;
        const Node name = n.at("name");
        c.text = name.string(64);
        const Node value = n.at("value");
        const auto& j = value.json();
        if (j.is_number()) c.value = j.get<double>();
        else if (j.is_boolean()) c.value = j.get<bool>();
        else if (j.is_string()) c.value = value.string(64);
        else value.fail("expected a number, true/false or a string");
        // Check the value against the setting's type and range now, so a bad script
        // is refused when loaded rather than halfway through a run.
        LiveSettings scratch;
        if (const std::string why = applySetting(scratch, c.text, c.value); !why.empty())
            (findSetting(c.text) ? value : name).fail(why);
    }
    n.finish();
    return c;
}

} // namespace

std::vector<Command> parseCommands(const std::string& file, const std::string& text) {
    const nlohmann::json doc = parseJson(file, text);
    return readCommands(Node(doc, file));
}

std::vector<Command> readCommands(const Node& root) {
    std::vector<Command> out;
    std::uint64_t last = 0;
    for (const Node& n : root.elements(kMaxCommands)) {
        Command c = readCommand(n);
        if (c.tick < last)
            n.at("tick").fail("expected ticks in order: " + std::to_string(c.tick) +
                              " comes after tick " + std::to_string(last));
        last = c.tick;
        out.push_back(std::move(c));
    }
    return out;
}

std::vector<Command> loadCommands(const std::string& file) {
    return parseCommands(file, readFile(file));
}

std::string commandsToJson(const std::vector<Command>& commands) {
    nlohmann::json list = nlohmann::json::array();
    for (const Command& c : commands) {
        nlohmann::json j{{"tick", c.tick}, {"cmd", commandName(c.kind)}};
        switch (c.kind) {
        case CommandKind::Aim: j["angle_deg"] = c.number; break;
        case CommandKind::Power: j["speed_mps"] = c.number; break;
        case CommandKind::Select: j["projectile"] = c.text; break;
        case CommandKind::Assist: j["what"] = c.text; break;
        case CommandKind::Set:
            j["name"] = c.text;
            std::visit([&](const auto& v) { j["value"] = v; }, c.value);
            break;
        case CommandKind::Spawn:
            j["what"] = c.text;
            j["at"] = {c.at.x, c.at.y};
            if (c.text == "rope" || c.text == "spring") j["to"] = {c.to.x, c.to.y};
            if (c.number > 0.0) j["size"] = c.number;
            break;
        case CommandKind::Grab:
        case CommandKind::Drag: j["at"] = {c.at.x, c.at.y}; break;
        default: break;
        }
        list.push_back(j);
    }
    return list.dump(1);
}

} // namespace game
