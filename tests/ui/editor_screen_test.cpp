// The level editor on the game screen, headless: it opens on a level (`play --edit`),
// draws the level beside its panel with the handles where the camera maps them, takes
// mouse presses and keys as the window would send them, refuses to play or save a level
// that fails the loader, plays the edited level (F5) and comes back to it intact (F4).
#include "game/files/text_file.h"
#include "game/terrain.h"
#include "sdl_events.h"
#include "ui/game/game_screen.h"
#include "ui/platform/gl_context.h"
#include "ui/render/screenshot.h"

#include <SDL.h>
#include <gtest/gtest.h>
#include <stb_image.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using game::editor::ItemKind;
using phys::Vec2;

const fs::path kRoot = fs::path(__FILE__).parent_path().parent_path().parent_path();
constexpr int kW = 960;
constexpr int kH = 540;

/// A settings folder of this process's own: the maps folder (Save As, the playtest)
/// is inside it.
struct Scratch {
    fs::path dir =
        fs::temp_directory_path() / ("artillery-editor-screen-test-" + std::to_string(::getpid()));
    Scratch() {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~Scratch() { fs::remove_all(dir); }
};

ui::GameScreenDef editCastle(const fs::path& settings) {
    ui::GameScreenDef def;
    def.edit = true;
    def.levelFile = (kRoot / "levels/05_castle.json").string();
    def.levelsFolder = (kRoot / "levels").string();
    def.settingsFolder = settings.string();
    return def;
}

SDL_Event key(SDL_Keycode sym) {
    SDL_Event e{};
    e.type = SDL_KEYDOWN;
    e.key.keysym.sym = sym;
    return e;
}

using test_events::button;
using test_events::motion;

/// The PNG as written, RGBA, row 0 at the top.
ui::Image readPng(const std::string& path) {
    ui::Image img;
    int channels = 0;
    unsigned char* px = stbi_load(path.c_str(), &img.width, &img.height, &channels, 4);
    if (!px) return img;
    img.rgba.assign(px, px + static_cast<std::size_t>(img.width) * img.height * 4);
    stbi_image_free(px);
    return img;
}

/// True when some pixel within `r` px of `p` satisfies `test`.
template <class Test> bool anyNear(const ui::Image& img, Vec2 p, int r, Test test) {
    for (int y = static_cast<int>(p.y) - r; y <= static_cast<int>(p.y) + r; ++y)
        for (int x = static_cast<int>(p.x) - r; x <= static_cast<int>(p.x) + r; ++x)
            if (x >= 0 && y >= 0 && x < img.width && y < img.height && test(img.pixel(x, y)))
                return true;
    return false;
}

bool yellow(const std::uint8_t* c) {
    return c[0] > 200 && c[1] > 160 && c[2] < 130;
}
bool red(const std::uint8_t* c) {
    return c[0] > 200 && c[1] < 110 && c[2] < 110;
}
bool white(const std::uint8_t* c) {
    return c[0] > 215 && c[1] > 215 && c[2] > 190;
}

} // namespace

TEST(EditorScreen, DrawsTheLevelBesideThePanelWithItsHandles) {
    Scratch scratch;
    std::string error;
    auto context = ui::createHeadlessContext(kW, kH, ui::HeadlessBackend::Auto, error);
    ASSERT_NE(context, nullptr) << error;
    ui::GameScreen screen(*context, nullptr, editCastle(scratch.dir));
    ui::LevelEditorView* view = screen.levelEditor();
    ASSERT_NE(view, nullptr);
    EXPECT_EQ(screen.session(), nullptr) << "nothing is played while editing";
    const ui::Camera camera = view->framing(kW, kH);
    // Pick the first block by a click on it, as the window would send it.
    const Vec2 block = view->editor().level().blocks[0].position;
    screen.handleEvent(button(SDL_MOUSEBUTTONDOWN, camera.toPixel(block)));
    screen.handleEvent(button(SDL_MOUSEBUTTONUP, camera.toPixel(block)));
    EXPECT_EQ(view->selection().kind, ItemKind::Block);
    EXPECT_EQ(view->selection().index, 0);
    EXPECT_EQ(view->editor().level().blocks[0].position, block) << "a click without a drag";
    EXPECT_FALSE(view->editor().canUndo()) << "moves nothing";
    for (int i = 0; i < 2; ++i)
        screen.frame(1.0 / 60.0);
    const fs::path png = scratch.dir / "editor.png";
    ASSERT_EQ(screen.saveScreenshot(png.string()), "");
    const ui::Image img = readPng(png.string());
    ASSERT_EQ(img.width, kW);

    // The panel on the left, dark; the world right of it, the sky not dark.
    const std::uint8_t* panel = img.pixel(static_cast<int>(ui::kEditorPanelWidth) - 12, kH - 12);
    EXPECT_LT(panel[0] + panel[1] + panel[2], 120) << "the panel's background";
    const Vec2 sky = camera.toPixel({110.0, 110.0});
    const std::uint8_t* skyPx = img.pixel(static_cast<int>(sky.x), static_cast<int>(sky.y));
    EXPECT_GT(skyPx[0] + skyPx[1] + skyPx[2], 200) << "the level's sky beside the panel";
    EXPECT_GT(sky.x, ui::kEditorPanelWidth) << "the world is framed beside the panel";
    // The selected block's outline in the selection's yellow, a terrain point's handle white.
    EXPECT_TRUE(anyNear(img, camera.toPixel(block), 4, yellow)) << "selected block outline";
    EXPECT_TRUE(anyNear(img, camera.toPixel({80.0, 0.0}), 2, white)) << "terrain handle";
    EXPECT_FALSE(anyNear(img, camera.toPixel({110.0, 60.0}), 4, yellow))
        << "nothing selected there";
}

