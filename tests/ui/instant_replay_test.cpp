// The last shot again (Z): the live game's recording so far, watched from half a second
// before the shot while the game waits, the moment it lands in slow motion, then play goes
// on where it stood; the game is the same to the bit for it.
#include "headless_game.h"

#include "ui/game/replay_view.h"

#include <SDL.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

void key(ui::GameScreen& screen, SDL_Keycode k) { test_game::tap(screen, k); }

} // namespace

TEST(InstantReplay, TheLastShotIsWatchedAgainAndTheGameWaitsForIt) {
    const fs::path settings =
        fs::temp_directory_path() / ("artillery-instant-" + std::to_string(::getpid()));
    fs::remove_all(settings);
    {
        test_game::HeadlessGame game("05_castle.json", 640, 360, settings);
        ASSERT_NE(game.screen, nullptr);
        ui::GameScreen& screen = *game.screen;
        key(screen, SDLK_z);
        EXPECT_EQ(screen.replayViewer(), nullptr) << "no shot yet: nothing to watch";

        for (int f = 0; f < 120; ++f) // two seconds of aiming
            screen.frame(1.0 / 60.0);
        key(screen, SDLK_RETURN); // fire at the cannon's aim
        const game::Match& live = screen.session()->match();
        for (int f = 0; f < 60 * 20 && (live.shotsFired() == 0 || live.shell()); ++f)
            screen.frame(1.0 / 60.0);
        ASSERT_EQ(live.shotsFired(), 1);
        ASSERT_FALSE(live.shell()) << "the shot is over";
        const std::uint64_t tick = live.tick();
        const std::uint64_t hash = live.hash();

        key(screen, SDLK_z);
        ASSERT_NE(screen.replayViewer(), nullptr);
        EXPECT_TRUE(screen.replayViewer()->instant());
        std::uint64_t fired = 0;
        for (const game::GameEvent& e : live.events())
            if (e.kind == game::EventKind::Fired) fired = e.tick;
        ASSERT_GT(fired, 60u);
        screen.frame(1.0 / 60.0); // the jump, and a frame's two ticks
        EXPECT_EQ(screen.replayViewer()->player().tick(), fired - 60 + 2)
            << "half a second before the shot (120 Hz)";
        // Where the shot first met something: from a quarter of a second before to three
        // quarters after, the replay runs at x1/4.
        std::uint64_t impact = 0;
        for (const game::GameEvent& e : live.events())
            if (e.tick > fired && impact == 0 &&
                (e.kind == game::EventKind::Bounce || e.kind == game::EventKind::Burst ||
                 e.kind == game::EventKind::TargetHit || e.kind == game::EventKind::ShotOver))
                impact = e.tick;
        ASSERT_GT(impact, fired);
        const std::uint64_t slowFrom = impact - 30, slowTo = std::min(impact + 90, tick);
        // Watched to its end: the game waits meanwhile, then goes on.
        int frames = 0, slowFrames = 0;
        while (screen.replayViewer() && frames < 60 * 60) {
            EXPECT_EQ(live.tick(), tick);
            const std::uint64_t at = screen.replayViewer()->player().tick();
            const bool slow = at >= slowFrom && at < slowTo;
            const std::string banner = screen.replayViewer()->banner();
            EXPECT_NE(banner.find(slow ? "x1/4" : "x1 "), std::string::npos)
                << banner << " at " << at;
            screen.frame(1.0 / 60.0);
            ++frames;
            slowFrames += slow ? 1 : 0;
        }
        EXPECT_EQ(screen.replayViewer(), nullptr) << "back to the game at the end";
        // Two ticks a frame at x1; half a tick a frame at x1/4.
        EXPECT_NEAR(slowFrames, static_cast<double>(slowTo - slowFrom) * 2.0, 3.0);
        EXPECT_NEAR(frames - slowFrames,
                    static_cast<double>(tick - (fired - 60) - (slowTo - slowFrom)) / 2.0, 3.0)
            << "the rest plays in real time";
        EXPECT_EQ(live.tick(), tick);
        EXPECT_EQ(live.hash(), hash) << "watching changed nothing";
        screen.frame(1.0 / 60.0);
        EXPECT_GT(live.tick(), tick) << "play goes on";

        // Z again leaves at once.
        key(screen, SDLK_z);
        ASSERT_NE(screen.replayViewer(), nullptr);
        key(screen, SDLK_z);
        EXPECT_EQ(screen.replayViewer(), nullptr);
    }
    fs::remove_all(settings);
}
