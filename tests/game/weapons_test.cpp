// The arsenal against exact physics: momentum across the cluster's split, the apex tick,
// the fuse to the tick, the bounce count and e, the sticky charge's e = 0, the airburst
// height, the tunnel's end point, the roller's stopping distance, the mortar's near-
// vacuum range; counted weapons refused when spent; bad entries named.
#include "game/ai.h"
#include "game/ai_weapons.h"
#include "game/files/text_file.h"
#include "game/match.h"
#include "game/session.h"
#include "game/weapon_text.h"
#include "game/weapons.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

using namespace game;
using phys::Vec2;

namespace {

// A flat floor (the rigid reference, e = 1) from x = 0 to 400, one cannon at `at`.
std::string arena(Vec2 at, bool drag, const std::string& projectiles,
                  const std::string& terrainMaterial = "floor") {
    return R"({"format": 1, "name": "arena", "world": {"min": [0, -20], "max": [400, 200]},
      "physics": {"gravity": 9.81, "drag": )" +
           std::string(drag ? "true" : "false") + R"(},
      "terrain": {"points": [[0, 0], [400, 0]], "material": ")" +
           terrainMaterial + R"("},
      "cannons": [{"position": [)" +
           std::to_string(at.x) + ", " + std::to_string(at.y) +
           R"(], "max_speed_mps": 100, "projectiles": [)" + projectiles + R"(]}],
      "targets": [{"position": [395, 190], "radius": 1}], "shots": 20})";
}

Level arenaLevel(Vec2 at, bool drag, const std::string& projectiles,
                 const std::string& m = "floor") {
    return parseLevel("arena.json", arena(at, drag, projectiles, m));
}

Command command(CommandKind k, double number = 0.0, std::string text = {}) {
    Command c;
    c.kind = k;
    c.number = number;
    c.text = std::move(text);
    return c;
}

void aimAndFire(Match& m, double angleDeg, double speed, const std::string& weapon) {
    ASSERT_EQ(m.apply(command(CommandKind::Select, 0.0, weapon)), "");
    ASSERT_EQ(m.apply(command(CommandKind::Aim, angleDeg)), "");
    ASSERT_EQ(m.apply(command(CommandKind::Power, speed)), "");
    ASSERT_EQ(m.apply(command(CommandKind::Fire)), "");
}

const GameEvent* first(const Match& m, EventKind k) {
    for (const auto& e : m.events())
        if (e.kind == k) return &e;
    return nullptr;
}

int count(const Match& m, EventKind k) {
    int n = 0;
    for (const auto& e : m.events())
        n += e.kind == k;
    return n;
}

void untilShotOver(Match& m) {
    for (int i = 0; i < 120 * 40 && m.shell(); ++i)
        m.step();
}

constexpr double kG = 9.81;
constexpr double kDt = 1.0 / 120.0;

} // namespace

TEST(Weapons, TableHasTheEightNamedWeaponsWithDistinctPhysics) {
    std::set<std::string> names;
    for (const Weapon& w : weapons()) {
        names.insert(w.name);
        EXPECT_TRUE(w.summary && *w.summary) << w.name;
        EXPECT_TRUE(w.physics && *w.physics) << w.name;
        EXPECT_STREQ(w.name, w.body.name);
        EXPECT_EQ(w.behaviour.apexFragments % 2, 0) << w.name << ": fragments go in pairs";
    }
    EXPECT_EQ(names, (std::set<std::string>{"cluster", "bouncer", "roller", "grenade", "mortar",
                                            "airburst", "digger", "sticky"}));
    const Weapon* mortar = weaponFromName("mortar");
    const Weapon* airburst = weaponFromName("airburst");
    // Drag constant k = rho Cd A / (2 m): the mortar's is over 100 times smaller.
    auto k = [](const Weapon* w) {
        const double a = std::numbers::pi * 0.25 * w->body.diameter * w->body.diameter;
        return 1.225 * w->body.dragCoefficient * a / (2.0 * w->body.mass);
    };
    EXPECT_NEAR(k(mortar), 8.2e-5, 0.05e-5);
    EXPECT_NEAR(k(airburst), 0.0104, 0.0001);
}

