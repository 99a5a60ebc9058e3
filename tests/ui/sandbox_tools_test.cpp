// The sandbox's mouse gestures become the commands a replay records: a click spawns, a
// press-drag-release spans a rope, the hand grabs, drags in steps and lets go; played
// through a session they change the match as the commands say.
#include "game/level.h"
#include "game/session.h"
#include "ui/game/sandbox_tools.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace {

using game::CommandKind;
using Tool = ui::SandboxTools::Tool;

game::Level sandboxLevel() {
    const auto root = std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();
    return game::loadLevel((root / "levels/11_sandbox.json").string());
}

void submitAll(game::Session& s, const std::vector<game::Command>& cmds) {
    for (const auto& c : cmds) EXPECT_EQ(s.submit(c), "") << game::commandName(c.kind);
}

} // namespace

TEST(SandboxTools, AClickSpawnsAndADragSpansARope) {
    ui::SandboxTools tools;
    tools.choose(Tool::Spawn, "block");
    auto cmds = tools.press({20, 10});
    ASSERT_EQ(cmds.size(), 1u);
    EXPECT_EQ(cmds[0].kind, CommandKind::Spawn);
    EXPECT_EQ(cmds[0].text, "block");
    EXPECT_EQ(cmds[0].at, (phys::Vec2{20, 10}));
    EXPECT_TRUE(tools.lift({20, 10}).empty());

    tools.choose(Tool::Spawn, "rope");
    EXPECT_TRUE(tools.press({30, 20}).empty()) << "the rope starts at its anchor";
    EXPECT_TRUE(tools.move({33, 17}).empty());
    cmds = tools.lift({36, 14});
    ASSERT_EQ(cmds.size(), 1u);
    EXPECT_EQ(cmds[0].text, "rope");
    EXPECT_EQ(cmds[0].at, (phys::Vec2{30, 20}));
    EXPECT_EQ(cmds[0].to, (phys::Vec2{36, 14}));
    tools.press({30, 20});
    EXPECT_TRUE(tools.lift({30.05, 20}).empty()) << "a click spans nothing";
}

TEST(SandboxTools, TheHandGrabsDragsInStepsAndLetsGo) {
    game::Session session(sandboxLevel());
    ui::SandboxTools tools;
    tools.choose(Tool::Spawn, "block");
    submitAll(session, tools.press({20, 3}));
    for (int i = 0; i < 240; ++i) session.step();
    const auto& m = session.match();
    const phys::Vec2 c = m.rigid().state(m.blocks().back().body).position;

    tools.choose(Tool::Hand);
    submitAll(session, tools.press(c));
    EXPECT_EQ(m.grab().kind, game::GrabState::Kind::Body);
    EXPECT_TRUE(tools.move(c + phys::Vec2{0.01, 0}).empty()) << "steps under 5 cm send nothing";
    const auto drag = tools.move(c + phys::Vec2{0, 5});
    ASSERT_EQ(drag.size(), 1u);
    EXPECT_EQ(drag[0].kind, CommandKind::Drag);
    submitAll(session, drag);
    for (int i = 0; i < 360; ++i) session.step();
    EXPECT_NEAR(m.rigid().state(m.blocks().back().body).position.y, c.y + 5.0, 0.05);
    const auto let = tools.lift(c + phys::Vec2{0, 5});
    ASSERT_EQ(let.size(), 1u);
    EXPECT_EQ(let[0].kind, CommandKind::Release);
    submitAll(session, let);
    EXPECT_EQ(m.grab().kind, game::GrabState::Kind::None);
    // Everything went through the session: the recording holds it.
    int spawns = 0, grabs = 0;
    for (const auto& cmd : session.recording().commands) {
        spawns += cmd.kind == CommandKind::Spawn;
        grabs += cmd.kind == CommandKind::Grab;
    }
    EXPECT_EQ(spawns, 1);
    EXPECT_EQ(grabs, 1);
}
