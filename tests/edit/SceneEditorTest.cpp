#include <abalike/edit/SceneEditor.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>
#include <cmath>

#include <gtest/gtest.h>
#include <random>

namespace abalike
{
namespace
{

/// Every edit goes through this: it checks that undo gives back exactly the level before the edit and redo
/// exactly the level after it.
template <class Edit>
void expectUndoable(SceneEditor& editor, Edit&& edit)
{
    const LevelDef before = editor.level();
    edit();
    const LevelDef after = editor.level();
    ASSERT_NE(after, before) << "the edit changed nothing";
    ASSERT_TRUE(editor.canUndo());
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.level(), before);
    ASSERT_TRUE(editor.redo());
    EXPECT_EQ(editor.level(), after);
}

LevelDef towerLevel()
{
    LevelDef level = emptyScene();
    level.sandbox = false;
    level.id = "t";
    level.title = "Tower";
    level.blocks = {{BlockShape::Box, "stone", 20.0, 0.25, 3.0, 0.5, 0.0, 0.1},
                    {BlockShape::Box, "wood", 19.0, 1.5, 0.25, 2.0, 0.0, 0.1},
                    {BlockShape::Box, "wood", 21.0, 1.5, 0.25, 2.0, 0.0, 0.1}};
    level.pigs = {{"small", 20.0, 0.75}};
    level.terrain = {{40.0, 1.0, 4.0, 2.0, 0.0, {}}};
    return level;
}

TEST(SceneEditor, EmptySceneIsASandboxThatSavesAsALevel)
{
    SceneEditor editor(emptyScene());
    EXPECT_TRUE(editor.level().sandbox);
    EXPECT_TRUE(editor.level().pigs.empty());
    EXPECT_FALSE(editor.dirty());
    EXPECT_TRUE(editor.saveProblems().empty());
    EXPECT_FALSE(editor.canUndo());
}

TEST(SceneEditor, PlacesABlockOfEveryShapeAndMaterialEachUndoable)
{
    SceneEditor editor(emptyScene());
    editor.snapSettings().grid = false;
    editor.snapSettings().surfaces = false;
    double x = 5.0;
    for (const BlockShape shape : {BlockShape::Box, BlockShape::Circle, BlockShape::Triangle, BlockShape::HollowBox})
        for (const Material& material : Catalog::builtin().materials())
        {
            SCOPED_TRACE(material.name);
            BlockDef block{shape, material.name, x, 1.0, 1.0, 1.0, 0.0, 0.1};
            x += 2.0;
            expectUndoable(editor, [&] { editor.place(block); });
            const BlockDef& placed = editor.level().blocks.back();
            EXPECT_EQ(placed.shape, shape);
            EXPECT_EQ(placed.material, material.name);
            EXPECT_EQ(placed.x, block.x);
            ASSERT_EQ(editor.selection().size(), 1u);
            EXPECT_EQ(editor.selection()[0], (ObjectRef{ObjectKind::Block, editor.level().blocks.size() - 1}));
        }
    EXPECT_EQ(editor.level().blocks.size(), 4u * Catalog::builtin().materials().size());
}

TEST(SceneEditor, PlacesPigsOfEveryTypeTerrainAndTheSlingshot)
{
    SceneEditor editor(emptyScene());
    editor.snapSettings().grid = false;
    double x = 5.0;
    for (const PigType& type : Catalog::builtin().pigs())
    {
        expectUndoable(editor, [&] { editor.place(PigDef{type.name, x, 3.0}); });
        // Surface snapping drops it onto the ground from within reach only; 3 m up it stays where it was put.
        EXPECT_EQ(editor.level().pigs.back().type, type.name);
        EXPECT_EQ(editor.level().pigs.back().y, 3.0);
        x += 2.0;
    }
    expectUndoable(editor, [&] { editor.place(TerrainDef{30.0, 2.0, 6.0, 4.0, 10.0, {}}); });
    EXPECT_EQ(editor.level().terrain.size(), 1u);
    expectUndoable(editor, [&] { editor.place(SlingshotDef{-3.0, 2.0, 1200.0, std::nullopt, std::nullopt}); });
    EXPECT_EQ(editor.level().slingshot.x, -3.0);
    EXPECT_EQ(editor.selection(), (std::vector<ObjectRef>{{ObjectKind::Slingshot, 0}}));
}

TEST(SceneEditor, RefusesToPlaceWhatTheFormatRejects)
{
    SceneEditor editor(emptyScene());
    EXPECT_THROW(editor.place(BlockDef{BlockShape::Box, "cheese", 5, 1, 1, 1, 0, 0.1}), std::invalid_argument);
    EXPECT_THROW(editor.place(BlockDef{BlockShape::Box, "wood", 5, 1, 12, 1, 0, 0.1}), std::invalid_argument);
    EXPECT_THROW(editor.place(PigDef{"tiny", 5, 1}), std::invalid_argument);
    EXPECT_EQ(editor.level(), emptyScene());
    EXPECT_FALSE(editor.canUndo());
}

TEST(SceneEditor, MovesTheSelectionExactly)
{
    SceneEditor editor(towerLevel());
    editor.select({ObjectKind::Block, 1});
    editor.select({ObjectKind::Pig, 0}, SelectMode::Add);
    expectUndoable(editor, [&] { editor.moveSelection(0.1, 0.2); });
    EXPECT_EQ(editor.level().blocks[1].x, 19.1);
    EXPECT_EQ(editor.level().blocks[1].y, 1.7);
    EXPECT_EQ(editor.level().pigs[0].x, 20.1);
    EXPECT_EQ(editor.level().pigs[0].y, 0.95); // 0.75 + 0.2 cleaned to the decimal, not 0.9500000000000001
    EXPECT_EQ(editor.level().blocks[0], towerLevel().blocks[0]);
    EXPECT_EQ(editor.undoLabel(), "Move 2 objects");
}

TEST(SceneEditor, ADragIsOneUndoStep)
{
    SceneEditor editor(towerLevel());
    editor.snapSettings().grid = false;
    editor.snapSettings().surfaces = false;
    const LevelDef before = editor.level();
    editor.beginDrag({ObjectKind::Terrain, 0});
    for (int i = 1; i <= 30; ++i)
        editor.dragTo(0.1 * i, 0.0);
    editor.endDrag();
    EXPECT_DOUBLE_EQ(editor.level().terrain[0].x, 43.0);
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.level(), before);
    EXPECT_FALSE(editor.canUndo());
    // A second drag after the first ended is a second step.
    editor.redo();
    editor.beginDrag({ObjectKind::Terrain, 0});
    editor.dragTo(1.0, 0.0);
    editor.endDrag();
    editor.undo();
    EXPECT_DOUBLE_EQ(editor.level().terrain[0].x, 43.0);
}

