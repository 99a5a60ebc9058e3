// The network protocol as plain data: every message two peers (or a host and a
// spectator) exchange, and its byte encoding. Nothing here touches a socket, so the
// encoder, the decoder and the validation run in unit tests and under a fuzzer.
//
// Wire format (little-endian), one message per packet:
//   magic "AN" (2 bytes) | protocol version (u8) | type (u8) | payload length (u16) |
//   payload (exactly that many bytes)
// Strings are a u8 length then that many bytes, limited per field (names 24 bytes,
// versions 32, reasons 160) and restricted to printable ASCII; nothing a peer sends is
// ever used as a file name, a path or a setting: the only actions it can ask for are
// the five duel commands (aim, power, select, fire, end_turn) of its own cannon.
//
// The messages, in the order a match uses them:
//   Offer      host -> peer: program version, level content hash, level file name (a
//              bare name looked up in the joiner's own level folder), host's name,
//              checkpoint interval
//   Hello      peer -> host: program version, level content hash it found, its name,
//              spectator or player, resume: the number of match commands and the
//              tick it already has (0, 0 for a fresh join), and its seat token ("" for
//              a first join; a rejoin presents the one the host gave)
//   Welcome    host -> peer: its cannon (-1 for a spectator), the other player's name,
//              how many commands the host holds and its tick (a rejoining peer
//              replays the stream up to there before it plays again), and the seat's
//              token (16 hex digits, secret: a name alone never takes a seat; "" for a
//              spectator)
//   Refuse     host -> peer: why the join was refused (version or level differ, full)
//   Command    one match command at a tick: its index in the match's command list, the
//              player whose command it is, kind, number, text (select's projectile)
//   Advance    "I have simulated through tick N and sent every command before it"
//   Handover   the sender's turn ended at tick N (the receiver's turn starts there)
//   Checkpoint state hashes at a replay checkpoint tick: particles, bodies, game
//   Bye        the sender leaves; the reason (a desync, the match is over, quit)
//   Aiming     the aim a player is editing in its turn (its cannon, angle, power): drawn
//              on the other side as it moves; never a command, never recorded, never
//              applied to the match (the aim and power commands settle it)
#pragma once

#include "game/command.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace game::net {

inline constexpr std::uint8_t kProtocolVersion = 2;
/// The program version both sides must run (the simulation's bits depend on it).
inline constexpr const char* kProgramVersion = "artillery 0.18 (replay format 1)";
/// Largest packet either side accepts; a longer one is refused before decoding.
inline constexpr std::size_t kMaxMessageBytes = 512;
inline constexpr std::size_t kHeaderBytes = 6;
inline constexpr std::size_t kMaxNameBytes = 24;
inline constexpr std::size_t kMaxVersionBytes = 32;
inline constexpr std::size_t kMaxReasonBytes = 160;
inline constexpr std::size_t kMaxLevelNameBytes = 64;
inline constexpr std::size_t kMaxProjectileBytes = 32;

enum class MessageType : std::uint8_t {
    Offer = 1,
    Hello = 2,
    Welcome = 3,
    Refuse = 4,
    Command = 5,
    Advance = 6,
    Handover = 7,
    Checkpoint = 8,
    Bye = 9,
    Aiming = 10,
};
const char* messageName(MessageType t);

/// One message; which fields mean something depends on `type` (see above).
struct Message {
    MessageType type = MessageType::Bye;
    std::string version;     ///< Offer, Hello: program version
    std::string levelHash;   ///< Offer, Hello: 16 hex digits ("" in Hello: none found)
    std::string levelName;   ///< Offer: bare file name of the level, e.g. 10_duel.json
    std::string name;        ///< Offer, Hello: sender's name; Welcome: the other player's
    std::string reason;      ///< Refuse, Bye
    bool spectator = false;  ///< Hello
    std::int8_t cannon = -1; ///< Welcome: the joiner's cannon, -1 spectator
    std::uint32_t checkpointEvery = 120; ///< Offer
    std::uint32_t commandIndex =
        0; ///< Command: index in the match's list; Hello, Welcome: count held
    std::uint32_t tick =
        0; ///< Command, Advance, Handover, Checkpoint; Hello: resume tick; Welcome: host's tick
    std::uint8_t player = 0;                           ///< Command, Aiming: whose cannon
    CommandKind kind = CommandKind::Fire;              ///< Command
    double number = 0.0;                               ///< Command: aim angle (deg) or power (m/s)
    double angleDeg = 0.0, speedMps = 0.0;             ///< Aiming
    std::string text;                                  ///< Command: select's projectile
    std::string token; ///< Hello: the seat token a rejoin presents; Welcome: the seat's
    std::uint64_t particles = 0, bodies = 0, game = 0; ///< Checkpoint
};

/// The bytes of a message. Throws std::invalid_argument when a field breaks a limit
/// (a program error: validate() names it).
std::vector<std::uint8_t> encode(const Message& m);

struct Decoded {
    std::optional<Message> message;
    std::string error; ///< why the bytes are not a valid message ("" when they are)
};
/// Decodes and validates: magic, version, type, exact length, every field's limits and
/// character set, finite numbers in range. Never throws, never reads past `size`.
Decoded decode(const std::uint8_t* data, std::size_t size);

/// "" when every field is within its limits, else what is wrong.
std::string validate(const Message& m);

/// A match command as a message, and back (the kinds a network duel allows).
Message commandMessage(const Command& c, std::uint32_t index, int player);
Command commandOf(const Message& m);
/// The command kinds a peer may send: aim, power, select, fire, end_turn.
bool networkCommand(CommandKind k);

} // namespace game::net
