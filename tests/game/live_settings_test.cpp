// Live controls as settings: each projectile's restitution preset, the
// material pair table, the contact model and continuous detection, set by `set`
// commands in a match. Checked against the physics they stand for: a drop rebounds to
// e^2 H (Claypool, Game Physics (ch. 10): e = sqrt(h/H)), a penalty contact sinks as its spring and damper
// say, continuous detection stops what tunnels without it; refusals say what was
// expected; a replay carrying these commands re-simulates bit for bit.
#include "game/headless.h"
#include "game/match.h"
#include "game/replay.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

using namespace game;
namespace fs = std::filesystem;

namespace {
const fs::path kLevels = fs::path(ARTILLERY_SOURCE_DIR) / "levels";
constexpr double kG = 9.81;

Command set(const std::string& name, SettingValue value, std::uint64_t tick = 0) {
    Command c;
    c.kind = CommandKind::Set;
    c.text = name;
    c.value = std::move(value);
    c.tick = tick;
    return c;
}

Command number(CommandKind k, double x) {
    Command c;
    c.kind = k;
    c.number = x;
    return c;
}

/// A sandbox over a rigid reference floor (material "floor", e = 1), no air: a cannon
/// pointing straight down releases a ball at rest with its bottom `drop` m above it.
Level dropLevel(double drop, double radius) {
    const double y = drop + radius + 1.5; // the muzzle is 1.5 m along the barrel
    const std::string text = R"({"format": 1, "name": "drop", "mode": "sandbox",
        "world": {"min": [0, -10], "max": [200, 100]},
        "physics": {"drag": false, "wind": 0},
        "terrain": {"points": [[0, 0], [200, 0]], "material": "floor", "destructible": false},
        "cannons": [{"position": [100, )" + std::to_string(y) + R"(], "angle_deg": -90,
                     "speed_mps": 0, "projectiles": ["golf-ball", "tennis-ball", "steel-ball"]}]})";
    return parseLevel("drop.json", text);
}

double radiusOf(const std::string& projectile) {
    return 0.5 * phys::projectileFromName(projectile)->diameter;
}

struct Drop {
    double releaseBottom = 0.0; ///< height of the ball's bottom when released, m
    /// The bounce the particle layer resolved at the time of impact: normal speed before
    /// and after. e = sqrt(h/H) with H = u^2/2g and h = v^2/2g is v/u.
    double closingSpeed = 0.0, reboundSpeed = 0.0;
    double apex = 0.0;    ///< apex of the bottom after the first bounce, from the ticks, m
    double deepest = 0.0; ///< lowest the bottom went (negative: into the floor), m
};

/// Fires the selected ball (speed 0, straight down) and follows it to the first bounce.
Drop dropBall(Match& m, const std::vector<Command>& during = {}) {
    EXPECT_EQ(m.apply(number(CommandKind::Fire, 0.0)), "");
    const phys::ParticleId id = m.shell().value();
    const auto& ps = m.world().particles;
    const double r = ps.radius[id];
    Drop d;
    d.releaseBottom = ps.position(id).y - r;
    d.deepest = d.releaseBottom;
    for (const Command& c : during) EXPECT_EQ(m.apply(c), "") << c.text;
    for (int i = 0; i < 120 * 10; ++i) {
        m.step();
        if (!m.shell()) break;
        for (const phys::ContactEvent& e : m.world().contacts())
            if (e.a == id && e.b == phys::kNoParticle && !e.resting && d.closingSpeed == 0.0) {
                d.closingSpeed = e.closingSpeed;
                d.reboundSpeed = dot(e.velocity, e.normal);
            }
        const phys::Vec2 p = ps.position(id), v = ps.velocity(id);
        d.deepest = std::min(d.deepest, p.y - r);
        if (v.y > 0.0 && p.y - r >= 0.0) { // risen out of the floor: a parabola from here
            d.apex = p.y - r + v.y * v.y / (2.0 * kG);
            return d;
        }
    }
    ADD_FAILURE() << "no bounce";
    return d;
}

