// Effects, shot feedback, the camera rig and the preview assist: views of the match that
// never change it, checked against the golden replays' hashes, the closed form, the
// exponential approach the camera and the smoke follow, and exact feedback text.
#include "game/effects/camera_rig.h"
#include "game/effects/effects.h"
#include "game/effects/shot_feedback.h"
#include "game/files/text_file.h"
#include "game/replay.h"

#include "shots.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace game;
namespace fs = std::filesystem;

namespace {
const fs::path kSource = ARTILLERY_SOURCE_DIR;
using shots::cmd;
using shots::level;
using shots::shoot;
} // namespace

// Golden replays with blasts, bounces, toppling blocks, splashes and a duel: with effects
// observing every tick, every checkpoint hash and the final hash are the recorded ones.
TEST(Effects, NeverChangeAGoldenReplaysHashes) {
    for (const char* name : {"01_earth_basics", "05_castle", "08_water", "10_duel"}) {
        SCOPED_TRACE(name);
        const std::string file =
            (kSource / "tests/replays" / (std::string(name) + ".replay.json")).string();
        const Replay r = loadReplay(file);
        Match m(levelForReplay(file, r));
        Effects fx;
        CameraRig rig;
        rig.setHome({100.0, 30.0}, 8.0);
        std::size_t next = 0, cp = 0, matched = 0;
        while (m.tick() < r.ticks) {
            while (next < r.commands.size() && r.commands[next].tick <= m.tick())
                m.apply(r.commands[next++]);
            m.step();
            fx.observe(m);
            rig.tick(m);
            while (cp < r.checkpoints.size() && r.checkpoints[cp].tick == m.tick()) {
                ASSERT_EQ(m.hash(), r.checkpoints[cp].hash) << "at tick " << m.tick();
                ++cp, ++matched;
            }
        }
        EXPECT_EQ(matched, r.checkpoints.size());
        EXPECT_EQ(m.hash(), r.finalHash);
        EXPECT_GT(fx.thrown(), 0u) << "the effects ran: something was thrown";
    }
}

// Every piece in the air is on the closed form p(t) = p0 + v0 t + g t^2 / 2.
TEST(Effects, DebrisFollowsTheClosedForm) {
    Match m(level("01_earth_basics.json"));
    Effects fx;
    m.step();
    fx.observe(m);
    fx.blast({120.0, 80.0}, 3.0, 150.0, 0); // high above the ground: nothing lands for 1 s
    const phys::ParticleSet& ps = fx.pieces();
    const std::size_t n = ps.count();
    ASSERT_GE(n, 30u);
    struct Start {
        double x, y, vx, vy;
    };
    std::vector<Start> start;
    std::vector<phys::ParticleId> ids;
    for (std::size_t i = 0; i < ps.flags.size(); ++i)
        if (ps.flags[i] & phys::kAlive) {
            start.push_back({ps.px[i], ps.py[i], ps.vx[i], ps.vy[i]});
            ids.push_back(static_cast<phys::ParticleId>(i));
        }
    const double g = m.world().def().forces.gravity.y;
    const double dt = m.world().def().tickSeconds;
    for (int k = 1; k <= 90; ++k) {
        m.step();
        fx.observe(m);
        const double t = k * dt;
        for (std::size_t j = 0; j < ids.size(); ++j) {
            const auto i = ids[j];
            ASSERT_TRUE(ps.flags[i] & phys::kAlive);
            EXPECT_NEAR(ps.px[i], start[j].x + start[j].vx * t, 1e-9);
            EXPECT_NEAR(ps.py[i], start[j].y + start[j].vy * t + 0.5 * g * t * t, 1e-9);
            EXPECT_NEAR(ps.vy[i], start[j].vy + g * t, 1e-9);
        }
        // Every piece on the closed form, none integrated.
        EXPECT_EQ(fx.profile().closedForm, static_cast<int>(n));
        EXPECT_EQ(fx.profile().integrated, 0);
    }
    EXPECT_EQ(m.world().def().forces.gravity.y, g);
}

