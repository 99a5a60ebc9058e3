// One verdict per shot (game/verdict.h): its exact text, its points, its side of a miss,
// given once for every shot fired in a whole game, practice and duel.
#include "game/ai.h"
#include "game/headless.h"
#include "game/match.h"
#include "game/replay.h"
#include "game/scoring.h"
#include "game/verdict.h"

#include "shots.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace game;
using namespace shots;

namespace {

std::vector<GameEvent> eventsOf(const std::vector<GameEvent>& all, EventKind k) {
    std::vector<GameEvent> out;
    for (const GameEvent& e : all)
        if (e.kind == k) out.push_back(e);
    return out;
}

/// Steps until the match has given `n` verdicts (or a limit of 60 s).
void untilVerdicts(Match& m, std::size_t n) {
    for (int i = 0; i < 120 * 60 && eventsOf(m.events(), EventKind::Verdict).size() < n; ++i) m.step();
}

void fireAt(Match& m, phys::Vec2 point) {
    const AimSolution aim = aimAt(m, point);
    shoot(m, aim.angleDeg, aim.speedMps);
}

/// Earth basics without wind, its targets kept to one disc at `at`.
Level oneDisc(phys::Vec2 at, double radius) {
    Level l = level("01_earth_basics.json");
    l.physics.windMin = l.physics.windMax = 0.0;
    l.targets.resize(1);
    l.targets[0].position = at;
    l.targets[0].radius = radius;
    l.targets[0].path.clear();
    return l;
}

} // namespace

TEST(Verdict, TextsAreExact) {
    ShotTally hit;
    hit.discsHit = 1;
    hit.points = 150;
    EXPECT_EQ(verdictText(hit, false, {}), "hit +150");
    ShotTally toppled;
    toppled.toppled = 2;
    toppled.points = 200;
    toppled.miss = 0.3; // a miss measured on the way does not speak over what it scored
    toppled.side = "short";
    EXPECT_EQ(verdictText(toppled, false, {}), "toppled 2 +200");
    ShotTally both = toppled;
    both.discsHit = 2;
    both.points = 450;
    EXPECT_EQ(verdictText(both, false, {}), "hit 2 and toppled 2 +450");
    ShotTally cannon;
    cannon.cannonsHit = {1};
    EXPECT_EQ(verdictText(cannon, true, {"your cannon", "the computer's cannon"}),
              "hit the computer's cannon");
    ShotTally miss;
    miss.miss = 4.04;
    miss.side = "short";
    EXPECT_EQ(verdictText(miss, false, {}), "missed by 4.0 m, short");
    EXPECT_EQ(missText(12.06, "over"), "missed by 12.1 m, over");
    EXPECT_EQ(missText(3.0, ""), "missed by 3.0 m");
}

// The side as an observer calls it: the path crossed the target's line above it, below
// it, or never reached it.
TEST(Verdict, MissSideIsHowThePathCrossedTheTarget) {
    EXPECT_EQ(missSide(1), "over");
    EXPECT_EQ(missSide(-1), "under");
    EXPECT_EQ(missSide(0), "short");
}

TEST(Verdict, AHitGivesOneVerdictWithItsPoints) {
    Match m(oneDisc({140.0, 8.0}, 1.5));
    fireAt(m, m.targets()[0].position);
    untilVerdicts(m, 1);
    const auto hits = eventsOf(m.events(), EventKind::TargetHit);
    const auto verdicts = eventsOf(m.events(), EventKind::Verdict);
    ASSERT_EQ(hits.size(), 1u);
    ASSERT_EQ(verdicts.size(), 1u);
    EXPECT_EQ(verdicts[0].value, hits[0].value);
    EXPECT_EQ(verdicts[0].text, "hit +" + std::to_string(static_cast<int>(hits[0].value)));
    EXPECT_EQ(verdicts[0].player, 0);
    EXPECT_EQ(verdicts[0].value, m.score() - kShotBonus * m.cannon().shotsLeft)
        << "the one target down: the score is the hit and the bonus";
}

// A shot that falls short of a disc by a known distance: the verdict says short and by
// how much, measured here from the shell's own path to the disc's rim.
TEST(Verdict, AShortMissSaysByHowMuch) {
    Match m(oneDisc({140.0, 8.0}, 1.5));
    shoot(m, 45.0, 18.0);
    double closest = INFINITY;
    while (m.shell()) {
        m.step();
        if (!m.shell()) break;
        const phys::Vec2 q = m.world().particles.position(*m.shell());
        closest = std::min(closest, length(q - m.targets()[0].position) - m.targets()[0].def.radius);
    }
    // Its last place is where it burst (the shell is gone by the end of that tick).
    for (const GameEvent& e : eventsOf(m.events(), EventKind::Burst))
        closest = std::min(closest, length(e.where - m.targets()[0].position) - m.targets()[0].def.radius);
    untilVerdicts(m, 1);
    const auto verdicts = eventsOf(m.events(), EventKind::Verdict);
    ASSERT_EQ(verdicts.size(), 1u);
    EXPECT_EQ(verdicts[0].text, missText(closest, "short"));
    EXPECT_EQ(verdicts[0].value, 0.0);
}