TEST(SceneEditor, DraggingASelectionKeepsItsFormation)
{
    SceneEditor editor(towerLevel());
    editor.snapSettings().grid = false;
    editor.select({ObjectKind::Block, 1});
    editor.select({ObjectKind::Block, 2}, SelectMode::Add);
    editor.beginDrag({ObjectKind::Block, 1});
    editor.dragTo(-5.0, -0.4);
    editor.endDrag();
    const auto& b = editor.level().blocks;
    EXPECT_DOUBLE_EQ(b[2].x - b[1].x, 2.0);
    // Both walls came off the slab to 0.1 m above the ground: surface snapping put the grabbed one on the ground,
    // the other kept formation.
    EXPECT_EQ(b[1].y, 1.0);
    EXPECT_EQ(b[2].y, 1.0);
}

TEST(SceneEditor, RotatesOneObjectInPlaceAndAGroupAboutItsCentre)
{
    SceneEditor editor(towerLevel());
    editor.select({ObjectKind::Block, 1});
    expectUndoable(editor, [&] { editor.rotateSelection(15.0); });
    EXPECT_EQ(editor.level().blocks[1].angleDeg, 15.0);
    EXPECT_EQ(editor.level().blocks[1].x, 19.0);
    for (int i = 0; i < 23; ++i)
        editor.rotateSelection(15.0);
    EXPECT_EQ(editor.level().blocks[1].angleDeg, 0.0) << "24 x 15 degrees is a full turn, kept in (-180, 180]";

    editor.select({ObjectKind::Block, 1});
    editor.select({ObjectKind::Block, 2}, SelectMode::Add);
    editor.select({ObjectKind::Pig, 0}, SelectMode::Add);
    expectUndoable(editor, [&] { editor.rotateSelection(90.0); });
    // Centre of the three: (20, 1.25). A quarter turn takes (19, 1.5) to (19.75, 0.25).
    EXPECT_NEAR(editor.level().blocks[1].x, 19.75, 1e-9);
    EXPECT_NEAR(editor.level().blocks[1].y, 0.25, 1e-9);
    EXPECT_EQ(editor.level().blocks[1].angleDeg, 90.0);
    EXPECT_NEAR(editor.level().pigs[0].x, 20.5, 1e-9);
    EXPECT_NEAR(editor.level().pigs[0].y, 1.25, 1e-9);
}