/// The bounce against the measured e = sqrt(h/H): exact at the contact and, since the
/// particles meet the terrain only as the world's static shapes (the coupling skips its
/// Box2D mirror), exact at the apex over the ticks too.
void expectBounce(const Drop& d, double e, const char* what) {
    const double H = d.releaseBottom;
    EXPECT_NEAR(d.reboundSpeed / d.closingSpeed, e, 1e-12) << what;
    EXPECT_NEAR(d.closingSpeed, std::sqrt(2.0 * kG * H), 1e-9) << what;
    EXPECT_NEAR(d.apex, e * e * H, 1e-9) << what;
    EXPECT_GE(d.deepest, -1e-9) << what << ": the impulse model never lets the ball in";
}

Match dropMatch(const std::string& projectile, double drop, const std::vector<Command>& before) {
    Match m(dropLevel(drop, radiusOf(projectile)));
    Command select;
    select.kind = CommandKind::Select;
    select.text = projectile;
    EXPECT_EQ(m.apply(select), "");
    for (const Command& c : before) EXPECT_EQ(m.apply(c), "") << c.text;
    return m;
}

double presetE(const std::string& name) {
    for (const auto& p : phys::kRestitutionPresets)
        if (name == p.name) return p.restitution;
    ADD_FAILURE() << name;
    return 0.0;
}
} // namespace

TEST(LiveSettings, EachRestitutionPresetBouncesAGolfBallToESquaredH) {
    constexpr double H = 1.0;
    for (const auto& preset : phys::kRestitutionPresets) {
        if (preset.restitution == 0.0) continue; // plastic: nothing rises
        Match m = dropMatch("golf-ball", H, {set("restitution.golf-ball", std::string(preset.name))});
        const Drop d = dropBall(m);
        EXPECT_NEAR(d.releaseBottom, H, 1e-12);
        expectBounce(d, preset.restitution, preset.name);
        std::printf("%-20s e %.3f  v/u %.15f  e^2 H %.6f m  apex %.6f m (%+.2f %%)\n",
                    preset.name, preset.restitution, d.reboundSpeed / d.closingSpeed,
                    preset.restitution * preset.restitution * H, d.apex,
                    100.0 * (d.apex / (preset.restitution * preset.restitution * H) - 1.0));
    }
}

TEST(LiveSettings, ANumberSetsEDirectlyAndTheSettingReadsBack) {
    Match m = dropMatch("tennis-ball", 2.0, {set("restitution.tennis-ball", 0.5)});
    const Drop d = dropBall(m);
    expectBounce(d, 0.5, "e = 0.5");
    EXPECT_EQ(readSetting(m.liveSettings(), "restitution.tennis-ball"), SettingValue(0.5));
    // A preset's value reads as its name; other projectiles keep theirs.
    EXPECT_EQ(readSetting(m.liveSettings(), "restitution.golf-ball"), SettingValue(std::string("golf")));
    EXPECT_EQ(readSetting(m.liveSettings(), "restitution.baseball"), SettingValue(0.546));
}

TEST(LiveSettings, ChangeInFlightActsAtTheNextCollision) {
    // Set after the ball left the cannon, before it lands: the pair cache is rebuilt.
    Match m = dropMatch("golf-ball", 1.0, {});
    const Drop d = dropBall(m, {set("restitution.golf-ball", std::string("wooden"))});
    expectBounce(d, presetE("wooden"), "wooden");
}

TEST(LiveSettings, RestitutionIsPerProjectileNotPerMaterial) {
    // Cannonball and steel ball share the measured steel bearing; each has its own setting.
    Match m = dropMatch("steel-ball", 1.0, {set("restitution.cannonball", 0.1)});
    EXPECT_EQ(readSetting(m.liveSettings(), "restitution.steel-ball"),
              SettingValue(std::string("steel-bearing")));
    expectBounce(dropBall(m), presetE("steel-bearing"), "steel-bearing");
}