// A disc high in the air, one shot through a point 4 m above it and one through a point
// 4 m below it: both land beyond it, neither is long; they are over and under.
TEST(Verdict, AShotOverADiscSaysOverAndOneUnderItUnder) {
    for (const double dy : {4.0, -4.0}) {
        Match m(oneDisc({110.0, 25.0}, 1.0));
        const AimSolution aim = aimAt(m, m.targets()[0].position + phys::Vec2{0.0, dy});
        shoot(m, aim.angleDeg, aim.speedMps);
        untilVerdicts(m, 1);
        const auto verdicts = eventsOf(m.events(), EventKind::Verdict);
        ASSERT_EQ(verdicts.size(), 1u);
        EXPECT_TRUE(verdicts[0].text.ends_with(dy > 0 ? " m, over" : " m, under")) << verdicts[0].text;
        EXPECT_GT(verdicts[0].where.x, 111.0) << "it came down beyond the disc";
    }
}

namespace {

/// Fires at the highest target block (the top of Tower's tower); false if there is none.
bool fireAtTheTop(Match& m) {
    const BlockState* top = nullptr;
    for (const auto& b : m.blocks())
        if (b.def.target && (!top || b.def.position.y > top->def.position.y)) top = &b;
    if (!top) return false;
    fireAt(m, top->def.position);
    return true;
}

} // namespace

// Tower: the shell knocks the top block off and comes to rest before the blocks it set
// moving have fallen. The verdict waits for them: one verdict, the toppled and their
// points, and no miss beside it.
TEST(Verdict, AToppleAfterTheShotEndsGivesOnlyTheToppledVerdict) {
    Level l = level("25_tower.json");
    l.physics.windMin = l.physics.windMax = 0.0;
    Match m(l);
    ASSERT_TRUE(fireAtTheTop(m));
    untilVerdicts(m, 1);
    const auto toppled = eventsOf(m.events(), EventKind::Toppled);
    const auto over = eventsOf(m.events(), EventKind::ShotOver);
    const auto verdicts = eventsOf(m.events(), EventKind::Verdict);
    ASSERT_FALSE(toppled.empty());
    ASSERT_EQ(over.size(), 1u);
    EXPECT_GT(toppled.back().tick, over[0].tick) << "a block fell after the shot was over";
    ASSERT_EQ(verdicts.size(), 1u);
    EXPECT_GE(verdicts[0].tick, toppled.back().tick);
    int points = 0;
    for (const GameEvent& e : toppled) points += static_cast<int>(e.value);
    EXPECT_EQ(verdicts[0].value, points);
    const std::string expected =
        (toppled.size() == 1 ? std::string("toppled") : "toppled " + std::to_string(toppled.size())) +
        " +" + std::to_string(points);
    EXPECT_EQ(verdicts[0].text, expected);
}

// The same shot as the last of the game: the game is not over when the shell is, but once
// the tower has come down, so the blocks that fall late are in its verdict and its score,
// and the end comes after them.
TEST(Verdict, TheLastShotsLateToppleIsInItsVerdictAndTheGamesEnd) {
    Level l = level("25_tower.json");
    l.physics.windMin = l.physics.windMax = 0.0;
    l.shots = 1;
    Match m(l);
    ASSERT_TRUE(fireAtTheTop(m));
    for (int i = 0; i < 120 * 60 && !m.over(); ++i) m.step();
    ASSERT_TRUE(m.over());
    const auto toppled = eventsOf(m.events(), EventKind::Toppled);
    const auto over = eventsOf(m.events(), EventKind::ShotOver);
    const auto verdicts = eventsOf(m.events(), EventKind::Verdict);
    const auto end = eventsOf(m.events(), EventKind::MatchOver);
    ASSERT_FALSE(toppled.empty());
    ASSERT_EQ(over.size(), 1u);
    ASSERT_EQ(end.size(), 1u);
    EXPECT_GT(toppled.back().tick, over[0].tick) << "a block fell after the shot was over";
    EXPECT_GE(end[0].tick, toppled.back().tick);
    ASSERT_EQ(verdicts.size(), 1u);
    int points = 0;
    for (const GameEvent& e : toppled) points += static_cast<int>(e.value);
    EXPECT_EQ(verdicts[0].value, points);
    EXPECT_EQ(m.score(), points); // one shot, no shot left for a bonus
    for (int i = 0; i < 120 * 10; ++i) m.step();
    EXPECT_EQ(eventsOf(m.events(), EventKind::Toppled).size(), toppled.size())
        << "nothing falls after the game's end";
}

