// The keys and the mouse of a turn at the cannon, as every window that plays one reads
// them (the game's, the network duel's): synthetic SDL events in, the commands a match
// takes out, applied to a real match.
#include "game/files/text_file.h"
#include "game/level.h"
#include "game/match.h"
#include "ui/game/turn_controls.h"

#include "sdl_events.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

using game::CommandKind;

game::Match earthBasics() {
    const auto root = std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();
    return game::Match(game::loadLevel((root / "levels/01_earth_basics.json").string()));
}

void submit(game::Match& m, const std::vector<game::Command>& commands) {
    for (const game::Command& c : commands)
        ASSERT_EQ(m.apply(c), "") << game::commandName(c.kind);
}

/// A drag by the window's pointer (points) from `from` to `to`, the cannon's pivot at
/// `pivot` (framebuffer pixels, `scale` of them a point): the commands it ends with.
std::vector<game::Command> drag(ui::AimInput& aim, const game::Match& m, phys::Vec2 pivot,
                                phys::Vec2 scale, phys::Vec2 from, phys::Vec2 to) {
    std::vector<game::Command> out;
    EXPECT_TRUE(ui::dragToAim(test_events::button(SDL_MOUSEBUTTONDOWN, from), aim, m, true, pivot,
                              scale, out));
    EXPECT_TRUE(ui::dragToAim(test_events::motion(to), aim, m, true, pivot, scale, out));
    EXPECT_TRUE(ui::dragToAim(test_events::button(SDL_MOUSEBUTTONUP, to), aim, m, true, pivot,
                              scale, out));
    return out;
}

std::vector<CommandKind> kinds(const std::vector<game::Command>& commands) {
    std::vector<CommandKind> k;
    for (const game::Command& c : commands)
        k.push_back(c.kind);
    return k;
}

} // namespace

TEST(TurnControls, EnterAndFFireWhileEEndsTheTurn) {
    game::Match m = earthBasics();
    ui::AimInput aim;
    aim.sync(m.cannon());
    for (SDL_Keycode fire : {SDLK_RETURN, SDLK_KP_ENTER, SDLK_f}) {
        const auto commands = ui::pressTurnKey(fire, aim, m);
        ASSERT_TRUE(commands);
        EXPECT_EQ(kinds(*commands), std::vector{CommandKind::Fire}) << "the aim set is the cannon's";
    }
    const auto end = ui::pressTurnKey(SDLK_e, aim, m);
    ASSERT_TRUE(end);
    EXPECT_EQ(kinds(*end), std::vector{CommandKind::EndTurn});
    EXPECT_FALSE(ui::pressTurnKey(SDLK_q, aim, m)) << "not a turn key: left to the window";
}

// Tab steps through the balls; a number key is a weapon by its own number (5 is the
// mortar wherever a level lists it), and a weapon the level lacks is refused, saying so.
TEST(TurnControls, TabCyclesTheBallsAndEachNumberIsAWeapon) {
    game::Match m = earthBasics(); // cannonball, golf ball, tennis ball; no weapon
    ui::AimInput aim;
    const auto next = ui::pressTurnKey(SDLK_TAB, aim, m);
    ASSERT_TRUE(next);
    submit(m, *next);
    EXPECT_EQ(m.cannon().projectile, 1u);
    std::string message;
    const auto none = ui::pressTurnKey(SDLK_1, aim, m, &message);
    ASSERT_TRUE(none) << "a turn key even where the level has no such weapon";
    EXPECT_TRUE(none->empty());
    EXPECT_EQ(message, "select: this level has no cluster");
    EXPECT_EQ(m.cannon().projectile, 1u);

    const auto root = std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();
    game::Match bridge(game::loadLevel((root / "levels/06_rope_bridge.json").string()));
    ASSERT_EQ(bridge.cannon().def.projectiles[2], "mortar");
    message.clear();
    const auto mortar = ui::pressTurnKey(SDLK_5, aim, bridge, &message);
    ASSERT_TRUE(mortar);
    submit(bridge, *mortar);
    EXPECT_EQ(bridge.cannon().projectile, 2u) << "5 is the mortar, third in this level's list";
    EXPECT_EQ(message, "");
    // Tab from the mortar goes on to the balls, not through the weapons.
    const auto ball = ui::pressTurnKey(SDLK_TAB, aim, bridge);
    ASSERT_TRUE(ball);
    submit(bridge, *ball);
    EXPECT_EQ(bridge.cannon().projectile, 0u);
}

