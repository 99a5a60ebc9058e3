// Replays: record, save, load, re-simulate bit for bit; divergence is found and named;
// frame rate, rendering and rewinding never change the result.
#include "game/headless.h"
#include "game/replay.h"
#include "game/session.h"
#include "physics/clock.h"
#include "corpus.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace game;
namespace fs = std::filesystem;

namespace {
const fs::path kSource = ARTILLERY_SOURCE_DIR;
Level level(const std::string& name) { return loadLevel((kSource / "levels" / name).string()); }

// A recorded game: the computer plays every turn of the windy valley for 20 s.
Replay record(std::uint64_t ticks = 2400) {
    SessionOptions o;
    o.autoplay = true;
    o.difficulty = Difficulty::Hard;
    o.cpuDelayTicks = 30;
    Session s(level("03_windy_valley.json"), o);
    while (s.match().tick() < ticks) s.step();
    return s.finishedRecording();
}
} // namespace

TEST(Replay, RoundTripsThroughJsonAndReSimulatesBitForBit) {
    const Replay r = record();
    ASSERT_GE(r.commands.size(), 3u) << "the computer aimed and fired";
    EXPECT_EQ(r.checkpoints.size(), r.ticks / kDefaultCheckpointEvery);
    const Replay back = parseReplay("mem.json", replayToJson(r));
    EXPECT_EQ(back.commands.size(), r.commands.size());
    EXPECT_EQ(back.finalHash, r.finalHash);
    const VerifyResult v = verifyReplay(level("03_windy_valley.json"), back);
    EXPECT_TRUE(v.ok) << "diverged at " << v.firstDivergentTick.value_or(0) << " in " << v.diverged;
    EXPECT_EQ(v.ticks, r.ticks);
    EXPECT_EQ(v.checkpoints, r.checkpoints.size());
    EXPECT_EQ(v.finalHash, r.finalHash);
}

TEST(Replay, ATamperedCommandIsFoundAtTheFirstCheckpointAfterIt) {
    Replay r = record();
    // Change the aim of the first shot by a hundredth of a degree: the last aim before
    // the first fire (the computer's earlier aims are its barrel on the way there).
    Command* aim = nullptr;
    for (Command& c : r.commands) {
        if (c.kind == CommandKind::Fire) break;
        if (c.kind == CommandKind::Aim) aim = &c;
    }
    ASSERT_NE(aim, nullptr);
    aim->number += 0.01;
    const VerifyResult v = verifyReplay(level("03_windy_valley.json"), r);
    EXPECT_FALSE(v.ok);
    ASSERT_TRUE(v.firstDivergentTick.has_value());
    EXPECT_EQ(*v.firstDivergentTick % kDefaultCheckpointEvery, 0u);
    EXPECT_NE(v.diverged.find("particles"), std::string::npos) << v.diverged;
}

TEST(Replay, AReplayForAnotherLevelIsRefused) {
    Replay r = record(240);
    r.levelHash = "0123456789abcdef";
    r.levelFile = (kSource / "levels/03_windy_valley.json").string();
    try {
        levelForReplay("x.json", r);
        FAIL();
    } catch (const LoadError& e) {
        EXPECT_NE(std::string(e.what()).find("recorded on another version"), std::string::npos)
            << e.what();
    }
}

TEST(Replay, BadCorpusGivesTheExpectedMessages) {
    const int cases = checkBadCorpus(kSource / "tests/data/bad_replays",
                                     [](const std::string& f) { loadReplay(f); });
    EXPECT_GE(cases, 10);
}

namespace {
class CountingSink : public FrameSink {
  public:
    void frame(const Match& m) override { sum ^= m.hash(); ++frames; }
    std::uint64_t sum = 0;
    int frames = 0;
};
} // namespace

TEST(Replay, RenderingOrNotGivesTheSameFinalHash) {
    const Replay r = record(1800);
    HeadlessOptions plain;
    plain.commands = r.commands;
    plain.ticks = r.ticks;
    plain.session.autoplay = false;
    const auto a = runHeadless(level("03_windy_valley.json"), plain);
    CountingSink sink;
    HeadlessOptions drawn = plain;
    drawn.sink = &sink;
    drawn.every = 7;
    const auto b = runHeadless(level("03_windy_valley.json"), drawn);
    EXPECT_EQ(a.finalHash, r.finalHash);
    EXPECT_EQ(b.finalHash, r.finalHash);
    EXPECT_EQ(sink.frames, static_cast<int>(r.ticks / 7));
}

TEST(Replay, FrameRateDoesNotChangeTheResult) {
    // A window drives the session through the fixed-step clock at its own frame rate.
    const Replay r = record(1800);
    for (double fps : {30.0, 60.0, 144.0}) {
        Session s(level("03_windy_valley.json"));
        phys::FixedClock clock;
        std::size_t next = 0;
        while (s.match().tick() < r.ticks) {
            for (int n = clock.advance(1.0 / fps); n > 0 && s.match().tick() < r.ticks; --n) {
                while (next < r.commands.size() && r.commands[next].tick <= s.match().tick())
                    s.submit(r.commands[next++]);
                s.step();
            }
        }
        EXPECT_EQ(s.match().hash(), r.finalHash) << fps << " frames per second";
    }
}

TEST(Replay, RewindingToAMidRunSnapshotAndPlayingOnGivesTheSameResult) {
    SessionOptions o;
    o.autoplay = true;
    o.cpuDelayTicks = 30;
    Session s(level("03_windy_valley.json"), o);
    while (s.match().tick() < 600) s.step();
    const auto atSnapshot = s.match().hash();
    while (s.match().tick() < 1200) s.step();
    const Replay full = s.finishedRecording();
    // Back to tick 600: the very state the match had then.
    s.rewindTo(600);
    EXPECT_EQ(s.match().hash(), atSnapshot);
    // Play on with the recorded commands: the same end.
    std::size_t next = 0;
    while (next < full.commands.size() && full.commands[next].tick < 600) ++next;
    Session replayed = std::move(s);
    while (replayed.match().tick() < 1200) {
        while (next < full.commands.size() && full.commands[next].tick <= replayed.match().tick())
            replayed.match().apply(full.commands[next++]);
        replayed.match().step();
    }
    EXPECT_EQ(replayed.match().hash(), full.finalHash);
}