TEST(SceneEditor, ResizesKeepingTheBottomEdge)
{
    SceneEditor editor(towerLevel());
    const ObjectRef wall{ObjectKind::Block, 1};
    expectUndoable(editor, [&] { EXPECT_EQ(editor.resizeObject(wall, 0.5, 3.0), ""); });
    EXPECT_EQ(editor.level().blocks[1].widthM, 0.5);
    EXPECT_EQ(editor.level().blocks[1].heightM, 3.0);
    EXPECT_EQ(editor.level().blocks[1].y - 1.5, 0.5) << "the bottom stays on the slab";
    expectUndoable(editor, [&] { EXPECT_EQ(editor.resizeObject({ObjectKind::Terrain, 0}, 8.0, 4.0), ""); });
    EXPECT_EQ(editor.level().terrain[0].y, 2.0);
    // Out of range: refused with the loader's words, nothing changes.
    const LevelDef before = editor.level();
    const std::string why = editor.resizeObject(wall, 0.05, 3.0);
    EXPECT_NE(why.find("outside the sizes Box2D simulates well"), std::string::npos) << why;
    EXPECT_EQ(editor.level(), before);
    EXPECT_NE(editor.resizeObject({ObjectKind::Pig, 0}, 1.0, 1.0), "");
}

TEST(SceneEditor, ResizingACircleSetsItsDiameter)
{
    LevelDef level = emptyScene();
    level.blocks = {{BlockShape::Circle, "stone", 10.0, 0.5, 1.0, 1.0, 0.0, 0.1}};
    SceneEditor editor(level);
    expectUndoable(editor, [&] { EXPECT_EQ(editor.resizeObject({ObjectKind::Block, 0}, 2.0, 0.0), ""); });
    EXPECT_EQ(editor.level().blocks[0].widthM, 2.0);
    EXPECT_EQ(editor.level().blocks[0].heightM, 2.0);
    EXPECT_EQ(editor.level().blocks[0].y, 1.0);
}

TEST(SceneEditor, DuplicatesBesideTheOriginals)
{
    SceneEditor editor(towerLevel());
    editor.selectAll();
    expectUndoable(editor, [&] { editor.duplicateSelection(); });
    const LevelDef& level = editor.level();
    ASSERT_EQ(level.blocks.size(), 6u);
    ASSERT_EQ(level.pigs.size(), 2u);
    ASSERT_EQ(level.terrain.size(), 2u);
    // The whole scene spans x = 18.5 .. 42, 23.5 m: the copies start one span (on the 0.25 m grid) to the right.
    EXPECT_EQ(level.blocks[3].x, 20.0 + 23.5);
    EXPECT_EQ(level.blocks[3].y, 0.25);
    EXPECT_EQ(level.terrain[1].x, 40.0 + 23.5);
    EXPECT_EQ(editor.selection().size(), 5u) << "the copies are selected, not the slingshot";
}

