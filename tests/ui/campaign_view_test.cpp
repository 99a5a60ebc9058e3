// The level select's way through the campaign: "Play next" (and Enter) opens the first
// open practice level not cleared yet, where the player left off, its chapter's lesson
// first the first time; duels, open from the start, are not the way.
#include "game/progress.h"
#include "ui/game/campaign_view.h"
#include "ui/game/game_menus.h"
#include "ui/game/game_screen.h"
#include "ui/game/lesson_pictures.h"
#include "ui/game/menu_flow.h"
#include "ui/platform/gl_context.h"

#include <SDL.h>
#include <imgui.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

const std::string kLevels =
    (std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "levels").string();

std::string fileName(const ui::CampaignMenu& menu, game::LevelPlace p) {
    return std::filesystem::path(menu.chapters[p.chapter][p.level].file).filename().string();
}

} // namespace

TEST(CampaignView, PlayNextIsWhereThePlayerLeftOff) {
    const ui::CampaignMenu menu = ui::campaignMenu(kLevels, ui::listLevels(kLevels));
    ASSERT_TRUE(menu.error.empty()) << menu.error;
    game::Progress progress;

    auto next = ui::levelOnTheWay(menu, progress);
    ASSERT_TRUE(next);
    EXPECT_EQ(*next, (game::LevelPlace{0, 0}));
    EXPECT_EQ(fileName(menu, *next), "12_first_shot.json");

    // The chapter's lesson comes first, the first time.
    ui::MenuChoice choice;
    ui::chooseLevel(menu, *next, progress, choice);
    ASSERT_TRUE(choice.showLesson);
    EXPECT_EQ(*choice.showLesson, 0u);
    EXPECT_EQ(std::filesystem::path(choice.lessonThenLevel).filename(), "12_first_shot.json");
    EXPECT_FALSE(choice.openLevel);

    // One star on the first level: the next is the second, and the lesson is not shown
    // again once read.
    progress.record("12_first_shot.json", 100, 1, false);
    progress.lessonsSeen.insert(menu.campaign.chapters[0].id);
    next = ui::levelOnTheWay(menu, progress);
    ASSERT_TRUE(next);
    EXPECT_EQ(*next, (game::LevelPlace{0, 1}));
    choice = {};
    ui::chooseLevel(menu, *next, progress, choice);
    EXPECT_FALSE(choice.showLesson);
    ASSERT_TRUE(choice.openLevel);
    EXPECT_EQ(std::filesystem::path(*choice.openLevel).filename(), fileName(menu, *next));

    // Every practice level cleared: nothing is on the way, whatever the duels say.
    for (const auto& chapter : menu.chapters)
        for (const ui::LevelEntry& e : chapter)
            if (e.mode != game::Mode::Duel)
                progress.record(std::filesystem::path(e.file).filename().string(), 100, 3, false);
    EXPECT_FALSE(ui::levelOnTheWay(menu, progress));
}

// From the first screen to the first shot with the keyboard alone: Enter on the level
// select opens the first chapter's lesson, Enter there the level. Headless there is no
// SDL backend, so the key goes into ImGui's input as the backend puts it there.
TEST(CampaignView, EnterTwiceFromTheLevelSelectPlaysTheFirstLevel) {
    std::string error;
    auto context = ui::createHeadlessContext(1280, 720, ui::HeadlessBackend::Auto, error);
    ASSERT_NE(context, nullptr) << error;
    ui::GameScreenDef def;
    def.levelsFolder = kLevels;
    ui::GameScreen screen(*context, nullptr, def);
    ImGuiIO& io = ImGui::GetIO();
    io.KeyMap[ImGuiKey_Enter] = SDL_SCANCODE_RETURN;
    auto enter = [&] {
        io.KeysDown[SDL_SCANCODE_RETURN] = true;
        screen.frame(1.0 / 60.0);
        io.KeysDown[SDL_SCANCODE_RETURN] = false;
        screen.frame(1.0 / 60.0);
        screen.frame(1.0 / 60.0);
    };
    for (int i = 0; i < 3; ++i)
        screen.frame(1.0 / 60.0);
    ASSERT_EQ(screen.session(), nullptr) << "the level select comes first";
    enter();
    EXPECT_EQ(screen.session(), nullptr) << "the lesson, not yet the level";
    enter();
    ASSERT_NE(screen.session(), nullptr);
    EXPECT_EQ(screen.session()->match().level().name, "First shot");
}

