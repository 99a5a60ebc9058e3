// Commands: every change to the world is a Command at a tick (DESIGN.md). The window,
// the computer player, hand-written scripts and replays all speak this vocabulary, so
// replaying the commands of a game gives the same world to the last bit.
//
// A commands file is a JSON list of {"tick": t, "cmd": NAME, ...arguments}:
//   {"tick": 0,   "cmd": "aim",    "angle_deg": 52.5}
//   {"tick": 0,   "cmd": "power",  "speed_mps": 34}
//   {"tick": 0,   "cmd": "select", "projectile": "golf-ball"}
//   {"tick": 10,  "cmd": "fire"}
//   {"tick": 600, "cmd": "end_turn"}
//   {"tick": 700, "cmd": "set", "name": "integrator", "value": "rk4"}
#pragma once

#include "game/settings.h"

#include <cstdint>
#include <string>
#include <vector>

namespace game {

enum class CommandKind { Aim, Power, Select, Fire, EndTurn, Set };
const char* commandName(CommandKind k);

struct Command {
    std::uint64_t tick = 0;
    CommandKind kind = CommandKind::Fire;
    double number = 0.0;     ///< aim: angle_deg; power: speed_mps
    std::string text;        ///< select: projectile; set: setting name
    SettingValue value;      ///< set: the value
};

/// Largest tick a script may name (a day at 1000 Hz); keeps absurd files bounded.
inline constexpr std::uint64_t kMaxCommandTick = 86'400'000;
inline constexpr std::size_t kMaxCommands = 1'000'000;

class Node;
/// Reads a commands list at a node of a larger document (a replay's "commands").
std::vector<Command> readCommands(const Node& list);
/// Parses a commands list; ticks must not decrease. Throws LoadError naming file and path.
std::vector<Command> parseCommands(const std::string& file, const std::string& text);
std::vector<Command> loadCommands(const std::string& file);

/// The JSON form of a command list (what a replay stores).
std::string commandsToJson(const std::vector<Command>& commands);

} // namespace game