TEST(SceneEditor, DeletesBlocksPigsAndTerrainAndUndoRestoresTheirPlaces)
{
    SceneEditor editor(towerLevel());
    editor.select({ObjectKind::Block, 0});
    editor.select({ObjectKind::Block, 2}, SelectMode::Add);
    editor.select({ObjectKind::Pig, 0}, SelectMode::Add);
    editor.select({ObjectKind::Terrain, 0}, SelectMode::Add);
    editor.select({ObjectKind::Slingshot, 0}, SelectMode::Add);
    expectUndoable(editor, [&] { editor.deleteSelection(); });
    EXPECT_EQ(editor.level().blocks.size(), 1u);
    EXPECT_EQ(editor.level().blocks[0].x, 19.0);
    EXPECT_TRUE(editor.level().pigs.empty());
    EXPECT_TRUE(editor.level().terrain.empty());
    EXPECT_EQ(editor.level().slingshot, towerLevel().slingshot) << "the slingshot is never deleted";
    editor.undo();
    EXPECT_EQ(editor.level(), towerLevel());
    EXPECT_EQ(editor.selection().size(), 4u) << "the restored objects are selected again";
}

TEST(SceneEditor, ChangesObjectPropertiesAndRefusesBadOnes)
{
    SceneEditor editor(towerLevel());
    BlockDef block = editor.level().blocks[1];
    block.material = "ice";
    block.shape = BlockShape::Triangle;
    expectUndoable(editor, [&] { EXPECT_EQ(editor.changeObject({ObjectKind::Block, 1}, block, "Material"), ""); });
    EXPECT_EQ(editor.level().blocks[1].material, "ice");
    PigDef pig = editor.level().pigs[0];
    pig.type = "helmet";
    expectUndoable(editor, [&] { EXPECT_EQ(editor.changeObject({ObjectKind::Pig, 0}, pig, "Pig type"), ""); });
    SlingshotDef sling = editor.level().slingshot;
    sling.maxForceN = 3000;
    expectUndoable(editor,
                   [&] {
                       EXPECT_EQ(editor.changeObject({ObjectKind::Slingshot, 0}, sling, "Slingshot force"), "");
                   });

    const LevelDef before = editor.level();
    block.material = "cheese";
    EXPECT_NE(editor.changeObject({ObjectKind::Block, 1}, block, "Material").find("unknown material"),
              std::string::npos);
    block.material = "wood";
    block.shape = BlockShape::HollowBox;
    block.wallM = 3.0;
    EXPECT_NE(editor.changeObject({ObjectKind::Block, 1}, block, "Wall").find("wall"), std::string::npos);
    sling.maxForceN = 0.5;
    EXPECT_NE(editor.changeObject({ObjectKind::Slingshot, 0}, sling, "Force"), "");
    EXPECT_EQ(editor.level(), before);
}