TEST(Weapons, ClusterSplitsAtTheApexTickAndConservesMomentum) {
    Match m(arenaLevel({10, 2}, false, R"("cluster")"));
    const double angle = 60.0, speed = 40.0;
    aimAndFire(m, angle, speed, "cluster");
    const std::uint64_t fired = m.tick();
    while (m.shell() && !m.flight().split)
        m.step();
    ASSERT_TRUE(m.flight().split);
    // Closed form without drag: v_y(t) = v_y0 - g t; the split is on the first tick where
    // v_y <= 0, i.e. k = ceil(v_y0 / (g dt)).
    const double vy0 = speed * std::sin(angle * std::numbers::pi / 180.0);
    EXPECT_EQ(m.tick() - fired, static_cast<std::uint64_t>(std::ceil(vy0 / (kG * kDt))));
    EXPECT_LE(m.flight().apexVelocity.y, 0.0);
    EXPECT_GT(m.flight().apexVelocity.y, -kG * kDt - 1e-12);
    // Momentum and mass across the split.
    const auto& set = m.world().particles;
    std::vector<phys::ParticleId> pieces = m.flight().fragments;
    pieces.push_back(*m.shell());
    ASSERT_EQ(pieces.size(), 4u);
    Vec2 p{};
    double mass = 0.0;
    for (const auto id : pieces) {
        p = p + set.velocity(id) * set.mass(id);
        mass += set.mass(id);
    }
    const Vec2 before = m.flight().apexVelocity * m.flight().apexMass;
    EXPECT_NEAR(mass, m.flight().apexMass, 1e-12 * mass);
    EXPECT_NEAR(p.x, before.x, 1e-12 * length(before));
    EXPECT_NEAR(p.y, before.y, 1e-12 * length(before) + 1e-12);
    // Every fragment lands and bursts; the shot ends once the last one has.
    untilShotOver(m);
    EXPECT_EQ(count(m, EventKind::Burst), 4);
    EXPECT_EQ(count(m, EventKind::ShotOver), 1);
}

TEST(Weapons, BouncerKeepsItsRestitutionAndBurstsOnTheThirdImpact) {
    Match m(arenaLevel({10, 20}, false, R"("bouncer")"));
    aimAndFire(m, -90.0, 0.0, "bouncer");
    untilShotOver(m);
    std::vector<double> speeds;
    std::uint64_t lastBounce = 0;
    for (const auto& e : m.events())
        if (e.kind == EventKind::Bounce) {
            speeds.push_back(e.value);
            lastBounce = e.tick;
        }
    ASSERT_EQ(speeds.size(), 3u);
    ASSERT_NE(first(m, EventKind::Burst), nullptr);
    EXPECT_EQ(first(m, EventKind::Burst)->tick, lastBounce);
    // Against the rigid floor (e = 1) the pair's e is the bouncer's 0.9 (e_A e_B), and
    // without drag each impact speed is e times the one before.
    EXPECT_NEAR(speeds[1] / speeds[0], 0.9, 1e-9);
    EXPECT_NEAR(speeds[2] / speeds[1], 0.9, 1e-9);
    // The first impact: a fall from 18.5 m minus the radius, v = sqrt(2 g h).
    const double h = 20.0 - 1.5 - 0.045;
    EXPECT_NEAR(speeds[0], std::sqrt(2.0 * kG * h), 1e-9);
}

TEST(Weapons, GrenadeBurstsOnItsFuseToTheTickAndBouncesMeanwhile) {
    Match m(arenaLevel({10, 2}, false, R"("grenade")"));
    aimAndFire(m, 30.0, 12.0, "grenade");
    const std::uint64_t fired = m.tick();
    untilShotOver(m);
    const GameEvent* b = first(m, EventKind::Burst);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->tick - fired, 360u);          // 3 s at 120 ticks per second
    EXPECT_GE(count(m, EventKind::Bounce), 1); // it hit the floor before the fuse ran out
}

TEST(Weapons, StickyStopsDeadWhereItTouchesAndBurstsLater) {
    Match m(arenaLevel({10, 2}, false, R"("sticky")"));
    aimAndFire(m, 45.0, 20.0, "sticky");
    while (m.shell() && !m.flight().stuckTick)
        m.step();
    ASSERT_TRUE(m.flight().stuckTick);
    const auto id = *m.shell();
    const Vec2 at = m.world().particles.position(id);
    EXPECT_EQ(m.world().particles.velocity(id).x, 0.0);
    EXPECT_EQ(m.world().particles.velocity(id).y, 0.0);
    const std::uint64_t stuck = *m.flight().stuckTick;
    while (m.shell()) {
        m.step();
        if (m.shell()) {
            EXPECT_EQ(m.world().particles.position(id).x, at.x);
            EXPECT_EQ(m.world().particles.position(id).y, at.y);
        }
    }
    const GameEvent* b = first(m, EventKind::Burst);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->tick - stuck, 180u); // 1.5 s
    EXPECT_EQ(b->where.x, at.x);
    EXPECT_EQ(b->where.y, at.y);
    EXPECT_EQ(count(m, EventKind::Bounce), 0); // e = 0: no rebound at all
}

