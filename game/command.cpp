#include "game/command.h"

#include "game/files/json_reader.h"

namespace game {

const char* commandName(CommandKind k) {
    switch (k) {
    case CommandKind::Aim: return "aim";
    case CommandKind::Power: return "power";
    case CommandKind::Select: return "select";
    case CommandKind::Fire: return "fire";
    case CommandKind::EndTurn: return "end_turn";
    case CommandKind::Set: return "set";
    }
    return "?";
}

namespace {

Command readCommand(const Node& n) {
    Command c;
    c.tick = static_cast<std::uint64_t>(n.at("tick").integer(0, kMaxCommandTick));
    const std::string cmd =
        n.at("cmd").choice({"aim", "power", "select", "fire", "end_turn", "set"});
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
        phys::WorldDef scratch;
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
        case CommandKind::Set:
            j["name"] = c.text;
            std::visit([&](const auto& v) { j["value"] = v; }, c.value);
            break;
        default: break;
        }
        list.push_back(j);
    }
    return list.dump(1);
}

} // namespace game
