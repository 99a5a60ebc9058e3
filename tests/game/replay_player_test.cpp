// The replay viewer's engine: seeking either way lands on the very state
// straight play has at that tick; taking over keeps exactly the commands before the
// tick and plays on as a replay that verifies; a changed replay is reported.
#include "game/replay_player.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>

using namespace game;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = ARTILLERY_SOURCE_DIR;

struct Golden {
    Level level;
    Replay replay;
};

Golden golden(const std::string& name) {
    const std::string file = (kSource / "tests" / "replays" / name).string();
    Replay r = loadReplay(file);
    return {levelForReplay(file, r), std::move(r)};
}

/// Match::hash at every stored checkpoint tick, by playing straight through.
std::map<std::uint64_t, std::uint64_t> straightHashes(const Golden& g) {
    ReplayPlayer p(g.level, g.replay);
    std::map<std::uint64_t, std::uint64_t> out;
    out[0] = p.match().hash();
    while (!p.atEnd()) {
        p.step();
        if (p.tick() % g.replay.checkpointEvery == 0 || p.atEnd()) out[p.tick()] = p.match().hash();
    }
    return out;
}

std::vector<Command> commandsBefore(const Replay& r, std::uint64_t tick) {
    std::vector<Command> out;
    for (const Command& c : r.commands)
        if (c.tick < tick) out.push_back(c);
    return out;
}

} // namespace

TEST(ReplayPlayer, PlayingStraightThroughMatchesEveryStoredCheckpoint) {
    const Golden g = golden("05_castle.replay.json");
    ReplayPlayer p(g.level, g.replay);
    while (!p.atEnd())
        p.step();
    EXPECT_EQ(p.tick(), g.replay.ticks);
    EXPECT_FALSE(p.divergence().has_value())
        << "diverged at " << p.divergence()->tick << " in " << p.divergence()->what;
    EXPECT_EQ(p.checkpointsChecked(), g.replay.checkpoints.size());
    EXPECT_EQ(p.match().hash(), g.replay.finalHash);
    EXPECT_EQ(p.refusedCommands(), 0u);
}

TEST(ReplayPlayer, SeekingBackThenForwardGivesStraightPlaysHashAtEveryCheckpoint) {
    const Golden g = golden("03_windy_valley.replay.json");
    const auto straight = straightHashes(g);
    ASSERT_EQ(straight.size(), g.replay.checkpoints.size() + 1) << "tick 0 and every checkpoint";
    ReplayPlayer p(g.level, g.replay);
    p.seek(p.lastTick());
    // Backwards through every checkpoint (each a re-simulation from the start)...
    for (auto it = straight.rbegin(); it != straight.rend(); ++it) {
        p.seek(it->first);
        ASSERT_EQ(p.tick(), it->first);
        EXPECT_EQ(p.match().hash(), it->second) << "after seeking back to tick " << it->first;
    }
    // ...then forwards again, in uneven jumps from wherever it is.
    for (const auto& [tick, hash] : straight) {
        p.seek(tick);
        EXPECT_EQ(p.match().hash(), hash) << "after seeking forward to tick " << tick;
    }
    // Back to a tick between checkpoints and on: the same states.
    p.seek(1234);
    p.seek(1320);
    EXPECT_EQ(p.match().hash(), straight.at(1320));
    EXPECT_FALSE(p.divergence().has_value());
    EXPECT_EQ(p.checkpointsChecked(), g.replay.checkpoints.size()) << "each counted once";
}

TEST(ReplayPlayer, SeekingPastTheEndClampsAndSteppingAtTheEndDoesNothing) {
    const Golden g = golden("02_moon.replay.json");
    ReplayPlayer p(g.level, g.replay);
    p.seek(p.lastTick() + 100000);
    EXPECT_EQ(p.tick(), g.replay.ticks);
    EXPECT_TRUE(p.atEnd());
    const std::uint64_t hash = p.match().hash();
    p.step();
    EXPECT_EQ(p.tick(), g.replay.ticks);
    EXPECT_EQ(p.match().hash(), hash);
    EXPECT_EQ(hash, g.replay.finalHash);
    p.seek(0);
    EXPECT_EQ(p.tick(), 0u);
    EXPECT_EQ(p.match().hash(), Match(g.level).hash());
}