TEST(Weapons, AirburstBurstsAtItsHeightOnTheWayDown) {
    Match m(arenaLevel({10, 2}, true, R"("airburst")"));
    aimAndFire(m, 60.0, 45.0, "airburst");
    untilShotOver(m);
    const GameEvent* b = first(m, EventKind::Burst);
    ASSERT_NE(b, nullptr);
    // It bursts on the first tick at or below 5 m: within one tick's fall of it (the
    // descent is slower than 60 m/s, 0.5 m per tick).
    EXPECT_LE(b->where.y, 5.0);
    EXPECT_GT(b->where.y, 5.0 - 0.5);
    EXPECT_EQ(count(m, EventKind::Crater), 0); // in the air: no crater
}

TEST(Weapons, DiggerTunnelsItsLengthAlongItsPathThenBursts) {
    Match m(arenaLevel({10, 30}, false, R"("digger")", "ground"));
    aimAndFire(m, -45.0, 20.0, "digger");
    while (m.shell() && !m.flight().digging)
        m.step();
    ASSERT_TRUE(m.flight().digging);
    const Vec2 origin = m.flight().digOrigin, dir = m.flight().digDirection;
    EXPECT_NEAR(length(dir), 1.0, 1e-12);
    EXPECT_LT(dir.y, 0.0);
    untilShotOver(m);
    const GameEvent* b = first(m, EventKind::Burst);
    ASSERT_NE(b, nullptr);
    const Vec2 end = origin + dir * 10.0;
    EXPECT_NEAR(b->where.x, end.x, 1e-9);
    EXPECT_NEAR(b->where.y, end.y, 1e-9);
    // The ground over the middle of the tunnel is gone: the tunnel (1 m wide) reaches
    // from the surface to 7 m down, so the surface at its middle has dropped.
    const Vec2 mid = origin + dir * 5.0;
    EXPECT_LT(m.terrain().heightAt(mid.x), mid.y + 1.0 + 1e-9);
    EXPECT_GE(count(m, EventKind::Crater), 10);
}

TEST(Weapons, RollerRollsItsStoppingDistanceAndBurstsAtRest) {
    Match m(arenaLevel({10, 0.075}, false, R"("roller")"));
    const double v0 = 8.0;
    aimAndFire(m, 0.0, v0, "roller");
    const double x0 = m.world().particles.position(*m.shell()).x;
    untilShotOver(m);
    const GameEvent* b = first(m, EventKind::Burst);
    ASSERT_NE(b, nullptr);
    // Sliding friction on the flat: a = mu g, so it stops after v0^2 / (2 mu g), with the
    // pair's mu = sqrt(mu_roller mu_floor) (the combine rule).
    const auto& mats = m.world().materials;
    const double mu = mats.pair(*mats.find("roller"), *mats.find("floor")).dynamicFriction;
    const double want = v0 * v0 / (2.0 * mu * kG);
    EXPECT_NEAR(b->where.x - x0, want, 0.03 * want);
}

TEST(Weapons, MortarFliesAlmostAsInVacuumWhileTheAirburstFallsShort) {
    auto range = [](const std::string& weapon) {
        Match m(arenaLevel({10, 1.5}, true, "\"" + weapon + "\""));
        aimAndFire(m, 45.0, 40.0, weapon);
        untilShotOver(m);
        return first(m, EventKind::Burst)->where.x - m.muzzle(45.0).x;
    };
    const double vacuum = 40.0 * 40.0 / kG; // R = v^2 sin(2 theta) / g from launch height
    EXPECT_GT(range("mortar"), 0.97 * vacuum);
    EXPECT_LT(range("mortar"), 1.02 * vacuum);
    // The airburst shell (k 125 times the mortar's) falls far shorter, and bursts 5 m up.
    EXPECT_LT(range("airburst"), 0.6 * vacuum);
}

