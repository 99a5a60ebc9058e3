// The protocol's bytes: every message survives encode -> decode unchanged, and every
// malformed or hostile packet is refused with its reason before any field is used.
#include "game/net/message.h"

#include <gtest/gtest.h>

#include <limits>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace game::net {
namespace {

/// A command without designated initializers (the build warns about unnamed members).
Command commandAt(CommandKind kind, std::uint64_t tick = 0, double number = 0.0,
                  std::string text = {}) {
    Command c;
    c.tick = tick;
    c.kind = kind;
    c.number = number;
    c.text = std::move(text);
    return c;
}

Message roundTrip(const Message& m) {
    const auto bytes = encode(m);
    const Decoded d = decode(bytes.data(), bytes.size());
    EXPECT_EQ(d.error, "");
    return d.message.value_or(Message{});
}

TEST(NetMessage, EveryTypeRoundTrips) {
    Message offer;
    offer.type = MessageType::Offer;
    offer.version = kProgramVersion;
    offer.levelHash = "0123456789abcdef";
    offer.levelName = "10_duel.json";
    offer.name = "ada";
    offer.checkpointEvery = 120;
    const Message o = roundTrip(offer);
    EXPECT_EQ(o.version, offer.version);
    EXPECT_EQ(o.levelHash, offer.levelHash);
    EXPECT_EQ(o.levelName, offer.levelName);
    EXPECT_EQ(o.name, "ada");
    EXPECT_EQ(o.checkpointEvery, 120u);

    Message hello;
    hello.type = MessageType::Hello;
    hello.version = kProgramVersion;
    hello.name = "bob";
    hello.spectator = true;
    hello.commandIndex = 17;
    hello.tick = 4321;
    const Message h = roundTrip(hello);
    EXPECT_TRUE(h.spectator);
    EXPECT_EQ(h.commandIndex, 17u);
    EXPECT_EQ(h.tick, 4321u);
    EXPECT_EQ(h.levelHash, "");
    EXPECT_EQ(h.token, "");
    hello.token = "0123456789abcdef"; // a rejoin presents its seat's token
    EXPECT_EQ(roundTrip(hello).token, "0123456789abcdef");

    Message welcome;
    welcome.type = MessageType::Welcome;
    welcome.cannon = 1;
    welcome.name = "ada";
    welcome.token = "fedcba9876543210";
    EXPECT_EQ(roundTrip(welcome).token, "fedcba9876543210");
    welcome.token = "FEDCBA9876543210";
    EXPECT_EQ(validate(welcome), "welcome: seat token must be 16 lowercase hex digits or empty");
    hello.token = "12345";
    EXPECT_EQ(validate(hello), "hello: seat token must be 16 lowercase hex digits or empty");

    Message cmd = commandMessage(commandAt(CommandKind::Select, 99, 0.0, "golf-ball"), 5, 1);
    const Message c = roundTrip(cmd);
    EXPECT_EQ(c.type, MessageType::Command);
    EXPECT_EQ(c.tick, 99u);
    EXPECT_EQ(c.commandIndex, 5u);
    EXPECT_EQ(c.player, 1);
    EXPECT_EQ(c.kind, CommandKind::Select);
    EXPECT_EQ(c.text, "golf-ball");

    Message aim = commandMessage(commandAt(CommandKind::Aim, 3, 52.125), 0, 0);
    EXPECT_EQ(roundTrip(aim).number, 52.125); // the double's bits, exactly

    Message cp;
    cp.type = MessageType::Checkpoint;
    cp.tick = 240;
    cp.particles = 0x0123456789abcdefull;
    cp.bodies = 0xfedcba9876543210ull;
    cp.game = 42;
    const Message k = roundTrip(cp);
    EXPECT_EQ(k.particles, cp.particles);
    EXPECT_EQ(k.bodies, cp.bodies);
    EXPECT_EQ(k.game, 42u);

    Message bye;
    bye.type = MessageType::Bye;
    bye.reason = "desync at tick 240 (particles differ)";
    EXPECT_EQ(roundTrip(bye).reason, bye.reason);

    Message aiming;
    aiming.type = MessageType::Aiming;
    aiming.player = 1;
    aiming.angleDeg = 137.25;
    aiming.speedMps = 48.5;
    const Message a = roundTrip(aiming);
    EXPECT_EQ(a.player, 1);
    EXPECT_EQ(a.angleDeg, 137.25);
    EXPECT_EQ(a.speedMps, 48.5);
    EXPECT_EQ(encode(aiming).size(), kHeaderBytes + 17) << "a cannon and two doubles";
}

// An aim only drawn still has to be a number a cannon could take, from a duel's cannon.
TEST(NetMessage, AnAimingMessageIsBoundedLikeTheAimCommands) {
    Message m;
    m.type = MessageType::Aiming;
    m.angleDeg = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(validate(m), "aiming: angle and power must be finite and within +-1e6");
    m.angleDeg = 45.0;
    m.speedMps = 2e6;
    EXPECT_EQ(validate(m), "aiming: angle and power must be finite and within +-1e6");
    m.speedMps = 40.0;
    m.player = 2;
    EXPECT_EQ(validate(m), "aiming: player must be 0 or 1");
}

std::string errorOf(std::vector<std::uint8_t> bytes) {
    const Decoded d = decode(bytes.data(), bytes.size());
    EXPECT_FALSE(d.message.has_value());
    return d.error;
}

std::vector<std::uint8_t> advanceBytes() {
    Message m;
    m.type = MessageType::Advance;
    m.tick = 6;
    return encode(m);
}

TEST(NetMessage, MalformedPacketsAreRefusedWithTheirReason) {
    EXPECT_EQ(errorOf({'A', 'N', 1}), "message of 3 bytes is shorter than its header");
    EXPECT_EQ(errorOf(std::vector<std::uint8_t>(600, 'A')),
              "message of 600 bytes is over the limit of 512");
    auto b = advanceBytes();
    b[0] = 'X';
    EXPECT_EQ(errorOf(b), "message does not start with the protocol's magic bytes");
    b = advanceBytes();
    b[2] = 7;
    EXPECT_EQ(errorOf(b), "protocol version 7, expected 2");
    b = advanceBytes();
    b[3] = 200;
    EXPECT_EQ(errorOf(b), "message type 200 is unknown");
    b = advanceBytes();
    b.push_back(0);
    EXPECT_EQ(errorOf(b), "payload length field says 4 bytes, the message has 5");
    b = advanceBytes();
    b[4] = 2;
    b.resize(8);
    EXPECT_EQ(errorOf(b), "advance: payload ends early");
    b = advanceBytes();
    b[4] = 5;
    b.push_back(9);
    EXPECT_EQ(errorOf(b), "advance: 1 bytes after the last field");
}

TEST(NetMessage, OnlyTheFiveDuelCommandsPass) {
    Message set = commandMessage(commandAt(CommandKind::Set, 1, 0.0, "integrator"), 0, 0);
    EXPECT_EQ(validate(set),
              "command: 'set' is not a duel command (aim, power, select, fire, end_turn)");
    EXPECT_THROW(encode(set), std::invalid_argument);
    // Forge the bytes of a set command by hand: the decoder refuses it too.
    Message aim = commandMessage(commandAt(CommandKind::Aim, 1, 1), 0, 0);
    auto bytes = encode(aim);
    bytes[kHeaderBytes + 9] = static_cast<std::uint8_t>(CommandKind::Set);
    EXPECT_EQ(errorOf(bytes),
              "command: 'set' is not a duel command (aim, power, select, fire, end_turn)");
    bytes[kHeaderBytes + 9] = 250;
    EXPECT_EQ(errorOf(bytes), "command: kind 250 is unknown");
    Message sel = commandMessage(commandAt(CommandKind::Select, 1, 0.0, "../../etc/passwd"), 0, 0);
    EXPECT_EQ(validate(sel), "command: select needs a projectile name (letters, digits, _ - .)");
    Message nan = commandMessage(commandAt(CommandKind::Power, 1, NAN), 0, 0);
    EXPECT_EQ(validate(nan), "command: number must be finite and within +-1e6");
    Message who = aim;
    who.player = 3;
    EXPECT_EQ(validate(who), "command: player must be 0 or 1");
}

TEST(NetMessage, TextFieldsAreBoundedAndPrintable) {
    Message hello;
    hello.type = MessageType::Hello;
    hello.version = kProgramVersion;
    hello.name = std::string(25, 'x');
    EXPECT_EQ(validate(hello), "hello: name is 25 bytes, at most 24 allowed");
    hello.name = "bell\a";
    EXPECT_EQ(validate(hello), "hello: name has a byte outside printable ASCII");
    Message offer;
    offer.type = MessageType::Offer;
    offer.version = kProgramVersion;
    offer.levelHash = "0123456789abcdef";
    offer.levelName = "../levels/10_duel.json";
    EXPECT_EQ(validate(offer),
              "offer: level name must be a bare file name (letters, digits, _ - .)");
    offer.levelName = "10_duel.json";
    offer.levelHash = "0123";
    EXPECT_EQ(validate(offer), "offer: level hash must be 16 lowercase hex digits");
}

} // namespace
} // namespace game::net

namespace game::net {
namespace {

// The fuzzer's seeds (tests/data/net_messages) are valid messages of every kind.
TEST(NetMessage, TheFuzzSeedsDecode) {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(
             std::filesystem::path(ARTILLERY_SOURCE_DIR) / "tests" / "data" / "net_messages")) {
        std::ifstream in(entry.path(), std::ios::binary);
        const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
        const Decoded d = decode(bytes.data(), bytes.size());
        EXPECT_EQ(d.error, "") << entry.path();
        if (d.message) {
            EXPECT_EQ(encode(*d.message), bytes) << entry.path();
        }
        ++files;
    }
    EXPECT_EQ(files, 9);
}

} // namespace
} // namespace game::net