TEST(SceneEditor, SetsEveryLevelPropertyUndoably)
{
    SceneEditor editor(towerLevel());
    const auto edit = [&](auto change)
    {
        LevelDef next = editor.level();
        change(next);
        expectUndoable(editor, [&] { EXPECT_EQ(editor.setProperties(next, "Edit"), ""); });
        EXPECT_EQ(editor.level().blocks, towerLevel().blocks) << "properties never touch the objects";
    };
    edit([](LevelDef& l) { l.id = "9-9"; });
    edit([](LevelDef& l) { l.title = "Nine"; });
    edit([](LevelDef& l) { l.episode = "9"; });
    edit([](LevelDef& l) { l.lesson = "Momentum"; });
    edit([](LevelDef& l) { l.hints = {"one", "two"}; });
    edit([](LevelDef& l) { l.birds = {"yellow", "black"}; });
    edit([](LevelDef& l) { l.starScores = {1000, 2000, 3000}; });
    edit([](LevelDef& l) { l.referenceShot = ReferenceShotDef{40.0, 15.0}; });
    edit([](LevelDef& l) { l.timeLimitS = 45.0; });
    edit([](LevelDef& l) { l.environment.gravity = 1.62; });
    edit([](LevelDef& l) { l.environment.airDensity = 1.2; });
    edit([](LevelDef& l) { l.environment.windX = -5.0; });
    edit(
        [](LevelDef& l)
        {
            GustDef g;
            g.kind = GustDef::Kind::Sine;
            g.amplitudeX = 4.0;
            g.periodS = 3.0;
            l.environment.gusts = g;
        });
    edit([](LevelDef& l) { l.materials = {{"wood", 600.0, 0.3, std::nullopt, 80.0}}; });
    edit(
        [](LevelDef& l)
        {
            l.customBird = CustomBirdDef{0.145, 0.074, 0.35};
            l.birds.push_back(kCustomBirdName);
        });
    edit([](LevelDef& l) { l.sandbox = true; });
    edit([](LevelDef& l) { l.groundY = -1.0; });
    edit([](LevelDef& l) { l.slingshot.y = 3.0; });
}

TEST(SceneEditor, RefusesPropertiesTheLoaderWouldReject)
{
    SceneEditor editor(towerLevel());
    const LevelDef before = editor.level();
    const auto refused = [&](auto change, const std::string& expected)
    {
        LevelDef next = editor.level();
        change(next);
        const std::string why = editor.setProperties(next, "Edit");
        EXPECT_NE(why.find(expected), std::string::npos) << why;
        EXPECT_EQ(editor.level(), before);
    };
    refused([](LevelDef& l) { l.title = ""; }, "/title");
    refused([](LevelDef& l) { l.id = ""; }, "/id");
    refused([](LevelDef& l) { l.birds.clear(); }, "/birds");
    refused([](LevelDef& l) { l.birds = {"custom"}; }, "defines no custom bird");
    refused([](LevelDef& l) { l.starScores = {3000, 2000, 1000}; }, "must not decrease");
    refused([](LevelDef& l) { l.environment.gravity = 150.0; }, "/environment/gravity");
    refused([](LevelDef& l) { l.environment.windX = 3.0; }, "acts only through air drag");
    refused([](LevelDef& l) { l.customBird = CustomBirdDef{9000.0, 0.5, 0.47}; }, "/custom_bird/mass_kg");
    refused(
        [](LevelDef& l) {
            l.materials = {{"wood", std::nullopt, std::nullopt, 1.5, std::nullopt}};
        },
        "/materials/wood/restitution");
    refused([](LevelDef& l) { l.timeLimitS = 0.5; }, "/time_limit_s");
    EXPECT_FALSE(editor.canUndo());
}

TEST(SceneEditor, ASliderDragIsOneUndoStep)
{
    SceneEditor editor(towerLevel());
    LevelDef next = editor.level();
    for (int i = 1; i <= 20; ++i)
    {
        next.environment.gravity = 9.81 + i * 0.5;
        EXPECT_EQ(editor.setProperties(next, "Gravity", "gravity"), "");
    }
    editor.endGesture();
    next.environment.gravity = 1.62;
    editor.setProperties(next, "Gravity", "gravity");
    editor.undo();
    EXPECT_DOUBLE_EQ(editor.level().environment.gravity, 19.81);
    editor.undo();
    EXPECT_EQ(editor.level().environment.gravity, 9.81);
    EXPECT_FALSE(editor.canUndo());
}