TEST(LiveSettings, APairOverrideWinsOverTheRuleAndCombineGivesItBack) {
    Match m = dropMatch("golf-ball", 1.0, {set("pair.golf-ball.floor", 0.3)});
    EXPECT_EQ(readSetting(m.liveSettings(), "pair.golf-ball.floor"), SettingValue(0.3));
    EXPECT_EQ(readSetting(m.liveSettings(), "pair.floor.golf-ball"), SettingValue(0.3)) << "either order";
    expectBounce(dropBall(m), 0.3, "pair 0.3");
    // The override also wins over a later restitution change ...
    Match m2 = dropMatch("golf-ball", 1.0,
                         {set("pair.golf-ball.floor", 0.3), set("restitution.golf-ball", 0.9)});
    expectBounce(dropBall(m2), 0.3, "pair 0.3 over restitution 0.9");
    // ... until the pair goes back to the rule e_golf-ball * e_floor = 0.9 * 1.
    Match m3 = dropMatch("golf-ball", 1.0,
                         {set("pair.golf-ball.floor", 0.3), set("restitution.golf-ball", 0.9),
                          set("pair.golf-ball.floor", std::string("combine"))});
    EXPECT_EQ(readSetting(m3.liveSettings(), "pair.golf-ball.floor"), SettingValue(std::string("combine")));
    expectBounce(dropBall(m3), 0.9, "rule again");
}

TEST(LiveSettings, RuleCombinesWithTheTerrainsMaterial) {
    // Earth basics' ground is "earth" (e = 0.3): the pair golf-ball / earth is 0.858 x 0.3.
    Match m(loadLevel((kLevels / "01_earth_basics.json").string()));
    const MaterialsInPlay in = m.materialsInPlay();
    const auto& t = m.world().materials;
    const auto earth = t.find("earth").value();
    EXPECT_NE(std::find(in.surfaces.begin(), in.surfaces.end(), earth), in.surfaces.end());
    const auto golf = t.find("golf-ball").value();
    EXPECT_NEAR(t.pair(golf, earth).restitution, 0.858 * 0.3, 1e-15);
    EXPECT_EQ(m.apply(set("restitution.golf-ball", std::string("tennis"))), "");
    EXPECT_NEAR(m.world().materials.pair(golf, earth).restitution, 0.712 * 0.3, 1e-15);
}

TEST(LiveSettings, PenaltyContactSinksAsItsSpringAndDamperSay) {
    // Penalty: F/m = w^2 x - 2 zeta w x' while overlapping, w = 2 pi penaltyHertz, zeta
    // from e (zeta = -ln e / sqrt(pi^2 + ln^2 e)). A ball arriving at v = sqrt(2 g H)
    // sinks to the damped oscillator's first extremum (plus gravity's g / w^2) and leaves
    // with about e v (README: apexes a few per cent under e^2 H). The world is set up by
    // the same settings a match takes, over a thick floor (as `artillery drop`).
    constexpr double H = 1.0;
    const auto drop = [&](const std::string& contact) {
        LiveSettings s;
        EXPECT_EQ(applySetting(s, "contact_model", contact), "");
        EXPECT_EQ(applySetting(s, "restitution.golf-ball", std::string("golf")), "");
        phys::World w(s.world);
        w.materials = s.materials;
        w.shapes.addBox({-100.0, -10.0}, {100.0, 0.0}, phys::material::kFloor);
        const phys::ProjectilePreset golf = *phys::projectileFromName("golf-ball");
        phys::ParticleDef pd = phys::particleDef(golf, {0.0, H + 0.5 * golf.diameter});
        pd.material = projectileMaterial(w.materials, golf);
        const phys::ParticleId id = w.particles.add(pd);
        Drop d;
        for (int i = 0; i < 240; ++i) {
            w.step();
            const phys::Vec2 p = w.particles.position(id), v = w.particles.velocity(id);
            d.deepest = std::min(d.deepest, p.y - pd.radius);
            if (v.y > 0.0 && p.y - pd.radius > 0.0) {
                d.apex = p.y - pd.radius + v.y * v.y / (2.0 * kG);
                break;
            }
        }
        return d;
    };
    const double e = presetE("golf");
    const double w = 2.0 * std::numbers::pi * phys::CollisionDef{}.penaltyHertz;
    const double lnE = std::log(e);
    const double zeta = -lnE / std::sqrt(std::numbers::pi * std::numbers::pi + lnE * lnE);
    const double wd = w * std::sqrt(1.0 - zeta * zeta);
    const double v = std::sqrt(2.0 * kG * H);
    const double tMax = std::atan(wd / (zeta * w)) / wd;
    const double sink = v / wd * std::exp(-zeta * w * tMax) * std::sin(wd * tMax) + kG / (w * w);
    const Drop penalty = drop("penalty"), impulse = drop("impulse");
    std::printf("penalty: sank %.4f m (spring-damper %.4f m), apex %.4f m (e^2 H %.4f m, %+.2f %%)\n",
                -penalty.deepest, sink, penalty.apex, e * e * H,
                100.0 * (penalty.apex / (e * e * H) - 1.0));
    EXPECT_NEAR(-penalty.deepest, sink, 0.1 * sink); // sampled once per tick (w dt = 0.52)
    EXPECT_NEAR(penalty.apex, e * e * H, 0.05 * e * e * H);
    EXPECT_GE(impulse.deepest, -1e-9) << "the impulse model: no overlap at all";
    EXPECT_NEAR(impulse.apex, e * e * H, 1e-9);
    // In a match the setting reaches the world the same way.
    Match m = dropMatch("golf-ball", H, {set("contact_model", std::string("penalty"))});
    EXPECT_EQ(m.world().def().collision.model, phys::ContactModel::Penalty);
    EXPECT_EQ(readSetting(m.liveSettings(), "contact_model"), SettingValue(std::string("penalty")));
}

