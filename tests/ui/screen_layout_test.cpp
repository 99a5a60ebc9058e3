// The clear field: on the game screen no overlay (a HUD box, a panel, the close-up, a
// label, a card) covers what the player must see (a target, a cannon, the shell in flight,
// the point of impact). Checked on the layout the screen gathers as it draws a frame: every
// shipped level at home, and shots of the golden replays (the solver's games and the
// computer's duels) in mid-flight and at impact.
#include "headless_game.h"
#include "game/replay.h"
#include "game/replay_player.h"
#include "ui/game/match_view.h"
#include "ui/game/screen_layout.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// A scratch settings folder, gone with the test.
struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("artillery-layout-" + std::to_string(::getpid()));
    Scratch() { fs::remove_all(dir); }
    ~Scratch() { fs::remove_all(dir); }
};

std::string coveringsOf(const ui::ScreenLayout& layout) {
    std::string text;
    for (const ui::Covering& c : ui::coverings(layout)) text += "\n  " + ui::describe(layout, c);
    return text;
}

std::vector<std::string> shippedLevels() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(test_game::kRoot / "levels")) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".json" && name != "campaign.json") names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

/// Where a replay's shots are: each shot's tick of firing and its first contact.
struct Shot {
    std::uint64_t fired = 0, impact = 0;
};

std::vector<Shot> shotsOf(const fs::path& file) {
    game::Replay replay = game::loadReplay(file.string());
    const game::Level level = game::levelForReplay(file.string(), replay);
    game::ReplayPlayer player(level, std::move(replay));
    std::vector<Shot> shots;
    std::size_t seen = 0;
    while (player.tick() < player.lastTick()) {
        player.step();
        const auto& events = player.match().events();
        for (; seen < events.size(); ++seen) {
            using game::EventKind;
            const game::GameEvent& e = events[seen];
            if (e.kind == EventKind::Fired) shots.push_back({e.tick, 0});
            const bool contact = e.kind == EventKind::Bounce || e.kind == EventKind::Burst ||
                                 e.kind == EventKind::TargetHit || e.kind == EventKind::CannonHit ||
                                 e.kind == EventKind::ShotOver;
            if (contact && !shots.empty() && shots.back().impact == 0) shots.back().impact = e.tick;
        }
    }
    return shots;
}

/// The tick a replay's match ends at (0 if it does not).
std::uint64_t matchOverTick(const fs::path& file) {
    game::Replay replay = game::loadReplay(file.string());
    const game::Level level = game::levelForReplay(file.string(), replay);
    game::ReplayPlayer player(level, std::move(replay));
    while (player.tick() < player.lastTick() && !player.match().over()) player.step();
    return player.match().over() ? player.match().tick() : 0;
}

/// A replay on a headless game screen of 1280 x 720 (`screen` null when no context could
/// be made: the test has failed and says why).
struct ReplayOnScreen {
    std::unique_ptr<ui::GLContext> context;
    std::unique_ptr<ui::GameScreen> screen;

    explicit ReplayOnScreen(const fs::path& replay) {
        std::string error;
        context = ui::createHeadlessContext(1280, 720, ui::HeadlessBackend::Auto, error);
        EXPECT_NE(context, nullptr) << error;
        if (!context) return;
        ui::GameScreenDef def;
        def.replayFile = replay.string();
        def.levelsFolder = (test_game::kRoot / "levels").string();
        screen = std::make_unique<ui::GameScreen>(*context, nullptr, def);
    }
};

/// The replay on a headless game screen, played to `seconds`, then three frames drawn.
void expectClearAt(const fs::path& replay, double seconds, const std::string& what) {
    ReplayOnScreen on(replay);
    ASSERT_NE(on.screen, nullptr);
    ui::GameScreen& screen = *on.screen;
    screen.warmUp(seconds);
    for (int i = 0; i < 3; ++i) screen.frame(1.0 / 120.0);
    const ui::ScreenLayout& layout = screen.layout();
    EXPECT_FALSE(layout.objects.empty()) << what;
    EXPECT_TRUE(ui::coverings(layout).empty()) << what << ":" << coveringsOf(layout);
}

void expectShotsClear(const std::string& replayName, std::size_t mostShots) {
    const fs::path file = test_game::kRoot / "tests" / "replays" / replayName;
    const game::Replay replay = game::loadReplay(file.string());
    const std::vector<Shot> shots = shotsOf(file);
    ASSERT_FALSE(shots.empty()) << replayName;
    const double dt = 1.0 / 120.0;
    for (std::size_t i = 0; i < shots.size() && i < mostShots; ++i) {
        const Shot& s = shots[i];
        if (s.impact <= s.fired) continue;
        const auto mid = (s.fired + s.impact) / 2;
        char what[160];
        std::snprintf(what, sizeof what, "%s, shot %zu in flight (tick %llu)", replayName.c_str(),
                      i + 1, static_cast<unsigned long long>(mid));
        expectClearAt(file, static_cast<double>(mid) * dt, what);
        std::snprintf(what, sizeof what, "%s, shot %zu at impact (tick %llu)", replayName.c_str(),
                      i + 1, static_cast<unsigned long long>(s.impact));
        expectClearAt(file, static_cast<double>(s.impact) * dt, what);
    }
}

} // namespace