TEST(SceneEditor, SelectionModesRectanglesAndPicking)
{
    SceneEditor editor(towerLevel());
    editor.select({ObjectKind::Block, 0});
    editor.select({ObjectKind::Block, 1}, SelectMode::Add);
    editor.select({ObjectKind::Block, 0}, SelectMode::Toggle);
    EXPECT_EQ(editor.selection(), (std::vector<ObjectRef>{{ObjectKind::Block, 1}}));
    editor.selectInRect(18.0, 0.0, 22.0, 5.0);
    EXPECT_EQ(editor.selection().size(), 4u) << "slab, two walls and the pig";
    editor.selectAll();
    EXPECT_EQ(editor.selection().size(), 6u);
    editor.clearSelection();
    EXPECT_TRUE(editor.selection().empty());
    // The pig is drawn over the slab: a click on it picks the pig.
    EXPECT_EQ(editor.objectAt(20.0, 0.75), (ObjectRef{ObjectKind::Pig, 0}));
    EXPECT_EQ(editor.objectAt(18.7, 0.25), (ObjectRef{ObjectKind::Block, 0}));
    EXPECT_EQ(editor.objectAt(40.0, 1.0), (ObjectRef{ObjectKind::Terrain, 0}));
    EXPECT_EQ(editor.objectAt(0.0, 1.0), (ObjectRef{ObjectKind::Slingshot, 0}));
    EXPECT_EQ(editor.objectAt(10.0, 10.0), std::nullopt);
}

TEST(SceneEditor, DirtyUntilSavedOrUndoneBackToTheSavedState)
{
    SceneEditor editor(towerLevel());
    EXPECT_FALSE(editor.dirty());
    editor.select({ObjectKind::Pig, 0});
    editor.moveSelection(1.0, 0.0);
    EXPECT_TRUE(editor.dirty());
    editor.undo();
    EXPECT_FALSE(editor.dirty());
    editor.redo();
    editor.markSaved();
    EXPECT_FALSE(editor.dirty());
    editor.undo();
    EXPECT_TRUE(editor.dirty());
    editor.redo();
    EXPECT_FALSE(editor.dirty());
}

TEST(SceneEditor, RandomEditsUndoAllTheWayBackAndRedoAllTheWayForward)
{
    // Any sequence of edits must be undoable to the start and redoable to the end, bit for bit.
    std::mt19937 random(7);
    SceneEditor editor(towerLevel());
    std::vector<LevelDef> states{editor.level()};
    const auto pick = [&](int n)
    {
        return std::uniform_int_distribution<int>(0, n - 1)(random);
    };
    for (int i = 0; i < 300; ++i)
    {
        const auto revisionBefore = editor.revision();
        switch (pick(8))
        {
        case 0:
            editor.place(BlockDef{static_cast<BlockShape>(pick(4)), Catalog::builtin().materials()[pick(3)].name,
                                  pick(60) - 10.0, pick(10) + 0.5, 0.5 + pick(4) * 0.5, 0.5 + pick(4) * 0.5, 0.0, 0.1});
            break;
        case 1:
            editor.place(PigDef{Catalog::builtin().pigs()[pick(4)].name, pick(60) - 10.0, pick(8) + 0.5});
            break;
        case 2:
            editor.selectAll();
            if (!editor.selection().empty())
                editor.select(editor.selection()[pick(static_cast<int>(editor.selection().size()))]);
            editor.moveSelection(pick(5) * 0.1 - 0.2, pick(5) * 0.1);
            break;
        case 3:
            editor.rotateSelection(15.0 * (pick(5) - 2));
            break;
        case 4:
            editor.duplicateSelection();
            break;
        case 5:
            editor.deleteSelection();
            break;
        case 6:
        {
            LevelDef next = editor.level();
            next.environment.gravity = pick(100);
            editor.setProperties(next, "Gravity");
            break;
        }
        default:
            if (!editor.selection().empty())
                editor.resizeObject(editor.selection()[0], 0.25 * (1 + pick(8)), 0.25 * (1 + pick(8)));
        }
        editor.endGesture();
        if (editor.revision() != revisionBefore)
            states.push_back(editor.level());
    }
    for (std::size_t i = states.size() - 1; i-- > 0;)
    {
        ASSERT_TRUE(editor.undo());
        ASSERT_EQ(editor.level(), states[i]) << "undo step " << i;
    }
    EXPECT_FALSE(editor.undo());
    for (std::size_t i = 1; i < states.size(); ++i)
    {
        ASSERT_TRUE(editor.redo());
        ASSERT_EQ(editor.level(), states[i]) << "redo step " << i;
    }
    EXPECT_FALSE(editor.redo());
}

} // namespace
} // namespace abalike