// The shake is the blast's energy (impulse times radius) relative to a cannonball's
// (150 N s over 3 m), at most 1, halving every 0.12 s.
TEST(Effects, ShakeScalesWithTheBlastAndDecays) {
    Match m(level("01_earth_basics.json"));
    Effects fx;
    m.step();
    fx.observe(m);
    fx.blast({120.0, 80.0}, 1.5, 75.0, 0);
    EXPECT_DOUBLE_EQ(fx.shake(), 0.25);
    fx.blast({120.0, 80.0}, 3.0, 300.0, 0);
    EXPECT_DOUBLE_EQ(fx.shake(), 1.0) << "capped";
    const double dt = m.world().def().tickSeconds;
    for (int n = 1; n <= 30; ++n) {
        m.step();
        fx.observe(m);
        EXPECT_NEAR(fx.shake(), std::exp2(-n * dt / 0.12), 1e-12);
    }
}

// What comes down on the ground stays there as soil, on the ground's surface.
TEST(Effects, SoilSettlesOnTheGround) {
    Match m(level("01_earth_basics.json"));
    Effects fx;
    m.step();
    fx.observe(m);
    fx.blast({60.0, m.terrain().heightAt(60.0) + 0.1}, 3.0, 150.0, 0);
    for (int k = 0; k < 600; ++k) {
        m.step();
        fx.observe(m);
    }
    EXPECT_EQ(fx.pieces().count(), 0u) << "everything came down within 5 s";
    ASSERT_GT(fx.specks().size(), 10u);
    for (const Speck& s : fx.specks())
        EXPECT_DOUBLE_EQ(s.where.y, m.terrain().heightAt(s.where.x));
    EXPECT_EQ(fx.flashes().size(), 0u) << "the flash is long gone";
}

// A puff's velocity relaxes to the wind plus its rise: after n ticks
// v_n = w + (v_0 - w) r^n with r = exp(-dt / tau) (the discrete form of the exponential).
TEST(Effects, SmokeDriftsWithTheWind) {
    Level l = level("03_windy_valley.json");
    l.physics.windMin = l.physics.windMax = 6.0;
    Match m(l);
    ASSERT_DOUBLE_EQ(m.wind(), 6.0);
    EffectsDef d;
    Effects fx(d);
    m.step();
    fx.observe(m);
    fx.blast({100.0, 90.0}, 3.0, 150.0, 0);
    ASSERT_FALSE(fx.smoke().empty());
    const std::vector<Smoke> start = fx.smoke();
    const int n = 100;
    for (int k = 0; k < n; ++k) {
        m.step();
        fx.observe(m);
    }
    const double dt = m.world().def().tickSeconds;
    const double r = std::pow(std::exp(-dt / d.smokeRelaxSeconds), n);
    ASSERT_EQ(fx.smoke().size(), start.size());
    for (std::size_t i = 0; i < start.size(); ++i) {
        EXPECT_NEAR(fx.smoke()[i].velocity.x, 6.0 + (start[i].velocity.x - 6.0) * r, 1e-9);
        EXPECT_NEAR(fx.smoke()[i].velocity.y,
                    d.smokeRiseMps + (start[i].velocity.y - d.smokeRiseMps) * r, 1e-9);
    }
}

// The same match gives the same effects (seeded by the level, stepped by ticks).
TEST(Effects, AreTheSameForTheSameMatch) {
    auto run = [] {
        Match m(level("05_castle.json"));
        Effects fx;
        shoot(m, 30.0, 40.0); // a cannonball: it bursts where it lands
        for (int k = 0; k < 800; ++k) {
            m.step();
            fx.observe(m);
        }
        std::vector<double> out;
        for (std::size_t i = 0; i < fx.pieces().flags.size(); ++i)
            if (fx.pieces().flags[i] & phys::kAlive) out.push_back(fx.pieces().px[i]);
        for (const Speck& s : fx.specks())
            out.push_back(s.where.x);
        return out;
    };
    const auto a = run();
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, run());
}

