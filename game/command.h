// Commands: every change to the world is a Command at a tick (docs/architecture.md). The window,
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
//   {"tick": 700, "cmd": "set", "name": "restitution.golf-ball", "value": "tennis"}
//   {"tick": 700, "cmd": "set", "name": "pair.golf-ball.earth", "value": 0.5}
// (every setting, what it takes and its refusal messages: game/settings.h)
// The sandbox's verbs (refused until the level is a sandbox, or a "sandbox" command
// has made it one):
//   {"tick": 0,   "cmd": "sandbox"}                       no budget, no score, tools on
//   {"tick": 5,   "cmd": "spawn", "what": "block", "at": [40, 10], "size": 1.5}
//   {"tick": 9,   "cmd": "spawn", "what": "rope", "at": [30, 20], "to": [34, 12]}
//   {"tick": 20,  "cmd": "grab", "at": [40, 10]}   then "drag" {"at": [..]}, "release"
// `what` is block, rope, cloth, blob, spring or a projectile preset (a ball).
// The learning aids, which cap a practice result at two stars (game/effects/assist.h):
//   {"tick": 0,   "cmd": "assist", "what": "preview"}      the full trajectory preview
//   {"tick": 0,   "cmd": "assist", "what": "hint"}         the firing-solution hint
#pragma once

#include "game/settings.h"
#include "physics/vec2.h"

#include <cstdint>
#include <string>
#include <vector>

namespace game {

enum class CommandKind { Aim, Power, Select, Fire, EndTurn, Set, Sandbox, Spawn, Grab, Drag, Release, Assist };
const char* commandName(CommandKind k);

struct Command {
    std::uint64_t tick = 0;
    CommandKind kind = CommandKind::Fire;
    double number = 0.0;     ///< aim: angle_deg; power: speed_mps; spawn: size (m, 0 = default)
    std::string text;        ///< select: projectile; set: setting name; spawn, assist: what
    SettingValue value;      ///< set: the value
    phys::Vec2 at;           ///< spawn, grab, drag: where, m
    phys::Vec2 to;           ///< spawn rope or spring: the other end, m
};

/// What `spawn` can make: block, rope, cloth, blob, spring and every projectile preset.
const std::vector<std::string>& spawnKinds();

/// What `assist` names: preview (the full trajectory preview), hint (the firing solution).
const std::vector<std::string>& assistKinds();

/// Largest tick a script may name (a day at 1000 Hz); keeps absurd files bounded.
inline constexpr std::uint64_t kMaxCommandTick = 86'400'000;
/// Upper bound on the length of a run and of a replay (a day of simulated time at
/// 120 Hz would be absurd for a match; an hour is plenty). `run` stops there and
/// `replay verify` refuses a replay that claims more.
inline constexpr std::uint64_t kMaxRunTicks = 120ull * 3600;
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