TEST(ReplayPlayer, TakingOverKeepsTheCommandsBeforeTheTickAndPlaysOnAsAReplayThatVerifies) {
    const Golden g = golden("10_duel.replay.json");
    const auto straight = straightHashes(g);
    ASSERT_GE(g.replay.commands.size(), 4u);
    const std::uint64_t secondShot = ReplayPlayer(g.level, g.replay).shotTicks().at(1);
    for (const std::uint64_t t : {std::uint64_t{0}, secondShot, std::uint64_t{secondShot + 1},
                                  std::uint64_t{2400}, g.replay.ticks}) {
        ReplayPlayer p(g.level, g.replay);
        p.seek(g.replay.ticks); // the viewer usually comes back to the moment
        p.seek(t);
        SessionOptions live;
        live.difficulty = Difficulty::Easy;
        live.cpuSeed = 99;
        live.cpuDelayTicks = 30;
        Session s = std::move(p).takeOver(live);
        EXPECT_EQ(s.match().tick(), t);
        if (straight.count(t)) {
            EXPECT_EQ(s.match().hash(), straight.at(t)) << t;
        }
        EXPECT_EQ(commandsToJson(s.recording().commands),
                  commandsToJson(commandsBefore(g.replay, t)))
            << "taking over at tick " << t;
        for (const Checkpoint& c : s.recording().checkpoints)
            EXPECT_LE(c.tick, t);
        // The branch: the computer plays its cannon again, and the person's turns pass.
        for (int i = 0; i < 1500; ++i) {
            if (!s.match().over() && s.match().cannon().def.player != "cpu" && !s.match().shell() &&
                s.match().cannon().shotsLeft > 0 && s.match().tick() % 400 == 0) {
                Command fire;
                fire.kind = CommandKind::Fire;
                s.submit(fire);
            }
            s.step();
        }
        const Replay branch = s.finishedRecording();
        EXPECT_EQ(branch.difficulty, "easy");
        const VerifyResult v =
            verifyReplay(g.level, parseReplay("branch.json", replayToJson(branch)));
        EXPECT_TRUE(v.ok) << "branch from " << t << " diverged at "
                          << v.firstDivergentTick.value_or(0) << " in " << v.diverged;
        EXPECT_EQ(v.checkpoints, branch.checkpoints.size());
    }
}

TEST(ReplayPlayer, JumpsBetweenShots) {
    const Golden g = golden("01_earth_basics.replay.json");
    ReplayPlayer p(g.level, g.replay);
    std::vector<std::uint64_t> fires;
    for (const Command& c : g.replay.commands)
        if (c.kind == CommandKind::Fire) fires.push_back(c.tick);
    ASSERT_GE(fires.size(), 2u);
    EXPECT_EQ(p.shotTicks(), fires);
    EXPECT_FALSE(p.previousShot().has_value());
    ASSERT_EQ(p.nextShot(), fires[0]);
    p.seek(*p.nextShot());
    EXPECT_EQ(p.nextShot(), fires[1]);
    EXPECT_FALSE(p.previousShot().has_value()) << "at the first shot, none before it";
    p.step();
    EXPECT_EQ(p.previousShot(), fires[0]);
    p.seek(p.lastTick());
    EXPECT_EQ(p.previousShot(), fires.back());
    EXPECT_FALSE(p.nextShot().has_value());
}

TEST(ReplayPlayer, AChangedCommandIsReportedAtTheFirstCheckpointAfterIt) {
    Golden g = golden("03_windy_valley.replay.json");
    // The aim the first shot is fired at: the last before the first fire (the computer's
    // earlier aims are its barrel on the way there).
    Command* aim = nullptr;
    for (Command& c : g.replay.commands) {
        if (c.kind == CommandKind::Fire) break;
        if (c.kind == CommandKind::Aim) aim = &c;
    }
    ASSERT_NE(aim, nullptr);
    aim->number += 0.01;
    const std::uint64_t changedAt = aim->tick;
    ReplayPlayer p(g.level, g.replay);
    p.seek(p.lastTick());
    ASSERT_TRUE(p.divergence().has_value());
    EXPECT_GT(p.divergence()->tick, changedAt);
    EXPECT_EQ(p.divergence()->tick % g.replay.checkpointEvery, 0u);
    EXPECT_NE(p.divergence()->what.find("particles"), std::string::npos) << p.divergence()->what;
    // Going back and playing again finds the same first divergence, not a later one.
    const ReplayDivergence first = *p.divergence();
    p.seek(0);
    p.seek(p.lastTick());
    EXPECT_EQ(p.divergence()->tick, first.tick);
}

TEST(ReplayPlayer, AWrongFinalHashIsReportedAtTheEnd) {
    Golden g = golden("02_moon.replay.json");
    g.replay.finalHash ^= 1;
    ReplayPlayer p(g.level, g.replay);
    p.seek(p.lastTick() - 1);
    EXPECT_FALSE(p.divergence().has_value());
    p.step();
    ASSERT_TRUE(p.divergence().has_value());
    EXPECT_EQ(p.divergence()->tick, g.replay.ticks);
    EXPECT_EQ(p.divergence()->what, "final state");
}

TEST(ReplayPlayer, ARefusedCommandIsCountedOnce) {
    Golden g = golden("02_moon.replay.json");
    // A second fire at the tick of the first: the shell is already in flight.
    const auto firstFire =
        std::find_if(g.replay.commands.begin(), g.replay.commands.end(),
                     [](const Command& c) { return c.kind == CommandKind::Fire; });
    ASSERT_NE(firstFire, g.replay.commands.end());
    g.replay.commands.insert(std::next(firstFire), *firstFire);
    ReplayPlayer p(g.level, g.replay);
    p.seek(p.lastTick());
    EXPECT_EQ(p.refusedCommands(), 1u);
    EXPECT_FALSE(p.divergence().has_value()) << "a refused command changes nothing";
    p.seek(0);
    p.seek(p.lastTick());
    EXPECT_EQ(p.refusedCommands(), 1u);
}
