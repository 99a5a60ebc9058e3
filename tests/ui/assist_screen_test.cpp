// The window's learning aids are commands: with the full preview or the hint chosen in
// the player's settings, the game screen sends `assist` on the player's turn, so the
// session records it (a replay keeps it) and the match caps its stars; with the launch
// arc alone it sends nothing.
#include "game/files/text_file.h"
#include "ui/game/game_screen.h"
#include "ui/platform/gl_context.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace {

const std::filesystem::path kRoot =
    std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();

/// Opens the castle with a settings file holding `settingsJson`, runs a few frames and
/// returns the match's assisted() and how many assist commands the session recorded.
std::pair<int, int> assistsFor(const std::string& settingsJson) {
    // One folder per process: CTest runs these tests side by side.
    const auto dir = std::filesystem::temp_directory_path() /
                     ("artillery-assist-screen-test-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    game::writeFileAtomically((dir / "settings.json").string(), settingsJson);
    std::string error;
    auto context = ui::createHeadlessContext(320, 200, ui::HeadlessBackend::Auto, error);
    EXPECT_NE(context, nullptr) << error;
    if (!context) return {-1, -1};
    ui::GameScreenDef def;
    def.levelFile = (kRoot / "levels/05_castle.json").string();
    def.levelsFolder = (kRoot / "levels").string();
    def.settingsFolder = dir.string();
    int assisted = 0, commands = 0;
    {
        ui::GameScreen screen(*context, nullptr, def);
        for (int i = 0; i < 4; ++i)
            screen.frame(1.0 / 60.0);
        assisted = screen.session()->match().assisted();
        for (const game::Command& c : screen.session()->recording().commands)
            commands += c.kind == game::CommandKind::Assist;
    }
    std::filesystem::remove_all(dir);
    return {assisted, commands};
}

TEST(AssistScreen, TheLaunchArcAloneIsNoAssist) {
    const auto [assisted, commands] = assistsFor(R"({"format": 1})");
    EXPECT_EQ(assisted, 0);
    EXPECT_EQ(commands, 0);
}

TEST(AssistScreen, TheFullPreviewIsRecordedOnce) {
    const auto [assisted, commands] = assistsFor(R"({"format": 1, "full_preview": true})");
    EXPECT_EQ(assisted, game::kAssistPreview);
    EXPECT_EQ(commands, 1) << "sent once, not every frame";
}

TEST(AssistScreen, TheHintIsRecorded) {
    const auto [assisted, commands] = assistsFor(R"({"format": 1, "solution_hint": true})");
    EXPECT_EQ(assisted, game::kAssistHint);
    EXPECT_EQ(commands, 1);
}

} // namespace
