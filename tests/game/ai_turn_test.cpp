// The computer's turn as a player sees it: after a pause it swings its barrel and power
// from where they are to its aim over a second, eased in and out, then fires; the sweep
// is commands like any other, recorded and replayed bit for bit; a moving target is led
// for the moment of the shot, not of the plan.
#include "game/ai_turn.h"
#include "game/replay.h"
#include "game/session.h"

#include "shots.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace game;

namespace {

using shots::level;

Command at(std::uint64_t tick, CommandKind kind, double number = 0.0, std::string text = {}) {
    Command c = shots::cmd(kind, number, std::move(text));
    c.tick = tick;
    return c;
}

constexpr double kDt = 1.0 / 120.0;

} // namespace

TEST(AimSweep, MovesFromTheCurrentAimToTheChosenOneOverASecondThenFires) {
    CannonState cannon;
    cannon.angleDeg = 45.0;
    cannon.speedMps = 30.0;
    const std::vector<Command> turn{at(100, CommandKind::Select, 0.0, "mortar"),
                                    at(100, CommandKind::Aim, 63.25),
                                    at(100, CommandKind::Power, 41.5),
                                    at(100, CommandKind::Fire)};
    const std::vector<Command> sweep = aimSweep(cannon, turn, 100, kDt);
    ASSERT_GE(sweep.size(), 4u);
    EXPECT_EQ(sweep.front().kind, CommandKind::Select) << "the weapon first, then the aim";
    EXPECT_EQ(sweep.front().tick, 100u);
    EXPECT_EQ(sweep.back().kind, CommandKind::Fire);
    EXPECT_EQ(sweep.back().tick, 220u) << "a second (120 ticks) after the plan";
    double angle = cannon.angleDeg, speed = cannon.speedMps;
    std::uint64_t tick = 100;
    int aims = 0;
    std::vector<double> steps;
    for (const Command& c : sweep) {
        EXPECT_GE(c.tick, tick) << "in tick order";
        tick = c.tick;
        if (c.kind == CommandKind::Aim) {
            EXPECT_GE(c.number, angle) << "the barrel only rises toward its aim";
            EXPECT_LE(c.number, 63.25);
            steps.push_back(c.number - angle);
            angle = c.number;
            ++aims;
        } else if (c.kind == CommandKind::Power) {
            EXPECT_GE(c.number, speed);
            speed = c.number;
        }
    }
    EXPECT_EQ(angle, 63.25) << "the last step is the aim itself, not a rounding of it";
    EXPECT_EQ(speed, 41.5);
    EXPECT_EQ(aims, 30) << "30 steps a second";
    // Eased: it starts and ends slowly, fastest in the middle.
    EXPECT_LT(steps.front(), steps[steps.size() / 2]);
    EXPECT_LT(steps.back(), steps[steps.size() / 2]);
}

TEST(AimSweep, ATurnWithoutAShotIsLeftAsItIs) {
    CannonState cannon;
    const std::vector<Command> end{at(7, CommandKind::EndTurn)};
    const std::vector<Command> out = aimSweep(cannon, end, 7, kDt);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].kind, CommandKind::EndTurn);
    EXPECT_EQ(out[0].tick, 7u);
}

TEST(AimSweep, ABarrelAlreadyOnItsAimSendsOnlyThePower) {
    CannonState cannon;
    cannon.angleDeg = 30.0;
    cannon.speedMps = 20.0;
    const std::vector<Command> turn{at(0, CommandKind::Aim, 30.0), at(0, CommandKind::Power, 25.0),
                                    at(0, CommandKind::Fire)};
    for (const Command& c : aimSweep(cannon, turn, 0, kDt)) EXPECT_NE(c.kind, CommandKind::Aim);
}

// On the ridge the computer is player 2. Once the person ends the turn, the session has the
// computer think for its pause, then the barrel moves on many ticks of the next second,
// and the shot follows: all of it in the recording, which replays bit for bit.
TEST(ComputerTurns, TheSessionShowsTheComputerAimingBeforeItFires) {
    const Level duel = level("10_duel.json");
    SessionOptions o;
    o.difficulty = Difficulty::Normal;
    o.cpuDelayTicks = 60;
    Session s(duel, o);
    Command end;
    end.kind = CommandKind::EndTurn;
    ASSERT_EQ(s.submit(end), "");
    const std::uint64_t turnStart = s.match().tick();
    ASSERT_EQ(s.match().cannon().def.player, "cpu");
    std::vector<double> angles;
    std::uint64_t firedAt = 0;
    while (firedAt == 0 && s.match().tick() < turnStart + 600) {
        s.step();
        angles.push_back(s.match().cannon().angleDeg);
        for (const GameEvent& e : s.match().events())
            if (e.kind == EventKind::Fired && e.player == 1) firedAt = e.tick;
    }
    ASSERT_GT(firedAt, 0u) << "the computer fired";
    EXPECT_EQ(firedAt, turnStart + 60 + 120) << "its pause, then a second of aiming";
    std::vector<double> distinct;
    for (const double a : angles)
        if (distinct.empty() || a != distinct.back()) distinct.push_back(a);
    EXPECT_GE(distinct.size(), 20u) << "the barrel visibly moves";
    int aims = 0;
    for (const Command& c : s.recording().commands) aims += c.kind == CommandKind::Aim;
    EXPECT_GE(aims, 20);
    for (int i = 0; i < 1200; ++i) s.step();
    const VerifyResult v = verifyReplay(duel, s.finishedRecording());
    EXPECT_TRUE(v.ok) << v.diverged;
}

// The boat in the harbour sails at 2 m/s: led for the moment the plan is made, a shot
// fired a second later would pass 2 m behind it. The computer leads it for the moment it
// fires, and its first shot hits.
TEST(ComputerTurns, AMovingTargetIsLedForTheMomentOfTheShot) {
    const Level harbour = level("08_water.json");
    SessionOptions o;
    o.autoplay = true;
    o.difficulty = Difficulty::Hard;
    Session s(harbour, o);
    const Target& boat = s.match().targets()[0].def;
    ASSERT_GT(boat.speedMps, 0.0);
    bool over = false;
    while (!over && s.match().tick() < 120 * 30) {
        s.step();
        for (const GameEvent& e : s.match().events()) over = over || e.kind == EventKind::ShotOver;
    }
    ASSERT_TRUE(over);
    EXPECT_TRUE(s.match().targets()[0].hit);
}