TEST(ScreenLayout, NothingCoversWhatThePlayerMustSeeOnAnyLevelAtHome) {
    Scratch scratch;
    for (const std::string& name : shippedLevels()) {
        fs::remove_all(scratch.dir);
        test_game::HeadlessGame game(name, 1280, 720, scratch.dir);
        ASSERT_NE(game.screen, nullptr);
        ASSERT_NE(game.screen->session(), nullptr) << name;
        // Home settles as ImGui sizes its windows: a frame or two more.
        for (int i = 0; i < 2; ++i) game.screen->frame(1.0 / 60.0);
        const ui::ScreenLayout& layout = game.screen->layout();
        EXPECT_EQ(layout.width, 1280);
        EXPECT_FALSE(layout.objects.empty()) << name;
        EXPECT_TRUE(ui::coverings(layout).empty()) << name << ":" << coveringsOf(layout);
    }
}

TEST(ScreenLayout, EveryTargetReadsInTheMainViewOrTheCloseUp) {
    Scratch scratch;
    for (const std::string& name : shippedLevels()) {
        fs::remove_all(scratch.dir);
        test_game::HeadlessGame game(name, 1280, 720, scratch.dir);
        ASSERT_NE(game.screen, nullptr);
        const ui::ScreenLayout& layout = game.screen->layout();
        bool inset = false;
        for (const ui::LayoutOverlay& o : layout.overlays) inset = inset || o.name == "inset";
        for (const ui::LayoutObject& o : layout.objects) {
            if (o.kind != "target" || o.view != "main" || inset) continue;
            const double across = std::min(o.rect.x1 - o.rect.x0, o.rect.y1 - o.rect.y0);
            EXPECT_GE(across, 10.0 - 1e-9) << name << ": a target " << across
                                           << " px across at home, and no close-up of it";
        }
    }
}

TEST(ScreenLayout, ShotsInFlightAndTheirImpactsAreNotCovered) {
    expectShotsClear("01_earth_basics.replay.json", 3);
    expectShotsClear("05_castle.replay.json", 2);
    expectShotsClear("06_rope_bridge.replay.json", 2);
}

TEST(ScreenLayout, DuelShotsInFlightAndTheirImpactsAreNotCovered) {
    expectShotsClear("10_duel.replay.json", 3);
}

// A shell smaller than 6 px across on screen is drawn larger than life: its disc (the
// layout's rectangle is its glow, kShellGlow times the disc) is at least 6 px across at
// 1280 x 720, mid-flight in the solver's games and the computer's duel.
TEST(ScreenLayout, TheShellInFlightIsDrawnAtLeastSixPixelsAcross) {
    int small = 0;
    for (const char* name : {"01_earth_basics.replay.json", "05_castle.replay.json",
                             "10_duel.replay.json"}) {
        const fs::path file = test_game::kRoot / "tests" / "replays" / name;
        for (const Shot& s : shotsOf(file)) {
            if (s.impact <= s.fired) continue;
            ReplayOnScreen on(file);
            ASSERT_NE(on.screen, nullptr);
            ui::GameScreen& screen = *on.screen;
            screen.warmUp(static_cast<double>((s.fired + s.impact) / 2) / 120.0);
            for (int i = 0; i < 3; ++i) screen.frame(1.0 / 120.0);
            ASSERT_NE(screen.replayViewer(), nullptr) << name;
            const game::Match& m = screen.replayViewer()->match();
            ASSERT_TRUE(m.shell().has_value()) << name << ": a shell in flight mid-shot";
            const double trueAcross =
                2.0 * m.world().particles.radius[*m.shell()] * screen.camera().pixelsPerMetre;
            if (trueAcross >= 6.0) continue;
            ++small;
            bool seen = false;
            for (const ui::LayoutObject& o : screen.layout().objects) {
                if (o.kind != "shell" || o.view != "main") continue;
                seen = true;
                const double across = std::max(o.rect.x1 - o.rect.x0, o.rect.y1 - o.rect.y0);
                EXPECT_GE(across / ui::kShellGlow, 6.0 - 1e-9)
                    << name << ": a shell " << trueAcross << " px across drawn " << across / ui::kShellGlow;
            }
            EXPECT_TRUE(seen) << name << ": the shell in flight is not in the layout";
        }
    }
    EXPECT_GT(small, 0) << "no shell smaller than 6 px across: nothing was checked";
}