TEST(Weapons, CountedWeaponsAreRefusedWhenSpent) {
    Match m(arenaLevel({10, 2}, false, R"({"name": "grenade", "count": 1}, "cannonball")"));
    ASSERT_EQ(m.cannon().ammoLeft, (std::vector<int>{1, -1}));
    aimAndFire(m, 45.0, 10.0, "grenade");
    EXPECT_EQ(m.cannon().ammoLeft[0], 0);
    untilShotOver(m);
    ASSERT_EQ(m.apply(command(CommandKind::Select, 0.0, "grenade")), "");
    EXPECT_EQ(m.apply(command(CommandKind::Fire)), "no grenade left");
    ASSERT_EQ(m.apply(command(CommandKind::Select, 0.0, "cannonball")), "");
    EXPECT_EQ(m.apply(command(CommandKind::Fire)), "");
}

TEST(Weapons, BadProjectileEntriesAreNamed) {
    try {
        parseLevel("bad.json",
                   arena({10, 2}, false, R"("cannonball", {"name": "nuke", "count": 2})"));
        FAIL() << "a weapon that does not exist was accepted";
    } catch (const LoadError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(
                      "bad.json: $.cannons[0].projectiles[1].name: expected a weapon (cluster, "
                      "bouncer, roller, grenade, mortar, airburst, digger, sticky)",
                      0),
                  0u)
            << e.what();
    }
    try {
        parseLevel("bad.json", arena({10, 2}, false, R"({"name": "grenade", "count": 0})"));
        FAIL() << "a count of 0 was accepted";
    } catch (const LoadError& e) {
        EXPECT_NE(std::string(e.what()).find("$.cannons[0].projectiles[0].count"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Weapons, PickerLabelsShowShotsLeftAndDescribeThePhysics) {
    Match m(arenaLevel({10, 2}, false, R"("cannonball", {"name": "grenade", "count": 1})"));
    // A weapon shows the number key that picks it in every level (the grenade is the
    // arsenal's fourth); a ball has none.
    EXPECT_EQ(projectileLabel(m.cannon(), 0), "cannonball");
    EXPECT_EQ(projectileLabel(m.cannon(), 1), "4  grenade  (1 left)");
    aimAndFire(m, 45.0, 10.0, "grenade");
    EXPECT_EQ(projectileLabel(m.cannon(), 1), "4  grenade  (none left)");
    EXPECT_EQ(projectileDescription("grenade"),
              "bounces (e = 0.5) until its 3 s fuse burns down, then bursts\n"
              "bursts at t = 3 s after firing, to the tick");
    EXPECT_EQ(
        projectileDescription("golf-ball"),
        "golf-ball: a ball, 0.0459 kg, 43 mm, Cd 0.25; bounces by its material's restitution");
}

TEST(Weapons, TheComputerPicksTheWeaponWhosePhysicsSuitsItsAim) {
    // A disc in the air: only a passing shell scores, so the least drag among the
    // weapons that burst on impact: the mortar (k = 8.2e-5 /m against 0.0104 /m).
    Match m(arenaLevel({10, 2}, true, R"("cannonball", "airburst", "mortar", "sticky")"));
    EXPECT_EQ(chooseWeapon(m, m.targets()[0].position), std::optional<std::string>("mortar"));
    // Spent: the next best.
    Match spent(
        arenaLevel({10, 2}, true, R"("cannonball", "airburst", {"name": "mortar", "count": 1})"));
    aimAndFire(spent, 45.0, 10.0, "mortar");
    untilShotOver(spent);
    EXPECT_EQ(chooseWeapon(spent, spent.targets()[0].position),
              std::optional<std::string>("airburst"));
    // The rope bridge's crate (a structure): the most momentum, m v + blast impulse.
    Match bridge(loadLevel(std::string(ARTILLERY_SOURCE_DIR) + "/levels/06_rope_bridge.json"));
    EXPECT_EQ(chooseWeapon(bridge, bridge.blocks()[1].def.position),
              std::optional<std::string>("mortar"));
    // Levels without weapons keep the player's pick (the golden replays depend on it).
    Match plain(arenaLevel({10, 2}, true, R"("cannonball", "golf-ball")"));
    EXPECT_EQ(chooseWeapon(plain, plain.targets()[0].position), std::nullopt);
}

// The selection spent and no weapon left that suits: the computer selects what still has
// ammunition, in the list's order, instead of asking to fire the empty one for ever. In
// the Bunker (two mortars, then cannonballs) it used to fire both mortars and then stand
// until the 60 s ran out; now it goes on with cannonballs until the match ends.
TEST(Weapons, TheComputerSwitchesFromASpentWeaponToWhatIsLeft) {
    Match m(arenaLevel({10, 2}, false, R"({"name": "mortar", "count": 1}, "cannonball")"));
    const Vec2 structure{200.0, 0.0}; // no disc there: a structure, where the mortar is spent
    aimAndFire(m, 45.0, 10.0, "mortar");
    untilShotOver(m);
    EXPECT_EQ(chooseWeapon(m, structure), std::optional<std::string>("cannonball"));

    SessionOptions o;
    o.autoplay = true;
    o.difficulty = Difficulty::Hard;
    Session bunker(loadLevel(std::string(ARTILLERY_SOURCE_DIR) + "/levels/27_bunker.json"), o);
    for (int t = 0; t < 120 * 60 && !bunker.match().over(); ++t)
        bunker.step();
    int mortars = 0, cannonballs = 0;
    for (const GameEvent& e : bunker.match().events())
        if (e.kind == EventKind::Fired) (e.text == "mortar" ? mortars : cannonballs) += 1;
    EXPECT_EQ(mortars, 2);
    EXPECT_GE(cannonballs, 1) << "after the spent mortars";
    EXPECT_TRUE(bunker.match().over());
}

// The computer's trial shots fly the projectile it is about to select: a preview of
// projectile i without selecting it is, point for point, the preview after selecting it.
TEST(Weapons, APreviewOfAnotherProjectileIsThePreviewAfterSelectingIt) {
    const Level level = arenaLevel({10, 2}, true, R"("cannonball", "airburst", "golf-ball")");
    Match kept(level), selected(level);
    ASSERT_EQ(selected.apply(command(CommandKind::Select, 0.0, "airburst")), "");
    const auto ahead = kept.previewTrajectory(40.0, 60.0, 8.0, INFINITY, std::size_t{1});
    EXPECT_EQ(ahead, selected.previewTrajectory(40.0, 60.0, 8.0));
    EXPECT_NE(ahead, kept.previewTrajectory(40.0, 60.0, 8.0)); // the cannonball's differs
    // And so the aim: at a target 150 m off, with drag, each projectile's own.
    const Vec2 target{160.0, 2.0};
    const AimSolution forAirburst = aimAt(kept, target, std::size_t{1});
    const AimSolution afterSelecting = aimAt(selected, target);
    EXPECT_EQ(forAirburst.angleDeg, afterSelecting.angleDeg);
    EXPECT_EQ(forAirburst.speedMps, afterSelecting.speedMps);
}

// The bouncer's shell bounces with its own e = 0.9 (its rubber body alone has 0.828): the
// preview the computer aims by flies through the first bounce as the shell does.
TEST(Weapons, TrialShotsBounceWithTheWeaponsOwnMaterial) {
    const Level arena = parseLevel("arena.json", R"({"format": 1, "name": "arena",
        "world": {"min": [0, -20], "max": [400, 200]}, "physics": {"drag": false},
        "terrain": {"points": [[0, 0], [400, 0]], "material": "perfectly-elastic"},
        "cannons": [{"position": [10, 2], "max_speed_mps": 100, "projectiles": ["bouncer"]}],
        "targets": [{"position": [395, 190], "radius": 1}]})");
    Match m(arena);
    const std::vector<phys::Vec2> preview = m.previewTrajectory(40.0, 25.0, 8.0, INFINITY, {}, 1);
    for (const auto& [kind, number] : {std::pair{CommandKind::Aim, 40.0}, {CommandKind::Power, 25.0}}) {
        Command c;
        c.kind = kind;
        c.number = number;
        ASSERT_EQ(m.apply(c), "");
    }
    Command fire;
    fire.kind = CommandKind::Fire;
    ASSERT_EQ(m.apply(fire), "");
    // Past the first bounce, the shell and the preview are at the same place tick by tick.
    std::size_t compared = 0;
    for (std::size_t i = 1; i < preview.size() && m.shell(); ++i) {
        m.step();
        if (!m.shell()) break;
        const phys::Vec2 p = m.world().particles.position(*m.shell());
        EXPECT_NEAR(p.x, preview[i].x, 1e-9) << "tick " << i;
        EXPECT_NEAR(p.y, preview[i].y, 1e-9) << "tick " << i;
        ++compared;
    }
    EXPECT_GT(compared, 300u) << "through the first bounce";
}
