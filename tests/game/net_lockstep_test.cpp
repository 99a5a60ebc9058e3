// Lockstep without sockets: two sessions of one duel joined by in-memory ordered
// channels that deliver late and in bursts, as a reliable network does. Both play the
// duel to the end and record the same bytes; a tampered side is caught at the next
// checkpoint; a peer may send only its own commands, only in its turn.
#include "game/net/lockstep.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

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

LockstepOptions side(int cannon, bool autoplay = false, std::optional<std::uint64_t> tamper = {}) {
    LockstepOptions o;
    o.localCannon = cannon;
    o.autoplay = autoplay;
    o.tamperTick = tamper;
    return o;
}

const Level& duel() {
    static const Level level = loadLevel(
        (std::filesystem::path(ARTILLERY_SOURCE_DIR) / "levels" / "10_duel.json").string());
    return level;
}

/// Steps both sides and carries their messages with a seeded random lag (in steps),
/// keeping each direction's order. Returns the number of rounds run.
int play(Lockstep& a, Lockstep& b, std::uint64_t seed, int maxRounds = 200000) {
    std::mt19937_64 rng(seed);
    std::deque<std::pair<int, Message>> ab, ba; // (rounds left, message)
    std::uniform_int_distribution<int> lag(0, 8), burst(0, 3);
    int round = 0;
    for (; round < maxRounds; ++round) {
        for (int i = burst(rng); i >= 0; --i)
            a.step();
        for (int i = burst(rng); i >= 0; --i)
            b.step();
        for (Message& m : a.takeOutbox())
            ab.emplace_back(lag(rng), std::move(m));
        for (Message& m : b.takeOutbox())
            ba.emplace_back(lag(rng), std::move(m));
        auto deliver = [](std::deque<std::pair<int, Message>>& q, Lockstep& to) {
            for (auto& [left, m] : q)
                left = std::max(0, left - 1);
            while (!q.empty() && q.front().first == 0) {
                EXPECT_EQ(to.receive(q.front().second), "");
                q.pop_front();
            }
        };
        deliver(ab, b);
        deliver(ba, a);
        const bool done = (a.over() || !a.stopped().empty()) && (b.over() || !b.stopped().empty());
        if (done && ab.empty() && ba.empty()) break;
    }
    return round;
}

TEST(NetLockstep, AutoplayedDuelEndsWithTheSameReplayOnBothSides) {
    Lockstep host(duel(), side(0, true));
    Lockstep joiner(duel(), side(1, true));
    play(host, joiner, 1);
    ASSERT_TRUE(host.over());
    ASSERT_TRUE(joiner.over());
    EXPECT_EQ(host.stopped(), "");
    EXPECT_EQ(joiner.stopped(), "");
    const Replay a = host.recording("levels/10_duel.json");
    const Replay b = joiner.recording("levels/10_duel.json");
    EXPECT_EQ(replayToJson(a), replayToJson(b));
    EXPECT_GT(a.commands.size(), 6u);
    const VerifyResult v = verifyReplay(duel(), a);
    EXPECT_TRUE(v.ok) << v.diverged;
    EXPECT_EQ(v.finalHash, host.match().hash());
}

TEST(NetLockstep, AnotherLagPatternGivesTheSameMatch) {
    Lockstep h1(duel(), side(0, true));
    Lockstep j1(duel(), side(1, true));
    play(h1, j1, 1);
    Lockstep h2(duel(), side(0, true));
    Lockstep j2(duel(), side(1, true));
    play(h2, j2, 987654321);
    EXPECT_EQ(replayToJson(h1.recording("x")), replayToJson(h2.recording("x")));
}

TEST(NetLockstep, ATamperedSideIsCaughtAtTheNextCheckpoint) {
    Lockstep host(duel(), side(0, true));
    Lockstep joiner(duel(), side(1, true, 0));
    play(host, joiner, 3);
    // The host fires first, after the computer's 60-tick pause and its second (120
    // ticks) of aiming: the shell flies from tick 181, is nudged there on the joiner's
    // side, and the checkpoint at 240 differs.
    EXPECT_EQ(host.stopped(), "desync at tick 240 (particles differ)");
    EXPECT_EQ(joiner.stopped(), "desync at tick 240 (particles differ)");
    EXPECT_FALSE(host.over());
}

