// The level editor's model: each edit and its undo and redo; hit-testing; the loader's
// verdict as the live validation (its very message, and Save refused while it fails);
// every shipped level opened and saved unchanged is the same level; an edited level
// saves, loads with the real loader and plays.
#include "game/editor/level_editor.h"
#include "game/files/text_file.h"
#include "game/level_write.h"
#include "game/session.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace game;
using namespace game::editor;
using phys::Vec2;

namespace {

const fs::path kSource = ARTILLERY_SOURCE_DIR;

Level content(Level l) {
    l.file.clear();
    l.contentHash.clear();
    return l;
}

/// A folder of this process's own (CTest runs test programs side by side).
fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() /
                         ("artillery-editor-test-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

Level earthBasics() {
    return loadLevel((kSource / "levels/01_earth_basics.json").string());
}

} // namespace

TEST(LevelEditor, ANewLevelPassesCheck) {
    LevelEditor editor(newLevel());
    EXPECT_TRUE(editor.valid()) << editor.problem();
    EXPECT_EQ(editor.file(), "");
    EXPECT_FALSE(editor.canUndo());
    EXPECT_FALSE(editor.modified());
}

TEST(LevelEditor, TerrainPointsGoInXOrderAndUndo) {
    LevelEditor editor(newLevel());
    const Level before = editor.level();
    const int i = editor.addTerrainPoint({50.0, 14.0});
    EXPECT_EQ(i, 3) << "between x = 40 and x = 60";
    EXPECT_EQ(editor.level().terrain.points[3], (Vec2{50.0, 14.0}));
    EXPECT_EQ(editor.level().terrain.points.size(), before.terrain.points.size() + 1);
    EXPECT_TRUE(editor.valid()) << editor.problem();
    EXPECT_EQ(editor.addTerrainPoint({40.0, 3.0}), -1) << "x = 40 has a point";
    EXPECT_NE(editor.refusal().find("has this x already"), std::string::npos);
    EXPECT_EQ(editor.addTerrainPoint({-5.0, 10.0}), 0) << "before the first point";
    editor.undo();
    editor.undo();
    EXPECT_TRUE(editor.level() == before);
    EXPECT_FALSE(editor.canUndo());
    editor.redo();
    EXPECT_EQ(editor.level().terrain.points[3], (Vec2{50.0, 14.0}));
    editor.redo();
    EXPECT_EQ(editor.level().terrain.points.front(), (Vec2{-5.0, 10.0}));
    EXPECT_FALSE(editor.canRedo());
}

TEST(LevelEditor, DeletingATerrainPointKeepsTwo) {
    Level l = newLevel();
    l.terrain.points = {{0.0, 10.0}, {100.0, 10.0}, {200.0, 10.0}};
    LevelEditor editor(l);
    EXPECT_TRUE(editor.remove({ItemKind::TerrainPoint, 1}));
    EXPECT_EQ(editor.level().terrain.points, (std::vector<Vec2>{{0.0, 10.0}, {200.0, 10.0}}));
    EXPECT_FALSE(editor.remove({ItemKind::TerrainPoint, 0}));
    EXPECT_EQ(editor.refusal(), "the terrain needs at least two points");
    editor.undo();
    EXPECT_EQ(editor.level().terrain.points.size(), 3u);
}

TEST(LevelEditor, PlacesEveryKindAndUndoesEachPlacement) {
    LevelEditor editor(newLevel());
    const Level start = editor.level();
    const Item cannon = editor.place(ItemKind::Cannon, {180.0, 10.0});
    const Item target = editor.place(ItemKind::Target, {100.0, 30.0});
    const Item block = editor.place(ItemKind::Block, {90.0, 10.5});
    const Item rope = editor.place(ItemKind::Rope, {60.0, 40.0});
    const Item blob = editor.place(ItemKind::Blob, {120.0, 20.0});
    const Level& l = editor.level();
    ASSERT_EQ(l.cannons.size(), 2u);
    EXPECT_EQ(l.cannons[1].player, "cpu") << "a second cannon is the computer's";
    EXPECT_DOUBLE_EQ(l.cannons[1].angleDeg, 135.0) << "aims back across the level";
    EXPECT_EQ(l.targets[static_cast<std::size_t>(target.index)].position, (Vec2{100.0, 30.0}));
    EXPECT_EQ(l.blocks[static_cast<std::size_t>(block.index)].position, (Vec2{90.0, 10.5}));
    EXPECT_EQ(l.ropes[static_cast<std::size_t>(rope.index)].from, (Vec2{60.0, 40.0}));
    EXPECT_EQ(l.blobs[static_cast<std::size_t>(blob.index)].center, (Vec2{120.0, 20.0}));
    EXPECT_EQ(cannon, (Item{ItemKind::Cannon, 1, -1}));
    EXPECT_TRUE(editor.valid()) << editor.problem();
    for (int i = 0; i < 5; ++i)
        editor.undo();
    EXPECT_TRUE(editor.level() == start);
    for (int i = 0; i < 5; ++i)
        editor.redo();
    EXPECT_EQ(editor.level().blobs.size(), 1u);
}

TEST(LevelEditor, HitTestFindsTheNearestHandleThenBodies) {
    Level l = newLevel();
    Block b;
    b.position = {100.0, 11.0};
    b.size = {4.0, 2.0};
    b.angleDeg = 90.0; // 2 m wide, 4 m tall once turned
    l.blocks.push_back(b);
    Rope r;
    r.from = {60.0, 40.0};
    r.to = {70.0, 40.0};
    l.ropes.push_back(r);
    LevelEditor editor(l);
    EXPECT_EQ(editor.hitTest({24.3, 10.2}, 0.5), (Item{ItemKind::Cannon, 0, -1}));
    EXPECT_EQ(editor.hitTest({20.1, 10.0}, 0.5), (Item{ItemKind::TerrainPoint, 1, -1}));
    EXPECT_EQ(editor.hitTest({150.5, 12.5}, 0.5), (Item{ItemKind::Target, 0, -1}));
    EXPECT_EQ(editor.hitTest({80.2, 10.1}, 0.5), (Item{ItemKind::TerrainPoint, 4, -1}));
    EXPECT_EQ(editor.hitTest({100.0, 12.8}, 0.5), (Item{ItemKind::Block, 0, -1}))
        << "inside, turned";
    EXPECT_FALSE(editor.hitTest({101.8, 11.0}, 0.5)) << "outside the turned block";
    EXPECT_EQ(editor.hitTest({70.2, 40.0}, 0.5), (Item{ItemKind::Rope, 0, 1}));
    EXPECT_EQ(editor.hitTest({65.0, 40.3}, 0.5), (Item{ItemKind::Rope, 0, -1}));
    EXPECT_FALSE(editor.hitTest({120.0, 60.0}, 0.5));
}

TEST(LevelEditor, ADragIsOneUndoStepAndMovesWhatIsTiedToIt) {
    Level l = newLevel();
    Block b;
    b.position = {100.0, 12.0};
    b.size = {2.0, 2.0};
    l.blocks.push_back(b);
    Rope r;
    r.from = {100.0, 30.0};
    r.to = {100.0, 12.5};
    r.pinTo = false;
    r.toBlock = 0;
    l.ropes.push_back(r);
    LevelEditor editor(l);
    ASSERT_TRUE(editor.valid()) << editor.problem();
    const Item block{ItemKind::Block, 0};
    editor.beginGesture();
    for (int i = 1; i <= 10; ++i)
        editor.dragTo(block, {100.0 + i, 12.0});
    editor.endGesture();
    EXPECT_EQ(editor.level().blocks[0].position, (Vec2{110.0, 12.0}));
    EXPECT_EQ(editor.level().ropes[0].to, (Vec2{110.0, 12.5})) << "the tied end went along";
    EXPECT_EQ(editor.level().ropes[0].from, (Vec2{100.0, 30.0}));
    EXPECT_TRUE(editor.valid()) << editor.problem();
    editor.undo();
    EXPECT_TRUE(editor.level() == l) << "the whole drag undoes at once";
    EXPECT_FALSE(editor.canUndo());
}

TEST(LevelEditor, DeletingABlockUntiesItsRopesAndRenumbersTheRest) {
    Level l = newLevel();
    for (double x : {90.0, 100.0, 110.0}) {
        Block b;
        b.position = {x, 12.0};
        l.blocks.push_back(b);
    }
    Rope r;
    r.from = {90.0, 12.0};
    r.to = {110.0, 12.0};
    r.fromBlock = 0;
    r.toBlock = 2;
    l.ropes.push_back(r);
    LevelEditor editor(l);
    ASSERT_TRUE(editor.valid()) << editor.problem();
    EXPECT_TRUE(editor.remove({ItemKind::Block, 0}));
    EXPECT_EQ(editor.level().ropes[0].fromBlock, -1);
    EXPECT_EQ(editor.level().ropes[0].toBlock, 1);
    EXPECT_TRUE(editor.valid()) << editor.problem();
    EXPECT_FALSE(editor.remove({ItemKind::Cannon, 0}));
    EXPECT_EQ(editor.refusal(), "a level needs at least one cannon");
}

TEST(LevelEditor, ATargetInTheGroundShowsTheLoadersMessageAndIsNotSaved) {
    const fs::path dir = scratch("invalid-target");
    LevelEditor editor(earthBasics());
    ASSERT_TRUE(editor.valid()) << editor.problem();
    const Vec2 below{editor.level().targets[0].position.x, -5.0};
    editor.move({ItemKind::Target, 0}, below);
    EXPECT_FALSE(editor.valid());
    // The loader's own words for the same file.
    Level written = editor.level();
    std::string loaderSays;
    try {
        parseLevel(editor.file(), levelToJson(written));
    } catch (const LoadError& e) {
        loaderSays = e.what();
    }
    EXPECT_EQ(editor.problem(), loaderSays);
    EXPECT_NE(editor.problem().find("$.targets[0].position"), std::string::npos)
        << editor.problem();
    EXPECT_NE(editor.problem().find("above the ground"), std::string::npos) << editor.problem();
    const std::string why = editor.save((dir / "bad.json").string());
    EXPECT_NE(why.find("does not pass check"), std::string::npos) << why;
    EXPECT_FALSE(fs::exists(dir / "bad.json"));
    ASSERT_NE(editor.checked(), nullptr);
    EXPECT_TRUE(content(*editor.checked()) == content(earthBasics())) << "the last valid state";
    editor.undo();
    EXPECT_TRUE(editor.valid());
    fs::remove_all(dir);
}

TEST(LevelEditor, ATerrainPointMakingXDecreaseShowsTheLoadersMessage) {
    LevelEditor editor(newLevel());
    editor.move({ItemKind::TerrainPoint, 3}, {10.0, 10.0}); // x 60 -> 10, after x = 40
    EXPECT_FALSE(editor.valid());
    EXPECT_NE(editor.problem().find("$.terrain.points[3]"), std::string::npos) << editor.problem();
    EXPECT_NE(editor.problem().find("expected x to increase"), std::string::npos)
        << editor.problem();
    EXPECT_NE(editor.save((fs::temp_directory_path() / "never.json").string()), "");
}

TEST(LevelEditor, EveryShippedLevelSavedUnchangedIsTheSameLevel) {
    const fs::path dir = scratch("round-trip");
    int count = 0;
    for (const auto& entry : fs::directory_iterator(kSource / "levels")) {
        if (entry.path().extension() != ".json" || entry.path().filename() == "campaign.json")
            continue;
        ++count;
        const Level original = loadLevel(entry.path().string());
        LevelEditor editor(original);
        ASSERT_TRUE(editor.valid()) << entry.path() << ": " << editor.problem();
        const fs::path written = dir / entry.path().filename();
        ASSERT_EQ(editor.save(written.string()), "") << entry.path();
        EXPECT_EQ(editor.file(), written.string());
        EXPECT_FALSE(editor.modified());
        const Level again = loadLevel(written.string());
        EXPECT_EQ(again.name, original.name) << entry.path();
        EXPECT_EQ(again.mode, original.mode) << entry.path();
        EXPECT_TRUE(again.physics == original.physics) << entry.path();
        EXPECT_TRUE(again.terrain == original.terrain) << entry.path();
        EXPECT_TRUE(again.cannons == original.cannons) << entry.path();
        EXPECT_TRUE(again.targets == original.targets) << entry.path();
        EXPECT_TRUE(again.blocks == original.blocks) << entry.path();
        EXPECT_TRUE(again.ropes == original.ropes) << entry.path();
        EXPECT_TRUE(again.blobs == original.blobs) << entry.path();
        EXPECT_TRUE(content(again) == content(original)) << entry.path();
    }
    EXPECT_GE(count, 10);
    fs::remove_all(dir);
}

TEST(LevelEditor, AnEditedLevelSavesLoadsAndPlays) {
    const fs::path dir = scratch("edited");
    LevelEditor editor(earthBasics());
    const Vec2 moved = editor.level().targets[0].position + Vec2{-3.0, 2.0};
    editor.move({ItemKind::Target, 0}, moved);
    const Vec2 blockAt{editor.level().cannons[0].position.x + 12.0, 0.0};
    const Heightfield ground(editor.level().terrain.points);
    editor.place(ItemKind::Block, {blockAt.x, ground.heightAt(blockAt.x) + 2.0});
    Level windy = editor.level();
    windy.physics.windMin = -4.0;
    windy.physics.windMax = 3.0;
    editor.change(windy);
    ASSERT_TRUE(editor.valid()) << editor.problem();
    const std::string file = (dir / "earth_edited.json").string();
    ASSERT_EQ(editor.save(file), "");

    const Level loaded = loadLevel(file); // the loader `check` runs
    EXPECT_EQ(loaded.targets[0].position, moved);
    EXPECT_EQ(loaded.blocks.size(), earthBasics().blocks.size() + 1);
    EXPECT_DOUBLE_EQ(loaded.physics.windMin, -4.0);
    EXPECT_DOUBLE_EQ(loaded.physics.windMax, 3.0);

    SessionOptions o;
    o.autoplay = true; // the computer plays the level
    Session session(loaded, o);
    for (int i = 0; i < 600; ++i)
        session.step();
    const Match& m = session.match();
    EXPECT_EQ(m.tick(), 600u);
    EXPECT_GE(m.shotsFired(), 1) << "the computer fired within 5 s";
    for (const GameEvent& e : m.events())
        EXPECT_NE(e.kind, EventKind::Unstable) << e.text;
    EXPECT_GE(m.wind(), -4.0);
    EXPECT_LE(m.wind(), 3.0);
    fs::remove_all(dir);
}