// A shell that enters the water splashes where it crossed the water line: a ring there,
// and spray thrown up from it.
// Looked at every tick (the window) or every tenth (frames written every 10 ticks).
TEST(Effects, AShellEnteringTheWaterSplashes) {
    const Level l = level("08_water.json");
    ASSERT_TRUE(l.physics.water);
    for (const int every : {1, 10}) {
        SCOPED_TRACE(every);
        Match m(l);
        Effects fx;
        ASSERT_EQ(m.apply(cmd(CommandKind::Select, 0.0, "tennis-ball")), ""); // does not burst
        shoot(m, 45.0, 28.0);
        bool rippled = false;
        for (int k = 1; k < 1200 && !rippled; ++k) {
            m.step();
            if (k % every == 0) fx.observe(m);
            rippled = !fx.ripples().empty();
        }
        ASSERT_TRUE(rippled) << "the ball reached the water";
        EXPECT_NEAR(fx.ripples()[0].where.y, l.physics.waterLevel, 1e-9);
        EXPECT_GT(fx.thrown(PieceKind::Spray), 10u);
        EXPECT_EQ(fx.thrown(PieceKind::Soil), 0u);
    }
}

// Blocks that topple, or are hit hard, throw splinters of their material: the castle's
// golden replay knocks blocks over.
TEST(Effects, ToppledBlocksSplinter) {
    const std::string file = (kSource / "tests/replays/05_castle.replay.json").string();
    const Replay r = loadReplay(file);
    Match m(levelForReplay(file, r));
    Effects fx;
    std::size_t next = 0;
    while (m.tick() < r.ticks) {
        while (next < r.commands.size() && r.commands[next].tick <= m.tick())
            m.apply(r.commands[next++]);
        m.step();
        fx.observe(m);
    }
    int toppled = 0;
    for (const GameEvent& e : m.events())
        toppled += e.kind == EventKind::Toppled;
    ASSERT_GT(toppled, 0) << "the replay topples blocks";
    EXPECT_GE(fx.thrown(PieceKind::Splinter), static_cast<std::size_t>(10 * toppled));
}

// The feedback judges nothing itself: the verdict it shows is the match's, word for word,
// and a shot that scored nothing leaves a marker where it came down.
TEST(ShotFeedback, ShowsTheMatchVerdict) {
    Level l = level("01_earth_basics.json");
    l.physics.windMin = l.physics.windMax = 0.0;
    Match m(l);
    Effects fx;
    shoot(m, 45.0, 18.0); // short of every target
    std::string verdict;
    for (int k = 0; k < 3000 && verdict.empty(); ++k) {
        m.step();
        fx.observe(m);
        for (const GameEvent& e : m.events())
            if (e.kind == EventKind::Verdict) verdict = e.text;
    }
    ASSERT_NE(verdict.find("missed by"), std::string::npos) << verdict;
    EXPECT_EQ(fx.feedback().verdict(), verdict);
    int markers = 0;
    for (const ShotNote& n : fx.feedback().notes()) markers += n.kind == ShotNote::Kind::Miss;
    EXPECT_EQ(markers, 1);
    shoot(m, 45.0, 18.0);
    fx.observe(m);
    EXPECT_EQ(fx.feedback().verdict(), "") << "the next shot clears it";
}

namespace {

/// Where the last shell burst (x = 0 before any did).
phys::Vec2 lastBurst(const Match& m) {
    phys::Vec2 burst;
    for (const GameEvent& e : m.events())
        if (e.kind == EventKind::Burst) burst = e.where;
    return burst;
}

/// Plays on while the camera holds on the impact.
void holdOnTheImpact(Match& m, CameraRig& rig) {
    while (rig.phase() == CameraRig::Phase::Holding) {
        m.step();
        rig.tick(m);
    }
}

} // namespace

