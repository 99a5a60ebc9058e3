// The fixed weapon keys: 1 to 8 name the eight weapons by identity in every level; a
// `select` names a projectile by what it is, not by where it stands in a level's list, and
// one the level lacks is refused with a short line; the line that introduces a weapon.
#include "game/level.h"
#include "game/match.h"
#include "game/replay.h"
#include "game/weapon_text.h"
#include "game/weapons.h"

#include "shots.h"

#include <gtest/gtest.h>

using namespace game;

namespace {

Level levelWith(const std::string& projectiles) {
    return parseLevel("keys.json", R"({"format": 1, "name": "keys",
        "terrain": {"points": [[0, 0], [200, 0]]},
        "cannons": [{"position": [10, 1], "projectiles": [)" + projectiles + R"(]}],
        "targets": [{"position": [100, 1]}]})");
}

Command select(const std::string& name) { return shots::cmd(CommandKind::Select, 0.0, name); }

} // namespace

TEST(WeaponKeys, OneToEightAreTheArsenalInItsOrder) {
    const char* order[] = {"cluster", "bouncer", "roller",   "grenade",
                           "mortar",  "airburst", "digger", "sticky"};
    for (int key = 1; key <= 8; ++key) {
        EXPECT_EQ(weaponOnKey(key), std::optional<std::string>(order[key - 1])) << key;
        EXPECT_EQ(keyOfProjectile(order[key - 1]), std::optional<int>(key));
    }
    EXPECT_FALSE(weaponOnKey(0));
    EXPECT_FALSE(weaponOnKey(9));
    EXPECT_FALSE(keyOfProjectile("cannonball")) << "a ball has no number key";
    EXPECT_EQ(weapons().size(), 8u);
}

TEST(WeaponKeys, SelectNamesTheProjectileWhateverTheListOrder) {
    // The same two weapons in the opposite order: a select of "sticky" picks the sticky
    // charge in both, at index 1 in one and 0 in the other.
    Match a(levelWith(R"("cannonball", "sticky", "mortar")"));
    Match b(levelWith(R"("sticky", "cannonball", "mortar")"));
    EXPECT_EQ(a.apply(select("sticky")), "");
    EXPECT_EQ(b.apply(select("sticky")), "");
    EXPECT_EQ(a.cannon().def.projectiles[a.cannon().projectile], "sticky");
    EXPECT_EQ(b.cannon().def.projectiles[b.cannon().projectile], "sticky");
    EXPECT_EQ(a.selectedAmmo().preset.name, std::string("sticky"));
}

TEST(WeaponKeys, AWeaponTheLevelLacksIsRefusedInOneShortLine) {
    Match m(levelWith(R"("cannonball", "mortar")"));
    const auto hash = m.hash();
    EXPECT_EQ(m.apply(select(*weaponOnKey(1))), "this level has no cluster");
    EXPECT_EQ(m.apply(select("golf-ball")), "this level has no golf-ball");
    ASSERT_FALSE(m.events().empty());
    EXPECT_EQ(m.events().back().kind, EventKind::Refused);
    EXPECT_EQ(m.events().back().text, "select: this level has no golf-ball");
    EXPECT_EQ(m.hash(), hash) << "a refused select changes nothing";
    EXPECT_EQ(m.cannon().projectile, 0u);
    // A name that is no projectile at all still lists what the cannon fires.
    EXPECT_NE(m.apply(select("anvil")).find("this cannon fires cannonball, mortar"),
              std::string::npos);
}

TEST(WeaponKeys, ASelectByNameIsRecordedAndReplayed) {
    std::vector<Command> commands{select("mortar")};
    const std::vector<Command> back = parseCommands("c.json", commandsToJson(commands));
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].kind, CommandKind::Select);
    EXPECT_EQ(back[0].text, "mortar");
}

TEST(WeaponKeys, EachWeaponHasItsOneLineIntroduction) {
    EXPECT_EQ(weaponIntroduction("cluster"),
              "New: the cluster splits into 4 bomblets at the top of its arc; each bursts where it "
              "lands");
    EXPECT_EQ(weaponIntroduction("mortar"),
              "New: the mortar, a heavy finned bomb: 30 kg, Cd 0.2, flies almost as in vacuum");
    EXPECT_EQ(weaponIntroduction("cannonball"), "") << "a ball needs no introduction";
    for (const Weapon& w : weapons()) {
        const std::string line = weaponIntroduction(w.name);
        EXPECT_EQ(line.find('\n'), std::string::npos) << w.name << ": one line";
        EXPECT_LE(line.size(), 100u) << w.name;
    }
}
