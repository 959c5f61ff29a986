#include <abalike/edit/SceneEditor.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>

#include <gtest/gtest.h>

namespace abalike
{
namespace
{

BlockDef box(double x, double y, double w, double h, const char* material = "wood")
{
    BlockDef block;
    block.material = material;
    block.x = x;
    block.y = y;
    block.widthM = w;
    block.heightM = h;
    return block;
}

TerrainDef hill()
{
    TerrainDef terrain;
    terrain.points = {{30.0, 0.0}, {36.0, 0.0}, {34.0, 2.0}, {32.0, 2.0}};
    terrain.x = 33.0;
    terrain.y = 1.0;
    terrain.widthM = 6.0;
    terrain.heightM = 2.0;
    return terrain;
}

TEST(SceneEditorAlign, LinesUpEdgesAndCentresInOneUndoStep)
{
    LevelDef level = emptyScene();
    level.blocks = {box(20.0, 1.0, 0.5, 2.0), box(23.0, 2.0, 1.0, 1.0), box(27.0, 0.5, 2.0, 1.0)};
    SceneEditor editor(level);
    editor.selectAll(); // the slingshot too: it never moves with a group
    editor.alignSelection(Align::Bottom);
    EXPECT_DOUBLE_EQ(editor.level().blocks[0].y, 1.0); // bottom 0
    EXPECT_DOUBLE_EQ(editor.level().blocks[1].y, 0.5);
    EXPECT_DOUBLE_EQ(editor.level().blocks[2].y, 0.5);
    EXPECT_EQ(editor.level().slingshot, level.slingshot);
    editor.alignSelection(Align::Left);
    for (const BlockDef& b : editor.level().blocks)
        EXPECT_DOUBLE_EQ(b.x - 0.5 * b.widthM, 19.75);
    editor.alignSelection(Align::CentreX);
    for (const BlockDef& b : editor.level().blocks)
        EXPECT_DOUBLE_EQ(b.x, 20.75); // the selection spans 19.75 .. 21.75
    editor.undo();
    editor.undo();
    editor.undo();
    EXPECT_EQ(editor.level().blocks, level.blocks);
}

TEST(SceneEditorDistribute, MakesEqualGapsBetweenBoundingBoxes)
{
    LevelDef level = emptyScene();
    // Widths 1, 2, 0.5, 1; outermost edges at 19.5 and 40.5: 21 m of which 4.5 is blocks, gaps of 5.5 m.
    level.blocks = {box(20.0, 0.5, 1.0, 1.0), box(22.0, 0.5, 2.0, 1.0), box(38.0, 0.5, 0.5, 1.0),
                    box(40.0, 0.5, 1.0, 1.0)};
    SceneEditor editor(level);
    editor.selectAll();
    editor.distributeSelection(true);
    const auto& b = editor.level().blocks;
    const double gap = 5.5;
    EXPECT_DOUBLE_EQ(b[0].x, 20.0);
    EXPECT_DOUBLE_EQ(b[3].x, 40.0);
    EXPECT_NEAR(b[1].x - 1.0 - (b[0].x + 0.5), gap, 1e-6);
    EXPECT_NEAR(b[2].x - 0.25 - (b[1].x + 1.0), gap, 1e-6);
    EXPECT_NEAR(b[3].x - 0.5 - (b[2].x + 0.25), gap, 1e-6);
    EXPECT_EQ(editor.selection().size(), 5u); // the group (and the slingshot) stay selected
    editor.undo();
    EXPECT_EQ(editor.level().blocks, level.blocks);
}

TEST(SceneEditorMultiEdit, ChangesAFieldOnEveryObjectOrNoneWithTheReason)
{
    LevelDef level = emptyScene();
    level.blocks = {box(20.0, 1.0, 0.5, 2.0), box(23.0, 0.5, 1.0, 1.0)};
    SceneEditor editor(level);
    std::vector<ObjectDef> stone;
    for (BlockDef b : level.blocks)
    {
        b.material = "stone";
        stone.emplace_back(b);
    }
    const std::vector<ObjectRef> refs{{ObjectKind::Block, 0}, {ObjectKind::Block, 1}};
    EXPECT_EQ(editor.changeObjects(refs, stone, "Material"), "");
    EXPECT_EQ(editor.level().blocks[0].material, "stone");
    EXPECT_EQ(editor.level().blocks[1].material, "stone");
    editor.undo(); // one step
    EXPECT_EQ(editor.level().blocks, level.blocks);
    std::vector<ObjectDef> tooThin = stone;
    std::get<BlockDef>(tooThin[1]).widthM = 0.01;
    const std::string why = editor.changeObjects(refs, tooThin, "Width");
    EXPECT_NE(why.find("block 1"), std::string::npos) << why;
    EXPECT_EQ(editor.level().blocks, level.blocks);
}

TEST(SceneEditorClipboard, CopyAndPasteAcrossScenesAsLevelJson)
{
    LevelDef first = emptyScene();
    first.blocks = {box(20.0, 1.0, 0.5, 2.0), box(21.0, 1.0, 0.5, 2.0, "ice"), box(20.5, 2.1, 1.5, 0.2)};
    first.pigs.push_back({"small", 20.5, 0.25});
    first.terrain.push_back(hill());
    SceneEditor from(first);
    from.selectAll();
    const std::string text = from.copySelection();
    // It is a level file in its own right: a sandbox scene any editor or `abalike check` reads.
    const LevelDef asLevel = parseLevelForEditing(text, "clip.json", Catalog::builtin()).level;
    EXPECT_TRUE(asLevel.sandbox);
    EXPECT_EQ(asLevel.blocks, first.blocks);

    LevelDef second = emptyScene();
    second.blocks = {box(10.0, 0.5, 1.0, 1.0)};
    SceneEditor to(second);
    // Pasted with its bounding box's bottom centre at (50, 0): the hill's bottom is the group's bottom.
    EXPECT_EQ(to.paste(text, Vec2{50.0, 0.0}), "");
    const LevelDef& pasted = to.level();
    ASSERT_EQ(pasted.blocks.size(), 4u);
    ASSERT_EQ(pasted.pigs.size(), 1u);
    ASSERT_EQ(pasted.terrain.size(), 1u);
    // The group spans x = 19.75 .. 36 in the first scene: centre 27.875, so 22.125 to the pointer, moved by whole
    // 0.25 m grid steps (22.25): bodies on the grid stay on it. Heights kept.
    EXPECT_DOUBLE_EQ(pasted.blocks[1].x, 20.0 + 22.25);
    EXPECT_DOUBLE_EQ(pasted.blocks[1].y, 1.0);
    EXPECT_DOUBLE_EQ(pasted.terrain[0].points[0].x, 30.0 + 22.25);
    EXPECT_EQ(to.selection().size(), 5u);
    to.undo();
    EXPECT_EQ(to.level().blocks, second.blocks);

    EXPECT_EQ(to.paste("   ", std::nullopt), "the clipboard is empty");
    EXPECT_NE(to.paste("hello", std::nullopt).find("the clipboard holds no level JSON"), std::string::npos);
    EXPECT_EQ(to.level().blocks, second.blocks);
}

TEST(SceneEditorClipboard, APastedGroupSettlesOntoTheSurfaceUnderIt)
{
    LevelDef scene = emptyScene();
    scene.blocks = {box(30.0, 0.5, 4.0, 1.0, "stone")}; // a plinth with its top at y = 1
    SceneEditor editor(scene);
    LevelDef tower = emptyScene();
    tower.blocks = {box(0.0, 1.0, 0.5, 2.0), box(1.5, 1.0, 0.5, 2.0), box(0.75, 2.1, 2.0, 0.2)};
    // Dropped 5 cm above the plinth (within snap reach): the posts land on it, the roof stays on the posts.
    ASSERT_EQ(editor.insertBodies(tower, Vec2{30.0, 1.05}, "Insert tower"), "");
    const auto& b = editor.level().blocks;
    ASSERT_EQ(b.size(), 4u);
    EXPECT_NEAR(b[1].y, 2.0, 1e-9);
    EXPECT_NEAR(b[2].y, 2.0, 1e-9);
    EXPECT_NEAR(b[3].y, 3.1, 1e-9);
    EXPECT_NEAR(b[1].x, 30.0 - 0.75, 1e-9);
    // Never under the ground: a drop below it comes up onto it.
    ASSERT_EQ(editor.insertBodies(tower, Vec2{10.0, -3.0}, "Insert tower"), "");
    EXPECT_NEAR(editor.level().blocks[4].y, 1.0, 1e-9);
}

TEST(SceneEditorClipboard, APasteLandsOnTheGridAndFallsOntoTheSurfaceFromAnyHeight)
{
    // The designer's case: a plank pasted with the pointer at x = 14.771127701, 24 cm and then 3 m above a plinth.
    LevelDef scene = emptyScene();
    scene.blocks = {box(15.0, 0.5, 4.0, 1.0, "stone")}; // top at y = 1
    SceneEditor editor(scene);
    editor.selectAll();
    LevelDef plank = emptyScene();
    plank.blocks = {box(0.0, 0.1, 2.0, 0.2)};
    for (const double height : {1.24, 4.0})
    {
        SCOPED_TRACE(height);
        ASSERT_EQ(editor.insertBodies(plank, Vec2{14.771127701, height}, "Paste"), "");
        const BlockDef& pasted = editor.level().blocks.back();
        EXPECT_DOUBLE_EQ(pasted.x, 14.75) << "on the 0.25 m grid";
        EXPECT_NEAR(pasted.y, 1.1, 1e-9) << "resting on the plinth";
        editor.undo();
    }
    // With surfaces off it stays where it was put (on the grid's heights too).
    editor.snapSettings().surfaces = false;
    ASSERT_EQ(editor.insertBodies(plank, Vec2{14.771127701, 3.9}, "Paste"), "");
    EXPECT_NEAR(editor.level().blocks.back().y, 4.0 + 0.1, 1e-9);
}

TEST(SceneEditorClipboard, TheOutlineBeforeADropIsWhereTheDropLands)
{
    // The Drop tool outlines placedBodies under the pointer; it once moved the group without the grid or the
    // settling, a grid step (and a fall onto the plinth) away from where the click put it.
    LevelDef scene = emptyScene();
    scene.blocks = {box(15.0, 0.5, 4.0, 1.0, "stone")}; // top at y = 1
    SceneEditor editor(scene);
    LevelDef frame = emptyScene();
    frame.blocks = {box(0.0, 1.0, 0.5, 2.0), box(1.5, 1.0, 0.5, 2.0), box(0.75, 2.1, 2.0, 0.2)};
    frame.pigs = {PigDef{"small", 0.75, 0.25}};
    const Vec2 at{14.771127701, 2.63};
    const std::vector<ObjectDef> outline = editor.placedBodies(frame, at);
    ASSERT_EQ(outline.size(), 4u);
    EXPECT_EQ(editor.level().blocks.size(), 1u) << "outlining adds nothing";
    ASSERT_EQ(editor.insertBodies(frame, at, "Drop"), "");
    const LevelDef& dropped = editor.level();
    ASSERT_EQ(dropped.blocks.size(), 4u);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(std::get<BlockDef>(outline[i]), dropped.blocks[1 + i]) << i;
    EXPECT_EQ(std::get<PigDef>(outline[3]), dropped.pigs.back());
    // On the 0.25 m grid across and standing on the plinth (its posts' bottoms at y = 1).
    EXPECT_NEAR(dropped.blocks[1].x, 14.0, 1e-9);
    EXPECT_NEAR(dropped.blocks[1].y, 2.0, 1e-9);
    EXPECT_TRUE(editor.placedBodies(emptyScene(), at).empty());
}

TEST(SceneEditorVertices, MovesAddsAndRemovesCornersAndRefusesACrossing)
{
    LevelDef level = emptyScene();
    level.terrain.push_back(hill());
    SceneEditor editor(level);
    EXPECT_EQ(editor.moveVertex(0, 2, 35.0, 3.0), "");
    EXPECT_EQ(editor.level().terrain[0].points[2], (Vec2{35.0, 3.0}));
    EXPECT_DOUBLE_EQ(editor.level().terrain[0].heightM, 3.0); // its box follows
    EXPECT_DOUBLE_EQ(editor.level().terrain[0].y, 1.5);
    EXPECT_EQ(editor.insertVertex(0, 0), ""); // the middle of the bottom edge
    ASSERT_EQ(editor.level().terrain[0].points.size(), 5u);
    EXPECT_EQ(editor.level().terrain[0].points[1], (Vec2{33.0, 0.0}));
    EXPECT_EQ(editor.removeVertex(0, 1), "");
    EXPECT_EQ(editor.level().terrain[0].points.size(), 4u);
    // Dragging the top-left corner past the right side makes the outline cross itself: refused, nothing changes.
    const LevelDef before = editor.level();
    const std::string why = editor.moveVertex(0, 3, 37.0, 1.0);
    EXPECT_NE(why.find("crosses itself"), std::string::npos) << why;
    EXPECT_EQ(editor.level(), before);
    EXPECT_EQ(editor.removeVertex(0, 0), "");
    EXPECT_EQ(editor.removeVertex(0, 0), "a polygon keeps at least 3 corners");
    EXPECT_EQ(editor.moveVertex(0, 9, 1.0, 1.0), "no such corner");
    while (editor.canUndo())
        editor.undo();
    EXPECT_EQ(editor.level().terrain, level.terrain);
}

TEST(SceneEditorVertices, AConcaveHillIsPickedByItsOwnOutlineNotItsHull)
{
    LevelDef level = emptyScene();
    TerrainDef valley;
    valley.points = {{20.0, 0.0}, {30.0, 0.0}, {30.0, 4.0}, {25.0, 1.0}, {20.0, 4.0}}; // a V-shaped dip
    valley.x = 25.0;
    valley.y = 2.0;
    valley.widthM = 10.0;
    valley.heightM = 4.0;
    level.terrain.push_back(valley);
    SceneEditor editor(level);
    EXPECT_EQ(editor.objectAt(21.0, 3.0), (ObjectRef{ObjectKind::Terrain, 0}));
    EXPECT_EQ(editor.objectAt(25.0, 0.5), (ObjectRef{ObjectKind::Terrain, 0}));
    EXPECT_EQ(editor.objectAt(25.0, 3.0), std::nullopt);            // in the dip: inside the hull, outside the hill
    EXPECT_EQ(editor.outline({ObjectKind::Terrain, 0}).size(), 5u); // drawn by its own five corners
}

} // namespace
} // namespace abalike