namespace abalike
{
namespace
{

TEST(SceneEditorMirror, MirrorsPositionsAnglesTrianglesAndPolygonsInOneUndoStep)
{
    LevelDef level = emptyScene();
    level.blocks.push_back({BlockShape::Box, "wood", 20.0, 1.0, 0.25, 2.0, 10.0, 0.1});
    level.blocks.push_back({BlockShape::Triangle, "stone", 22.0, 0.5, 2.0, 1.0, 0.0, 0.1});
    level.terrain.push_back({0.0, 0.0, 0.0, 0.0, 0.0, {{30.0, 0.0}, {34.0, 0.0}, {30.0, 2.0}}});
    level.terrain.back().x = 32.0;
    level.terrain.back().y = 1.0;
    level.terrain.back().widthM = 4.0;
    level.terrain.back().heightM = 2.0;
    SceneEditor editor(level);
    editor.selectAll();
    editor.mirrorSelection();
    const LevelDef& m = editor.level();
    // The selection spans x = 19.7 .. 34 (the tilted post reaches 19.7): the axis is at 26.85.
    const double axis = 0.5 * (34.0 + (20.0 - 0.5 * (0.25 * std::cos(10 * 3.141592653589793 / 180) +
                                                     2.0 * std::sin(10 * 3.141592653589793 / 180))));
    EXPECT_NEAR(m.blocks[0].x, 2.0 * axis - 20.0, 1e-9);
    EXPECT_NEAR(m.blocks[0].angleDeg, -10.0, 1e-9);
    // The triangle's right angle moves from the bottom left to the bottom right: legs swapped, a quarter turn.
    EXPECT_EQ(m.blocks[1].widthM, 1.0);
    EXPECT_EQ(m.blocks[1].heightM, 2.0);
    EXPECT_NEAR(m.blocks[1].angleDeg, 90.0, 1e-9);
    // The polygon's points mirror about its own new centre.
    ASSERT_EQ(m.terrain[0].points.size(), 3u);
    EXPECT_NEAR(m.terrain[0].points[0].x - m.terrain[0].points[1].x, 4.0, 1e-9);
    EXPECT_NEAR(m.terrain[0].points[2].x, m.terrain[0].points[0].x, 1e-9);
    editor.undo();
    EXPECT_EQ(editor.level().blocks, level.blocks);
    EXPECT_EQ(editor.level().terrain, level.terrain);
}

TEST(SceneEditorMirror, ASquareBlockMirroredAboutItsOwnCentreKeepsAPlainZero)
{
    // A square box at x = 0: mirrored, -0 for its angle and its x would read "-0.0" in the panels.
    LevelDef level = emptyScene();
    level.blocks.push_back({BlockShape::Box, "wood", 0.0, 0.5, 1.0, 1.0, 0.0, 0.1});
    SceneEditor editor(level);
    editor.selectAll();
    editor.mirrorSelection();
    EXPECT_EQ(editor.level().blocks[0].angleDeg, 0.0);
    EXPECT_FALSE(std::signbit(editor.level().blocks[0].angleDeg));
    EXPECT_FALSE(std::signbit(editor.level().blocks[0].x));
}

} // namespace
} // namespace abalike