// The camera keeps the shell in view while it flies and closes in on it as it nears the
// targets, holds on the impact, then goes home along
// c(n) = home + (c0 - home) exp(-n dt / tau).
TEST(CameraRig, ConvergesToTheShellAndReturnsHome) {
    Level l = level("01_earth_basics.json");
    l.physics.windMin = l.physics.windMax = 0.0;
    Match m(l);
    CameraRigDef def;
    CameraRig rig(def);
    const phys::Vec2 home{120.0, 40.0};
    const int W = 1280, H = 720;
    rig.setHome(home, 5.0, W, H);
    shoot(m, 40.0, 32.0);
    int followed = 0;
    while (m.shell()) {
        m.step();
        rig.tick(m);
        if (!m.shell()) break;
        ++followed;
        EXPECT_EQ(rig.phase(), CameraRig::Phase::Following);
        const phys::Vec2 s = m.world().particles.position(*m.shell());
        if (followed < 60) continue; // half a second to catch up from home
        // In view: within the half-extents of the picture at the rig's zoom.
        EXPECT_LT(std::abs(s.x - rig.center().x), 0.5 * W / rig.pixelsPerMetre());
        EXPECT_LT(std::abs(s.y - rig.center().y), 0.5 * H / rig.pixelsPerMetre());
    }
    ASSERT_GT(followed, 120);
    EXPECT_GT(rig.pixelsPerMetre(), 5.0 * 1.3) << "closed in on the shell near the first target";
    EXPECT_EQ(rig.phase(), CameraRig::Phase::Holding);
    const phys::Vec2 burst = lastBurst(m);
    ASSERT_GT(burst.x, 0.0) << "the cannonball burst";
    holdOnTheImpact(m, rig);
    // The impact framed low in the picture: the view's centre 15 % of its height above it.
    const double above = 0.15 * H / rig.pixelsPerMetre();
    EXPECT_NEAR(rig.center().x, burst.x, 0.05 * W / rig.pixelsPerMetre());
    EXPECT_NEAR(rig.center().y, burst.y + above, 0.05 * H / rig.pixelsPerMetre());
    // Held for 1.2 s = 3.4 tau: within 4 % of the impact's zoom.
    EXPECT_NEAR(rig.pixelsPerMetre(), 5.0 * def.impactZoom, 5.0 * def.impactZoom * 0.04);
    ASSERT_EQ(rig.phase(), CameraRig::Phase::Returning);
    const double dt = m.world().def().tickSeconds;
    const phys::Vec2 c0 = rig.center();
    for (int n = 1; n <= 240; ++n) {
        m.step();
        rig.tick(m);
        const double f = std::exp(-n * dt / def.returnSeconds);
        const phys::Vec2 want = home + (c0 - home) * f;
        ASSERT_NEAR(rig.center().x, want.x, 1e-6 * (1.0 + length(c0 - home)));
        ASSERT_NEAR(rig.center().y, want.y, 1e-6 * (1.0 + length(c0 - home)));
    }
    for (int n = 0; n < 1200 && rig.phase() != CameraRig::Phase::Home; ++n) {
        m.step();
        rig.tick(m);
    }
    EXPECT_EQ(rig.phase(), CameraRig::Phase::Home);
    EXPECT_NEAR(rig.pixelsPerMetre(), 5.0, 1e-5);
}

// With the bottom of the view covered by panels (the Match panel as it opens covers the
// lowest 37 % at 1280x720), the shell and the impact are framed in the open part above:
// the shell stays in it while followed, and the impact is held low in it, 15 % of the
// open height below its middle.
TEST(CameraRig, FramesTheShotAboveTheCoveredBottom) {
    Level l = level("01_earth_basics.json");
    l.physics.windMin = l.physics.windMax = 0.0;
    Match m(l);
    CameraRig rig;
    const int W = 1280, H = 720;
    const double covered = 0.37;
    rig.setHome({120.0, 40.0}, 5.0, W, H);
    rig.setCoveredBottom(covered);
    shoot(m, 40.0, 32.0);
    // Height above the covered band, px (negative: under the panels).
    auto aboveBand = [&](phys::Vec2 p) {
        const double bottom = rig.center().y - 0.5 * H / rig.pixelsPerMetre();
        return (p.y - bottom) * rig.pixelsPerMetre() - covered * H;
    };
    int followed = 0;
    double lowest = INFINITY;
    while (m.shell()) {
        m.step();
        rig.tick(m);
        if (!m.shell() || ++followed < 60) continue; // half a second to catch up from home
        lowest = std::min(lowest, aboveBand(m.world().particles.position(*m.shell())));
    }
    ASSERT_GT(followed, 120);
    EXPECT_GT(lowest, 0.0) << "the shell went under the covered band";
    const phys::Vec2 burst = lastBurst(m);
    ASSERT_GT(burst.x, 0.0) << "the cannonball burst";
    holdOnTheImpact(m, rig);
    const double open = (1.0 - covered) * H;
    EXPECT_NEAR(aboveBand(burst), 0.5 * open - 0.15 * open, 0.05 * H);

    // Nothing covered: the framing of ConvergesToTheShellAndReturnsHome, bit for bit.
    Match a(l), b(l);
    CameraRig plain, uncovered;
    plain.setHome({120.0, 40.0}, 5.0, W, H);
    uncovered.setHome({120.0, 40.0}, 5.0, W, H);
    uncovered.setCoveredBottom(0.0);
    shoot(a, 40.0, 32.0);
    shoot(b, 40.0, 32.0);
    for (int n = 0; n < 600; ++n) {
        a.step();
        b.step();
        plain.tick(a);
        uncovered.tick(b);
        ASSERT_EQ(plain.center().x, uncovered.center().x);
        ASSERT_EQ(plain.center().y, uncovered.center().y);
        ASSERT_EQ(plain.pixelsPerMetre(), uncovered.pixelsPerMetre());
    }
}

