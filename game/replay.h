// Replays: a game is its level, its seed, its difficulty and its commands; re-simulating
// them gives the same world to the last bit. A replay file stores those plus a state-hash
// checkpoint every `checkpoint_every` ticks (default 120, one second at the default
// tick), each split into the particle, body and game parts so a divergence says which.
//
// File format (JSON, written atomically):
//   {"format": "artillery-replay", "version": 1,
//    "level": {"file": "levels/01_earth_basics.json", "content_hash": "16 hex digits"},
//    "difficulty": "normal", "cpu_seed": 7, "checkpoint_every": 120, "ticks": 1800,
//    "commands": [{"tick": 0, "cmd": "aim", "angle_deg": 40}, ...],
//    "checkpoints": [{"tick": 120, "hash": "...", "particles": "...", "bodies": "...",
//                     "game": "..."}, ...],
//    "final_hash": "..."}
#pragma once

#include "game/command.h"
#include "game/match.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace game {

inline constexpr int kReplayVersion = 1;
inline constexpr std::uint64_t kDefaultCheckpointEvery = 120;

struct Checkpoint {
    std::uint64_t tick = 0;
    std::uint64_t hash = 0;      ///< the whole match (Match::hash)
    std::uint64_t particles = 0; ///< particle world only
    std::uint64_t bodies = 0;    ///< rigid world only
    std::uint64_t game = 0;      ///< cannons, targets, turn, terrain
};

/// The parts of a match's state, hashed separately.
Checkpoint checkpointOf(const Match& m);

struct Replay {
    std::string levelFile;         ///< as given when recorded (relative paths resolve from the replay's folder or one above it, then the working folder)
    std::string levelHash;         ///< content hash of the level file
    std::string difficulty = "normal";
    std::uint64_t cpuSeed = 1;
    std::uint64_t checkpointEvery = kDefaultCheckpointEvery;
    std::uint64_t ticks = 0;       ///< length of the recording
    std::vector<Command> commands;
    std::vector<Checkpoint> checkpoints;
    std::uint64_t finalHash = 0;
};

std::string hex(std::uint64_t v);

/// Serialises a replay to JSON text.
std::string replayToJson(const Replay& r);
/// Parses replay JSON; throws LoadError naming the file, the JSON path and what was
/// expected (wrong version, bad hashes, commands out of order, ...).
Replay parseReplay(const std::string& file, const std::string& text);
Replay loadReplay(const std::string& file);
/// Writes atomically (temporary file + rename): a crash leaves the old file or the new.
void saveReplay(const std::string& file, const Replay& r);

/// Loads the replay's level, checking its content hash (a replay for another level, or
/// for an edited one, is refused with a LoadError that says so).
Level levelForReplay(const std::string& replayFile, const Replay& r);

struct VerifyResult {
    bool ok = true;
    std::uint64_t ticks = 0;
    std::size_t checkpoints = 0;
    std::optional<std::uint64_t> firstDivergentTick;
    std::string diverged;  ///< "particles", "bodies", "game" (or a combination)
    std::uint64_t finalHash = 0;
    /// Commands the match refused as it re-ran them ("tick 120: select 'nuke' refused:
    /// ..."): they changed nothing, so the replay may still verify, but they are not
    /// what the recording seems to say.
    std::vector<std::string> ignored;
};

/// Re-simulates the replay and compares every checkpoint and the final hash.
VerifyResult verifyReplay(const Level& level, const Replay& r);

} // namespace game