// A game's end, played on from its replay (taken over at the end, as T does): the card
// (the breakdown and each star's needs) and the last shot's verdict are drawn, and stand
// clear of every target, cannon and impact.
TEST(ScreenLayout, TheEndCardAndTheVerdictCoverNothing) {
    for (const char* name : {"01_earth_basics.replay.json", "05_castle.replay.json",
                             "06_rope_bridge.replay.json", "07_soft_blob.replay.json"}) {
        const fs::path file = test_game::kRoot / "tests" / "replays" / name;
        const std::uint64_t over = matchOverTick(file);
        ASSERT_GT(over, 0u) << name << " ends its match";
        ReplayOnScreen on(file);
        ASSERT_NE(on.screen, nullptr);
        ui::GameScreen& screen = *on.screen;
        screen.warmUp(static_cast<double>(over + 60) / 120.0);
        test_game::tap(screen, SDLK_t);
        for (int i = 0; i < 3; ++i) screen.frame(1.0 / 120.0);
        const ui::ScreenLayout& layout = screen.layout();
        std::vector<std::string> drawn;
        for (const ui::LayoutOverlay& o : layout.overlays) drawn.push_back(o.name);
        EXPECT_NE(std::find(drawn.begin(), drawn.end(), "card"), drawn.end()) << name;
        EXPECT_NE(std::find(drawn.begin(), drawn.end(), "hud.verdict"), drawn.end()) << name;
        EXPECT_TRUE(ui::coverings(layout).empty()) << name << ":" << coveringsOf(layout);
    }
}

// A shot flown by explicit Euler at 30 Hz (recorded by `run`, watched as a replay 5 s in,
// after its landing): its one verdict carries the comparison with the exact path, a line
// far longer than the miss alone ("missed by 1.0 m, over" is some 200 px), and it covers
// nothing.
TEST(ScreenLayout, AnIntegratorsVerdictCarriesTheExactPathAndCoversNothing) {
    Scratch scratch;
    fs::create_directories(scratch.dir);
    const fs::path replay = scratch.dir / "euler.replay.json";
    const fs::path level = test_game::kRoot / "levels" / "12_first_shot.json";
    const fs::path commands = test_game::kRoot / "tests" / "data" / "first_shot_euler_30hz.json";
    const std::string command = std::string(ARTILLERY_EXE) + " run " + level.string() +
                                " --commands " + commands.string() + " --ticks 400 --record " +
                                replay.string() + " > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    ReplayOnScreen on(replay);
    ASSERT_NE(on.screen, nullptr);
    on.screen->warmUp(150.0 / 120.0);
    for (int i = 0; i < 3; ++i) on.screen->frame(1.0 / 120.0);
    const ui::ScreenLayout& layout = on.screen->layout();
    std::size_t verdicts = 0;
    for (const ui::LayoutOverlay& o : layout.overlays) {
        if (o.name != "hud.verdict") continue;
        ++verdicts;
        EXPECT_GT(o.rect.x1 - o.rect.x0, 500.0);
    }
    EXPECT_EQ(verdicts, 1u);
    EXPECT_TRUE(ui::coverings(layout).empty()) << coveringsOf(layout);
}

TEST(ScreenLayout, TheTurnsControlsFitWhatTheyHold) {
    Scratch scratch;
    test_game::HeadlessGame duel("10_duel.json", 1280, 720, scratch.dir);
    ASSERT_NE(duel.screen, nullptr);
    const ImGuiWindow* w = ImGui::FindWindowByName("Controls");
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->ScrollMax.x, 0.0f);
    EXPECT_EQ(w->ScrollMax.y, 0.0f);
    EXPECT_LE(w->Pos.x + w->Size.x, 1280.0f);
    EXPECT_LE(w->Pos.y + w->Size.y, 720.0f);
}

// `play --headless --json` reports the last frame's layout: the window's size, the
// overlays by name and the objects by kind and view, rectangles as [x, y, w, h].
TEST(ScreenLayout, ThePlayVerbReportsTheLayoutOfItsLastFrame) {
    const std::string command = std::string(ARTILLERY_EXE) + " play " +
                                (test_game::kRoot / "levels" / "05_castle.json").string() +
                                " --headless --frames 3 --json";
    FILE* pipe = ::popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string out;
    char buffer[4096];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
    EXPECT_EQ(::pclose(pipe), 0) << out;
    EXPECT_NE(out.find("\"layout\":{\"size\":[1280,720],\"overlays\":[{\"name\":\"hud.score\",\"rect\":[12,12,292,64]}"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("{\"kind\":\"cannon\",\"view\":\"main\",\"rect\":["), std::string::npos) << out;
    EXPECT_NE(out.find("{\"kind\":\"target\",\"view\":\"inset\",\"rect\":["), std::string::npos) << out;
    EXPECT_NE(out.find("{\"name\":\"panel.Controls\",\"rect\":["), std::string::npos) << out;
}