TEST(CameraRig, TheWheelZoomsHomeToo) {
    Match m(level("01_earth_basics.json"));
    CameraRig rig;
    rig.setHome({100.0, 30.0}, 5.0);
    rig.zoomBy(2.0);
    for (int n = 0; n < 240; ++n) {
        m.step();
        rig.tick(m);
    }
    EXPECT_DOUBLE_EQ(rig.pixelsPerMetre(), 10.0);
    EXPECT_EQ(rig.phase(), CameraRig::Phase::Home);
}

// The learning aids are commands: recorded, replayed, and they cap a practice result at
// two stars. A golden replay that earns three earns two with an assist at tick 0, and
// the hashes of the unassisted replay stay the recorded ones.
TEST(Assist, CapsStarsAtTwo) {
    int capped = 0;
    for (const auto& entry : fs::directory_iterator(kSource / "tests/replays")) {
        if (entry.path().extension() != ".json" ||
            entry.path().filename().string().find(".replay.") == std::string::npos)
            continue;
        const Replay r = loadReplay(entry.path().string());
        const Level l = levelForReplay(entry.path().string(), r);
        Match plain(l);
        runCommands(plain, r.commands, r.ticks);
        EXPECT_EQ(plain.hash(), r.finalHash) << entry.path();
        EXPECT_EQ(plain.assisted(), 0);
        if (plain.stars() != 3) continue;
        std::vector<Command> cmds = r.commands;
        Command a = cmd(CommandKind::Assist, 0.0, "preview");
        cmds.insert(cmds.begin(), a);
        // Through the file format, as a replay carries it.
        const std::vector<Command> back = parseCommands("mem.json", commandsToJson(cmds));
        ASSERT_EQ(back.front().kind, CommandKind::Assist);
        ASSERT_EQ(back.front().text, "preview");
        Match assisted(l);
        runCommands(assisted, back, r.ticks);
        EXPECT_EQ(assisted.assisted(), kAssistPreview);
        EXPECT_EQ(assisted.score(), plain.score()) << "the aid changes the stars, not the score";
        EXPECT_EQ(assisted.stars(), 2) << entry.path();
        EXPECT_NE(assisted.gameHash(), plain.gameHash())
            << "a replay carries the aid in its hashes";
        ++capped;
    }
    EXPECT_GE(capped, 1) << "some golden replay earns three stars";
}

TEST(Assist, BadKindIsRefusedWithTheChoices) {
    try {
        parseCommands("cmds.json", R"([{"tick": 0, "cmd": "assist", "what": "aimbot"}])");
        FAIL() << "accepted an unknown aid";
    } catch (const LoadError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("cmds.json"), std::string::npos) << what;
        EXPECT_NE(what.find("preview"), std::string::npos) << what;
        EXPECT_NE(what.find("hint"), std::string::npos) << what;
    }
    Match m(level("01_earth_basics.json"));
    EXPECT_NE(m.apply(cmd(CommandKind::Assist, 0.0, "aimbot")), "");
    EXPECT_EQ(m.assisted(), 0);
    EXPECT_EQ(m.apply(cmd(CommandKind::Assist, 0.0, "hint")), "");
    EXPECT_EQ(m.assisted(), kAssistHint);
}