TEST(EditorScreen, PlaysTheEditedLevelAndComesBackToIt) {
    Scratch scratch;
    std::string error;
    auto context = ui::createHeadlessContext(kW, kH, ui::HeadlessBackend::Auto, error);
    ASSERT_NE(context, nullptr) << error;
    ui::GameScreen screen(*context, nullptr, editCastle(scratch.dir));
    ui::LevelEditorView* view = screen.levelEditor();
    ASSERT_NE(view, nullptr);
    const std::size_t blocks = view->editor().level().blocks.size();
    const ui::Camera camera = view->framing(kW, kH);
    screen.handleEvent(key(SDLK_5)); // the block tool
    EXPECT_EQ(view->tool(), ui::LevelEditorView::Tool::Block);
    const Vec2 at{100.0, 0.5}; // on the flat ground left of the castle (snapped: the same)
    screen.handleEvent(button(SDL_MOUSEBUTTONDOWN, camera.toPixel(at)));
    screen.handleEvent(button(SDL_MOUSEBUTTONUP, camera.toPixel(at)));
    ASSERT_EQ(view->editor().level().blocks.size(), blocks + 1);
    EXPECT_NEAR(view->editor().level().blocks.back().position.x, 100.0, 0.5);
    EXPECT_TRUE(view->editor().valid()) << view->editor().problem();
    screen.frame(1.0 / 60.0);

    // A block sunk into the ground: the loader's message; F5 and Save do nothing.
    game::Level sunk = view->editor().level();
    sunk.blocks.back().position = {100.0, -5.0};
    view->editor().change(sunk);
    EXPECT_NE(view->editor().problem().find("above the ground"), std::string::npos)
        << view->editor().problem();
    // The block the message names is marked red where it lies.
    screen.frame(1.0 / 60.0);
    const fs::path png = scratch.dir / "sunk.png";
    ASSERT_EQ(screen.saveScreenshot(png.string()), "");
    EXPECT_TRUE(anyNear(readPng(png.string()), camera.toPixel({100.0, -5.0}), 4, red))
        << "the block named by the loader";
    screen.handleEvent(key(SDLK_F5));
    EXPECT_FALSE(screen.playtest());
    EXPECT_NE(view->saveAs("sunk"), "");
    EXPECT_FALSE(fs::exists(scratch.dir / "maps/sunk.json"));
    view->editor().undo();
    ASSERT_TRUE(view->editor().valid());
    const game::Level edited = view->editor().level();

    screen.handleEvent(key(SDLK_F5));
    ASSERT_TRUE(screen.playtest());
    ASSERT_NE(screen.session(), nullptr);
    EXPECT_EQ(screen.levelEditor(), nullptr) << "the match is on screen";
    const game::Level& played = screen.session()->match().level();
    EXPECT_EQ(played.file, (scratch.dir / "maps/playtest.json").string());
    EXPECT_EQ(played.blocks.size(), blocks + 1);
    for (int i = 0; i < 30; ++i)
        screen.frame(1.0 / 60.0);
    EXPECT_GT(screen.session()->match().tick(), 0u);

    screen.handleEvent(key(SDLK_F4));
    ASSERT_NE(screen.levelEditor(), nullptr);
    EXPECT_FALSE(screen.playtest());
    EXPECT_EQ(screen.session(), nullptr);
    EXPECT_TRUE(screen.levelEditor()->editor().level() == edited) << "the level came back intact";
    EXPECT_TRUE(screen.levelEditor()->editor().canUndo()) << "and so did its history";

    // Saved as a file in the maps folder, which the loader reads back as the same level.
    ASSERT_EQ(screen.levelEditor()->saveAs("castle_plus"), "");
    const game::Level saved = game::loadLevel((scratch.dir / "maps/castle_plus.json").string());
    EXPECT_EQ(saved.blocks.size(), blocks + 1);
}

TEST(EditorScreen, ARopeDrawnOntoABlockIsTiedToIt) {
    Scratch scratch;
    std::string error;
    auto context = ui::createHeadlessContext(kW, kH, ui::HeadlessBackend::Auto, error);
    ASSERT_NE(context, nullptr) << error;
    ui::GameScreen screen(*context, nullptr, editCastle(scratch.dir));
    ui::LevelEditorView* view = screen.levelEditor();
    ASSERT_NE(view, nullptr);
    const ui::Camera camera = view->framing(kW, kH);
    const game::Block& crate = view->editor().level().blocks[0]; // at (150, 0.5), 1 m
    const Vec2 anchor{140.0, 20.0};
    screen.handleEvent(key(SDLK_6));
    screen.handleEvent(button(SDL_MOUSEBUTTONDOWN, camera.toPixel(anchor)));
    for (double s : {0.25, 0.5, 0.75, 1.0})
        screen.handleEvent(motion(camera.toPixel(anchor + (crate.position - anchor) * s)));
    screen.handleEvent(button(SDL_MOUSEBUTTONUP, camera.toPixel(crate.position)));
    ASSERT_EQ(view->editor().level().ropes.size(), 1u);
    const game::Rope& rope = view->editor().level().ropes[0];
    EXPECT_EQ(rope.from, anchor);
    EXPECT_NEAR(rope.to.x, crate.position.x, 0.5);
    EXPECT_EQ(rope.toBlock, 0) << "let go inside block 0";
    EXPECT_EQ(rope.fromBlock, -1);
    EXPECT_TRUE(view->editor().valid()) << view->editor().problem();
    view->editor().undo();
    EXPECT_TRUE(view->editor().level().ropes.size() == 1u &&
                view->editor().level().ropes[0].toBlock == -1)
        << "the drag (tie included) is one step; the placement another";
    view->editor().undo();
    EXPECT_TRUE(view->editor().level().ropes.empty());
}