// A campaign naming a level file the folder lacks: the menu says which and why (the
// level select shows it at the top), and "Play next" goes on past it: the level after it
// is open, where it used to stay locked for ever.
TEST(CampaignView, AMissingLevelIsNamedAndPlayGoesOnPastIt) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "artillery-campaign-view-missing";
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy_file(fs::path(kLevels) / "01_earth_basics.json", dir / "01_earth_basics.json");
    fs::copy_file(fs::path(kLevels) / "02_moon.json", dir / "03_after.json");
    std::ofstream((dir / "campaign.json").string()) << R"({"format": 1, "chapters": [
        {"id": "a", "title": "A", "lesson": "l", "formula": "f",
         "levels": ["01_earth_basics.json", "02_gone.json", "03_after.json"]}]})";
    const ui::CampaignMenu menu = ui::campaignMenu(dir.string(), ui::listLevels(dir.string()));
    ASSERT_TRUE(menu.error.empty()) << menu.error;
    ASSERT_EQ(menu.missing.size(), 1u);
    EXPECT_EQ(menu.missing[0], (dir / "campaign.json").string() +
                                   ": $.chapters[0].levels[1]: names 02_gone.json, which cannot be "
                                   "played (no such level file in " + dir.string() +
                                   "): the levels after it open without it");
    game::Progress progress;
    progress.record("01_earth_basics.json", 100, 1, false);
    const auto next = ui::levelOnTheWay(menu, progress);
    ASSERT_TRUE(next);
    EXPECT_EQ(*next, (game::LevelPlace{0, 2}));
    EXPECT_EQ(fileName(menu, *next), "03_after.json");
    fs::remove_all(dir);
}

TEST(CampaignView, EveryChaptersLessonHasItsPictureAndCaption) {
    const ui::CampaignMenu menu = ui::campaignMenu(kLevels, ui::listLevels(kLevels));
    ASSERT_TRUE(menu.error.empty()) << menu.error;
    const std::vector<std::string>& drawn = ui::lessonPictureNames();
    for (const game::LessonPicture& p : game::lessonPictures()) {
        EXPECT_NE(std::find(drawn.begin(), drawn.end(), p.name), drawn.end()) << p.name;
        EXPECT_FALSE(ui::lessonPictureCaption(p.name).empty()) << p.name;
    }
    for (const game::Chapter& c : menu.campaign.chapters)
        EXPECT_FALSE(ui::lessonPictureCaption(c.picture).empty()) << c.id << ": " << c.picture;
}

TEST(CampaignView, AWeaponIsIntroducedByTheFirstLevelThatOffersIt) {
    const ui::MenuFlow flow(kLevels);
    const ui::CampaignMenu menu = ui::campaignMenu(kLevels, ui::listLevels(kLevels));
    std::vector<std::string> introduced;
    for (const std::vector<ui::LevelEntry>& chapter : menu.chapters)
        for (const ui::LevelEntry& e : chapter) {
            const std::string line = flow.weaponIntroduction(e.file);
            const bool offersANewOne = std::any_of(e.weapons.begin(), e.weapons.end(), [&](const std::string& w) {
                return std::find(introduced.begin(), introduced.end(), w) == introduced.end();
            });
            EXPECT_EQ(!line.empty(), offersANewOne) << e.file;
            introduced.insert(introduced.end(), e.weapons.begin(), e.weapons.end());
        }
    // Every one of the eight weapons is met somewhere in the campaign.
    for (const std::string w : {"cluster", "bouncer", "roller", "grenade", "mortar", "airburst", "digger", "sticky"})
        EXPECT_NE(std::find(introduced.begin(), introduced.end(), w), introduced.end()) << w;
}
