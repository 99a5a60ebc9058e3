// Commands and live settings: the vocabulary scripts, the window and replays share.
#include "game/command.h"
#include "game/settings.h"
#include "corpus.h"

#include <gtest/gtest.h>

using namespace game;

TEST(Commands, ParseEveryKindAndRoundTripThroughJson) {
    const std::string text = R"([
      {"tick": 0, "cmd": "aim", "angle_deg": 52.5},
      {"tick": 0, "cmd": "power", "speed_mps": 34},
      {"tick": 3, "cmd": "select", "projectile": "golf-ball"},
      {"tick": 10, "cmd": "fire"},
      {"tick": 600, "cmd": "end_turn"},
      {"tick": 700, "cmd": "set", "name": "integrator", "value": "rk4"},
      {"tick": 700, "cmd": "set", "name": "drag", "value": false},
      {"tick": 701, "cmd": "set", "name": "wind", "value": -3.5}])";
    const auto cmds = parseCommands("script.json", text);
    ASSERT_EQ(cmds.size(), 8u);
    EXPECT_EQ(cmds[0].kind, CommandKind::Aim);
    EXPECT_EQ(cmds[0].number, 52.5);
    EXPECT_EQ(cmds[2].text, "golf-ball");
    EXPECT_EQ(cmds[5].value, SettingValue(std::string("rk4")));
    EXPECT_EQ(cmds[6].value, SettingValue(false));
    EXPECT_EQ(cmds[7].value, SettingValue(-3.5));
    const auto again = parseCommands("again.json", commandsToJson(cmds));
    ASSERT_EQ(again.size(), cmds.size());
    for (std::size_t i = 0; i < cmds.size(); ++i) {
        EXPECT_EQ(again[i].tick, cmds[i].tick);
        EXPECT_EQ(again[i].kind, cmds[i].kind);
        EXPECT_EQ(again[i].number, cmds[i].number);
        EXPECT_EQ(again[i].text, cmds[i].text);
        EXPECT_EQ(again[i].value, cmds[i].value);
    }
}

TEST(Commands, BadCorpusGivesTheExpectedMessages) {
    const int cases = checkBadCorpus(std::filesystem::path(ARTILLERY_SOURCE_DIR) /
                                         "tests/data/bad_commands",
                                     [](const std::string& f) { loadCommands(f); });
    EXPECT_GE(cases, 15);
}

TEST(Settings, ApplyChangesTheWorldDefinition) {
    phys::WorldDef def;
    EXPECT_EQ(applySetting(def, "integrator", std::string("euler-cromer")), "");
    EXPECT_EQ(def.integrator, phys::Integrator::SymplecticEuler);
    EXPECT_EQ(applySetting(def, "tick_hz", 60.0), "");
    EXPECT_EQ(def.tickSeconds, 1.0 / 60.0);
    EXPECT_EQ(applySetting(def, "planet", std::string("moon")), "");
    EXPECT_EQ(def.forces.gravity.y, -1.62);
    EXPECT_EQ(applySetting(def, "drag", true), "");
    EXPECT_EQ(def.forces.drag, phys::DragModel::Quadratic);
    EXPECT_EQ(applySetting(def, "wind", 4.0), "");
    EXPECT_EQ(def.forces.wind.x, 4.0);
    EXPECT_EQ(applySetting(def, "substeps", 8.0), "");
    EXPECT_EQ(def.substeps, 8);
    for (const std::string& name : settingNames(LiveSettings{def, {}}))
        EXPECT_NE(describe(readSetting(def, name)), "\"?\"") << name << " reads back";
    EXPECT_EQ(readSetting(def, "planet"), SettingValue(std::string("moon")));
}

TEST(Settings, RefusedValuesLeaveTheDefinitionUnchanged) {
    phys::WorldDef def;
    const phys::WorldDef before = def;
    EXPECT_NE(applySetting(def, "gravity", -1.0).find("gravity expects a number in [0, 1000] m/s^2"),
              std::string::npos);
    EXPECT_NE(applySetting(def, "gravity", std::nan("")).find("expects a number"), std::string::npos);
    EXPECT_NE(applySetting(def, "warp", 1.0).find("unknown setting"), std::string::npos);
    EXPECT_NE(applySetting(def, "drag", 1.0).find("true or false"), std::string::npos);
    EXPECT_EQ(def.tickSeconds, before.tickSeconds);
    EXPECT_EQ(def.forces.gravity, before.forces.gravity);
    EXPECT_EQ(def.forces.drag, before.forces.drag);
}