TEST(LiveSettings, ContinuousOffLetsTheRailgunShotTunnelThroughThePlate) {
    // 09_tunnelling: a 600 m/s steel ball (5 m per tick) against a 1 cm steel plate at
    // x = 200. With continuous detection it bounces off the plate; without, the overlap
    // test at the ends of the steps never sees the plate.
    const auto farthest = [](bool continuous) {
        Match m(loadLevel((kLevels / "09_tunnelling.json").string()));
        EXPECT_EQ(m.apply(set("continuous", continuous)), "");
        EXPECT_EQ(m.apply(number(CommandKind::Fire, 0.0)), "");
        const phys::ParticleId id = m.shell().value();
        double x = 0.0;
        for (int i = 0; i < 120 * 5 && m.shell(); ++i) {
            m.step();
            if (m.world().particles.alive(id)) x = std::max(x, m.world().particles.position(id).x);
        }
        return x;
    };
    const double on = farthest(true), off = farthest(false);
    std::printf("farthest x: continuous on %.3f m, off %.3f m (plate at 200..200.01 m)\n", on, off);
    EXPECT_LT(on, 200.0);
    EXPECT_GT(off, 200.01 + 5.0) << "more than a tick's travel past the plate";
}

TEST(LiveSettings, RefusalsSayWhatWasExpected) {
    LiveSettings s;
    EXPECT_EQ(applySetting(s, "restitution.golf-ball", 1.3),
              "restitution.golf-ball expects a preset name (golf, tennis, billiard, hand-ball, "
              "wooden, steel-bearing, glass-marble, rubber-band-ball, hollow-hard-plastic, "
              "perfectly-elastic, perfectly-plastic) or a number in [0, 1], got 1.3");
    EXPECT_EQ(applySetting(s, "restitution.golf-ball", std::string("rubber")).substr(0, 40),
              "restitution.golf-ball expects a preset n");
    EXPECT_EQ(applySetting(s, "pair.golf-ball.earth", 2.0),
              "pair.golf-ball.earth expects \"combine\" or a number in [0, 1], got 2");
    EXPECT_EQ(applySetting(s, "contact_model", std::string("soft")),
              "contact_model expects one of impulse, penalty, none, got \"soft\"");
    EXPECT_EQ(applySetting(s, "continuous", 1.0), "continuous expects true or false, got 1");
    EXPECT_EQ(applySetting(s, "restitution.bowling-ball", 0.5),
              "unknown setting \"restitution.bowling-ball\": restitution.PROJECTILE takes a "
              "projectile (" + phys::projectileNameList() + ")");
    EXPECT_EQ(applySetting(s, "pair.golf-ball", 0.5).rfind(
                  "unknown setting \"pair.golf-ball\": pair.MATERIAL.MATERIAL takes two materials "
                  "(default, floor, ",
                  0),
              0u);
    // Refused means unchanged, in a match too, with the same message as its event.
    Match m = dropMatch("golf-ball", 1.0, {});
    const std::string why = m.apply(set("restitution.golf-ball", 1.3));
    EXPECT_EQ(why, applySetting(s, "restitution.golf-ball", 1.3));
    EXPECT_EQ(m.events().back().kind, EventKind::Refused);
    EXPECT_EQ(m.events().back().text, "set: " + why);
    EXPECT_EQ(readSetting(m.liveSettings(), "restitution.golf-ball"), SettingValue(std::string("golf")));
}