namespace {

/// A whole game the computer plays on `file`: its events.
HeadlessSummary autoplayed(const std::string& file) {
    HeadlessOptions o;
    o.session.autoplay = true;
    return runHeadless(level(file), o);
}

} // namespace

// A whole autoplayed level: as many verdicts as shots, each by the shooter after its shot
// was fired and before the next, and their points add up to the score less the bonus.
TEST(Verdict, OnePerShotInAWholePracticeGame) {
    const HeadlessSummary s = autoplayed("05_castle.json");
    ASSERT_TRUE(s.over);
    const auto fired = eventsOf(s.events, EventKind::Fired);
    const auto verdicts = eventsOf(s.events, EventKind::Verdict);
    ASSERT_GE(fired.size(), 2u);
    ASSERT_EQ(verdicts.size(), fired.size());
    int points = 0;
    for (std::size_t i = 0; i < fired.size(); ++i) {
        EXPECT_GE(verdicts[i].tick, fired[i].tick);
        if (i + 1 < fired.size()) {
            EXPECT_LE(verdicts[i].tick, fired[i + 1].tick);
        }
        EXPECT_EQ(verdicts[i].player, fired[i].player);
        points += static_cast<int>(verdicts[i].value);
    }
    const auto end = eventsOf(s.events, EventKind::MatchOver);
    ASSERT_EQ(end.size(), 1u);
    const int bonus = s.winner == 0 ? kShotBonus * (level("05_castle.json").shots - s.shots) : 0;
    EXPECT_EQ(points + bonus, s.score);
}

// A duel: one verdict per shot, each worth 0 points; a shot that hit a cannon says whose.
TEST(Verdict, DuelVerdictsAreWorthNothing) {
    const HeadlessSummary s = autoplayed("10_duel.json");
    const auto fired = eventsOf(s.events, EventKind::Fired);
    const auto verdicts = eventsOf(s.events, EventKind::Verdict);
    ASSERT_FALSE(fired.empty());
    ASSERT_EQ(verdicts.size(), fired.size());
    int hits = 0;
    for (const GameEvent& v : verdicts) {
        EXPECT_EQ(v.value, 0.0);
        const bool hit = v.text.starts_with("hit ") && v.text.ends_with("cannon");
        EXPECT_TRUE(hit || v.text.starts_with("missed")) << v.text;
        hits += hit;
    }
    EXPECT_GT(hits, 0) << "a duel is won by hits";
}

// Every golden replay, played on 35 s past its end so its last shot settles: one verdict
// for each shot fired, by its shooter; in practice their points and the bonus are the
// score at the match's end, in a duel they are worth nothing. A sandbox has nothing to
// judge: no verdicts.
TEST(Verdict, OnePerShotInEveryGoldenReplay) {
    const auto folder = std::filesystem::path(ARTILLERY_SOURCE_DIR) / "tests" / "replays";
    int replays = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string file = entry.path().string();
        if (!file.ends_with(".replay.json")) continue;
        ++replays;
        const Replay replay = loadReplay(file);
        const Level l = levelForReplay(file, replay);
        Match m(l);
        runCommands(m, replay.commands, replay.ticks);
        // On past its end until its last shot is over (a flight lasts 30 s at most) and
        // 5 s more.
        for (int i = 0; i < 120 * 35; ++i) m.step();
        const auto fired = eventsOf(m.events(), EventKind::Fired);
        const auto verdicts = eventsOf(m.events(), EventKind::Verdict);
        ASSERT_FALSE(fired.empty()) << file;
        ASSERT_EQ(verdicts.size(), l.mode == Mode::Sandbox ? 0u : fired.size()) << file;
        if (l.mode == Mode::Sandbox) continue;
        int points = 0;
        for (std::size_t i = 0; i < fired.size(); ++i) {
            EXPECT_EQ(verdicts[i].player, fired[i].player) << file;
            points += static_cast<int>(verdicts[i].value);
        }
        if (l.mode == Mode::Duel) {
            EXPECT_EQ(points, 0) << file;
        } else if (l.mode == Mode::Practice) {
            // The score when the match ended (a block the last shot topples after the end
            // still scores, but was not yet down when the verdict was given).
            const auto end = eventsOf(m.events(), EventKind::MatchOver);
            const int bonus = m.winner() == 0 ? kShotBonus * m.cannons()[0].shotsLeft : 0;
            EXPECT_EQ(points + bonus, end.empty() ? m.score() : static_cast<int>(end[0].value)) << file;
        }
    }
    EXPECT_GE(replays, 10);
}