TEST(TurnControls, ADragAimsAndEnterFiresItThroughAMatch) {
    game::Match m = earthBasics();
    ui::AimInput aim;
    aim.sync(m.cannon());
    const phys::Vec2 pivot{200, 400}, scale{1, 1};
    // 60 degrees, 207.8 px of the 260 that mean full power.
    std::vector<game::Command> out = drag(aim, m, pivot, scale, pivot, {304, 220});
    ASSERT_EQ(kinds(out), (std::vector{CommandKind::Aim, CommandKind::Power}));
    submit(m, out);
    EXPECT_NEAR(m.cannon().angleDeg, 60.0, 0.05);
    EXPECT_NEAR(m.cannon().speedMps, m.cannon().def.maxSpeedMps * std::hypot(104.0, 180.0) / 260.0,
                0.05);
    const auto fire = ui::pressTurnKey(SDLK_RETURN, aim, m);
    ASSERT_TRUE(fire);
    submit(m, *fire);
    EXPECT_TRUE(m.shell());
    // A drag while the shell flies aims nothing; motion without a drag is not the drag's.
    out.clear();
    EXPECT_TRUE(ui::dragToAim(test_events::button(SDL_MOUSEBUTTONDOWN, pivot), aim, m, true, pivot,
                              scale, out));
    EXPECT_FALSE(aim.dragging());
    EXPECT_FALSE(ui::dragToAim(test_events::motion({300, 300}), aim, m, true, pivot, scale, out));
    EXPECT_TRUE(out.empty());
}

TEST(TurnControls, OnAHighDpiScreenThePointerIsInFramebufferPixels) {
    game::Match m = earthBasics();
    ui::AimInput aim;
    aim.sync(m.cannon());
    // The pivot at (400, 800) framebuffer pixels is (200, 400) in window points at 2x.
    const phys::Vec2 pivot{400, 800}, scale{2, 2};
    submit(m, drag(aim, m, pivot, scale, {200, 400}, {265, 335})); // 130 px at 45 degrees
    EXPECT_NEAR(m.cannon().angleDeg, 45.0, 0.05);
    EXPECT_NEAR(m.cannon().speedMps, m.cannon().def.maxSpeedMps * std::hypot(130.0, 130.0) / 260.0,
                0.05);
}

TEST(TurnControls, SpaceChargesUntilReleasedAndHeldArrowsSettleWhenLetGo) {
    game::Match m = earthBasics();
    ui::AimInput aim;
    aim.sync(m.cannon());
    // An arrow: its press steps the aim at once, held it repeats, and the aim becomes
    // commands once it is let go.
    const auto left = ui::pressTurnKey(SDLK_LEFT, aim, m);
    ASSERT_TRUE(left);
    EXPECT_TRUE(left->empty());
    EXPECT_TRUE(ui::holdToAim({1.0, 0.0}, 0.25, aim, m, true).empty()); // within the delay
    EXPECT_DOUBLE_EQ(aim.pending().angleDeg, 45.5);
    const std::vector<game::Command> settled = ui::holdToAim({}, 0.016, aim, m, true);
    ASSERT_EQ(kinds(settled), std::vector{CommandKind::Aim});
    submit(m, settled);
    EXPECT_DOUBLE_EQ(m.cannon().angleDeg, 45.5);
    // Space: a charge of 0.75 s (half of full power), fired on release.
    const auto press = ui::pressTurnKey(SDLK_SPACE, aim, m);
    ASSERT_TRUE(press);
    EXPECT_TRUE(press->empty()) << "the release fires, not the press";
    EXPECT_TRUE(aim.charging());
    ui::holdToAim({}, 0.75, aim, m, true);
    const std::vector<game::Command> shot = ui::releaseTurnKey(SDLK_SPACE, aim, m);
    ASSERT_FALSE(shot.empty());
    EXPECT_EQ(shot.back().kind, CommandKind::Fire);
    submit(m, shot);
    EXPECT_NEAR(m.cannon().speedMps, 0.5 * m.cannon().def.maxSpeedMps, 0.01);
    // Not one's turn (or a shell in flight): a charge is dropped, nothing is sent.
    ui::pressTurnKey(SDLK_SPACE, aim, m);
    EXPECT_FALSE(aim.charging()) << "no charge while the shell flies";
    EXPECT_TRUE(ui::holdToAim({1.0, 1.0}, 0.5, aim, m, false).empty());
    EXPECT_TRUE(ui::releaseTurnKey(SDLK_SPACE, aim, m).empty());
}