TEST(LiveSettings, EverySettingNameReadsBackWhatWasSet) {
    LiveSettings s;
    ASSERT_EQ(applySetting(s, "contact_model", std::string("penalty")), "");
    ASSERT_EQ(applySetting(s, "continuous", false), "");
    ASSERT_EQ(applySetting(s, "restitution.hand-ball", std::string("perfectly-elastic")), "");
    ASSERT_EQ(applySetting(s, "pair.cannonball.wooden", 0.25), "");
    EXPECT_EQ(s.world.collision.model, phys::ContactModel::Penalty);
    EXPECT_FALSE(s.world.collision.continuous);
    const auto names = settingNames(s);
    EXPECT_NE(std::find(names.begin(), names.end(), "pair.cannonball.wooden"), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), "restitution.glass-marble"), names.end());
    for (const std::string& n : names) {
        const SettingValue v = readSetting(s, n);
        EXPECT_NE(describe(v), "\"?\"") << n;
        if (n == "planet") continue; // reads "custom" for other g
        LiveSettings again = s;
        EXPECT_EQ(applySetting(again, n, v), "") << n << " = " << describe(v);
        EXPECT_EQ(readSetting(again, n), v) << n;
    }
}

TEST(LiveSettings, ACommandsFileWithTheNewSettingsReplaysBitForBit) {
    // Bank shots: a golf ball off steel walls ("floor") and earth: restitution matters.
    const Level level = loadLevel((kLevels / "04_bank_shots.json").string());
    const std::string script = R"([
        {"tick": 0, "cmd": "set", "name": "restitution.golf-ball", "value": "rubber-band-ball"},
        {"tick": 0, "cmd": "set", "name": "pair.golf-ball.floor", "value": 0.95},
        {"tick": 1, "cmd": "set", "name": "continuous", "value": false},
        {"tick": 2, "cmd": "set", "name": "contact_model", "value": "penalty"},
        {"tick": 3, "cmd": "aim", "angle_deg": 30}, {"tick": 3, "cmd": "power", "speed_mps": 35},
        {"tick": 5, "cmd": "fire"},
        {"tick": 400, "cmd": "set", "name": "contact_model", "value": "impulse"},
        {"tick": 401, "cmd": "set", "name": "continuous", "value": true},
        {"tick": 402, "cmd": "set", "name": "pair.golf-ball.floor", "value": "combine"},
        {"tick": 403, "cmd": "set", "name": "restitution.golf-ball", "value": 0.42}
    ])";
    HeadlessOptions o;
    o.commands = parseCommands("script.json", script);
    o.ticks = 1200;
    const HeadlessSummary run = runHeadless(level, o);
    int changed = 0;
    for (const GameEvent& e : run.events) changed += e.kind == EventKind::SettingChanged;
    EXPECT_EQ(changed, 8) << "every set took effect";
    // Through JSON and back: the commands and the hash.
    EXPECT_EQ(commandsToJson(parseCommands("again.json", commandsToJson(o.commands))),
              commandsToJson(o.commands));
    const Replay back = parseReplay("mem.json", replayToJson(run.recording));
    const VerifyResult v = verifyReplay(level, back);
    EXPECT_TRUE(v.ok) << "diverged at " << v.firstDivergentTick.value_or(0) << " in " << v.diverged;
    EXPECT_EQ(v.finalHash, run.finalHash);
    EXPECT_EQ(runHeadless(level, o).finalHash, run.finalHash);
    // And the settings are not no-ops: without them the game differs.
    HeadlessOptions plain = o;
    std::erase_if(plain.commands, [](const Command& c) { return c.kind == CommandKind::Set; });
    EXPECT_NE(runHeadless(level, plain).finalHash, run.finalHash);
}