TEST(NetLockstep, APeerMaySendOnlyItsOwnCommandsInItsTurn) {
    Lockstep host(duel(), side(0));
    // The joiner's cannon is 1: a command for cannon 0 is refused on arrival.
    Message forged = commandMessage(commandAt(CommandKind::Fire, 0), 0, 0);
    EXPECT_EQ(host.receive(forged), "a command for cannon 0 came from the peer of cannon 1");
    // Its own cannon, but the host's turn: refused when its tick comes.
    Lockstep host2(duel(), side(0));
    Message early = commandMessage(commandAt(CommandKind::Fire, 0), 0, 1);
    EXPECT_EQ(host2.receive(early), "");
    Message mark;
    mark.type = MessageType::Advance;
    mark.tick = 1;
    EXPECT_EQ(host2.receive(mark), "");
    EXPECT_EQ(host2.submit(commandAt(CommandKind::Aim, 0, 40)), "");
    // The host's own turn: it runs without waiting, and the forged command meets it at tick 0.
    host2.step();
    EXPECT_EQ(host2.stopped(), "player 1 sent a command outside its turn (tick 0)");
    // A local command in the peer's turn is refused before it is sent.
    Lockstep joiner(duel(), side(1));
    EXPECT_EQ(joiner.submit(commandAt(CommandKind::Fire, 0)), "it is not your turn");
    EXPECT_EQ(joiner.submit(commandAt(CommandKind::Set, 0, 0.0, "integrator")),
              "'set' is not a duel command (aim, power, select, fire, end_turn)");
    EXPECT_TRUE(joiner.takeOutbox().empty());
}

TEST(NetLockstep, TheFollowerWaitsForTheMarkAndOutOfOrderInputIsAnError) {
    Lockstep joiner(duel(), side(1));
    EXPECT_FALSE(joiner.canStep()); // the host's turn, no mark yet
    Message mark;
    mark.type = MessageType::Advance;
    mark.tick = 12;
    EXPECT_EQ(joiner.receive(mark), "");
    for (int i = 0; i < 100; ++i)
        joiner.step();
    EXPECT_EQ(joiner.match().tick(), 12u);
    Message late = commandMessage(commandAt(CommandKind::Fire, 3), 0, 0);
    EXPECT_EQ(joiner.receive(late), "a command for tick 3 arrived after tick 12");
    Message gap = commandMessage(commandAt(CommandKind::Fire, 20), 4, 0);
    EXPECT_EQ(joiner.receive(gap), "command number 4 arrived, expected 0");
    mark.tick = 6;
    EXPECT_EQ(joiner.receive(mark), "advance to tick 6 after one to tick 12");
    Message hello;
    hello.type = MessageType::Hello;
    EXPECT_EQ(joiner.receive(hello), "a hello message in the middle of a match");
}

// A side about to leave marks how far it played, so the other side plays to that very
// tick, not to the last multiple of the mark's period.
TEST(NetLockstep, ALeavingSideMarksItsTickSoTheOtherPlaysToIt) {
    Lockstep host(duel(), side(0)), joiner(duel(), side(1));
    for (int i = 0; i < 9; ++i)
        host.step();
    ASSERT_EQ(host.match().tick(), 9u);
    host.markProgress();
    host.markProgress(); // once: nothing new to mark
    std::vector<Message> out = host.takeOutbox();
    ASSERT_EQ(out.size(), 2u) << "the periodic mark at 6 and the one at 9";
    EXPECT_EQ(out.back().type, MessageType::Advance);
    EXPECT_EQ(out.back().tick, 9u);
    for (const Message& m : out)
        ASSERT_EQ(joiner.receive(m), "");
    for (int i = 0; i < 100; ++i)
        joiner.step();
    EXPECT_EQ(joiner.match().tick(), 9u);
    EXPECT_EQ(joiner.match().hash(), host.match().hash());
    joiner.markProgress();
    EXPECT_TRUE(joiner.takeOutbox().empty()) << "not its turn: it has nothing to mark";
}

TEST(NetLockstep, ASpectatorFollowsTheHostsStreamToTheSameEnd) {
    Lockstep host(duel(), side(0, true));
    Lockstep joiner(duel(), side(1, true));
    Lockstep watcher(duel(), side(kSpectator));
    std::vector<Message> stream;
    // Join the spectator half-way: it catches up from the host's list.
    std::mt19937_64 rng(5);
    bool joined = false;
    for (int round = 0; round < 200000 && !(host.over() && joiner.over() && watcher.over());
         ++round) {
        host.step();
        joiner.step();
        for (const Message& m : host.takeOutbox())
            ASSERT_EQ(joiner.receive(m), "");
        for (const Message& m : joiner.takeOutbox())
            ASSERT_EQ(host.receive(m), "");
        if (!joined && host.match().tick() > 700) {
            joined = true;
            host.takeSpectatorOutbox();
            for (const Message& m : host.catchUp(0, true))
                ASSERT_EQ(watcher.receive(m), "");
        }
        for (const Message& m : host.takeSpectatorOutbox())
            if (joined) {
                ASSERT_EQ(watcher.receive(m), "");
            }
        watcher.step();
        watcher.step();
    }
    ASSERT_TRUE(watcher.over());
    EXPECT_EQ(watcher.stopped(), "");
    EXPECT_EQ(replayToJson(watcher.recording("x")), replayToJson(host.recording("x")));
    EXPECT_TRUE(watcher.takeOutbox().empty()); // a spectator sends nothing
}

} // namespace
} // namespace game::net
