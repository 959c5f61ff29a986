#include <abalike/edit/SceneEditor.hpp>
#include <abalike/edit/Snapping.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/world/RestCheck.hpp>

#include <gtest/gtest.h>

namespace abalike
{
namespace
{

LevelDef slabScene()
{
    LevelDef level = emptyScene();
    level.blocks = {{BlockShape::Box, "stone", 10.0, 0.25, 3.0, 0.5, 0.0, 0.1}};
    return level;
}

SnapSettings surfacesOnly()
{
    SnapSettings s;
    s.grid = false;
    return s;
}

TEST(Snapping, ABlockDroppedNearAnotherRestsExactlyOnIt)
{
    const LevelDef level = slabScene();
    // 7 cm above the slab's top and off-grid: it lands with its bottom exactly on the top.
    const BlockDef wood{BlockShape::Box, "wood", 9.37, 1.57, 0.25, 2.0, 0.0, 0.1};
    const SnapResult at = snapObject(level, Catalog::builtin(), wood, {}, surfacesOnly());
    EXPECT_EQ(at.x, 9.37);
    EXPECT_EQ(at.y, 1.5);
    EXPECT_EQ(at.y - 1.0, level.blocks[0].y + 0.25) << "bottom on the top, to the bit";
    EXPECT_EQ(at.restsOn, (ObjectRef{ObjectKind::Block, 0}));
    EXPECT_FALSE(at.onGround);
    // From slightly inside it is lifted out the same way.
    const SnapResult in = snapObject(level, Catalog::builtin(), withCentre(wood, 9.37, 1.41), {}, surfacesOnly());
    EXPECT_EQ(in.y, 1.5);
}

TEST(Snapping, ASnappedStackPassesTheRestTest)
{
    // A tower built by dropping blocks roughly where they go, as a designer does with the mouse.
    SceneEditor editor(emptyScene());
    editor.snapSettings().grid = false;
    editor.place(BlockDef{BlockShape::Box, "stone", 20.0, 0.4, 3.0, 0.5, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Box, "wood", 19.0, 1.62, 0.25, 2.0, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Box, "wood", 21.0, 1.55, 0.25, 2.0, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Box, "wood", 20.0, 2.75, 2.6, 0.25, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Box, "ice", 20.0, 3.4, 1.0, 1.0, 0.0, 0.1});
    editor.place(BlockDef{BlockShape::Circle, "stone", 20.0, 4.2, 0.6, 0.6, 0.0, 0.1});
    editor.place(PigDef{"small", 20.0, 0.9});
    const LevelDef& level = editor.level();
    EXPECT_EQ(level.blocks[0].y, 0.25);
    EXPECT_EQ(level.blocks[1].y, 1.5);
    EXPECT_EQ(level.blocks[2].y, 1.5);
    EXPECT_EQ(level.blocks[3].y, 2.625);
    EXPECT_EQ(level.blocks[4].y, 3.25);
    EXPECT_EQ(level.blocks[5].y, 4.05);
    EXPECT_EQ(level.pigs[0].y, 0.75);
    EXPECT_TRUE(checkLevelGeometry(level, Catalog::builtin()).empty());
    const RestReport rest = checkRest(level);
    EXPECT_TRUE(rest.passed()) << rest.summary();
}

TEST(Snapping, EveryShapeRestsOnEveryShapeBelowIt)
{
    // Blocks of every shape dropped onto a box, and a box onto every shape with a flat top.
    for (const BlockShape shape : {BlockShape::Box, BlockShape::Circle, BlockShape::Triangle, BlockShape::HollowBox})
    {
        SCOPED_TRACE(static_cast<int>(shape));
        LevelDef level = slabScene();
        const BlockDef block{shape, "wood", 10.0, 1.1, 1.0, 1.0, 0.0, 0.1};
        const SnapResult at = snapObject(level, Catalog::builtin(), block, {}, surfacesOnly());
        EXPECT_EQ(at.y, 1.0);
        level.blocks.push_back(std::get<BlockDef>(withCentre(block, at.x, at.y)));
        if (shape == BlockShape::Circle || shape == BlockShape::Triangle)
            continue; // nothing rests level on a ball or a slope
        const BlockDef top{BlockShape::Box, "ice", 10.0, 1.9, 0.5, 0.5, 0.0, 0.1};
        const SnapResult onTop = snapObject(level, Catalog::builtin(), top, {}, surfacesOnly());
        EXPECT_EQ(onTop.y, 1.75);
        level.blocks.push_back(std::get<BlockDef>(withCentre(top, onTop.x, onTop.y)));
        level.pigs = {{"small", 14.0, 0.25}};
        EXPECT_TRUE(checkRest(level).passed()) << checkRest(level).summary();
    }
}

TEST(Snapping, APigRestsOnABlockAndTheGround)
{
    const LevelDef level = slabScene();
    for (const PigType& type : Catalog::builtin().pigs())
    {
        const SnapResult on = snapObject(level, Catalog::builtin(), PigDef{type.name, 10.3, 0.9}, {}, surfacesOnly());
        EXPECT_DOUBLE_EQ(on.y, 0.5 + type.radiusM) << type.name;
        const SnapResult ground =
            snapObject(level, Catalog::builtin(), PigDef{type.name, 3.0, type.radiusM + 0.1}, {}, surfacesOnly());
        EXPECT_DOUBLE_EQ(ground.y, type.radiusM) << type.name;
        EXPECT_TRUE(ground.onGround);
    }
}

TEST(Snapping, ABlockIsPushedAgainstANeighbourBesideIt)
{
    const LevelDef level = slabScene();
    // 5 cm right of the slab (whose right face is at x = 11.5), 5 cm above the ground: it moves left to touch the
    // slab's side and down onto the ground.
    const BlockDef box{BlockShape::Box, "ice", 12.05, 0.55, 1.0, 1.0, 0.0, 0.1};
    const SnapResult at = snapObject(level, Catalog::builtin(), box, {}, surfacesOnly());
    EXPECT_EQ(at.x, 12.0);
    EXPECT_EQ(at.y, 0.5);
    EXPECT_EQ(at.touchesSide, (ObjectRef{ObjectKind::Block, 0}));
    EXPECT_TRUE(at.onGround);
}

TEST(Snapping, NothingWithinReachLeavesOnlyTheGrid)
{
    const LevelDef level = slabScene();
    SnapSettings settings;
    settings.gridM = 0.5;
    const BlockDef box{BlockShape::Box, "ice", 30.3, 5.2, 1.0, 1.0, 0.0, 0.1};
    const SnapResult at = snapObject(level, Catalog::builtin(), box, {}, settings);
    // Lower-left corner (29.8, 4.7) to the grid: (30, 4.5).
    EXPECT_EQ(at.x, 30.5);
    EXPECT_EQ(at.y, 5.0);
    EXPECT_FALSE(at.restsOn);
    EXPECT_FALSE(at.onGround);
    settings.surfaces = false;
    settings.grid = false;
    const SnapResult none = snapObject(level, Catalog::builtin(), withCentre(box, 10.01, 0.77), {}, settings);
    EXPECT_EQ(none.x, 10.01);
    EXPECT_EQ(none.y, 0.77);
}

TEST(Snapping, WithTheGridOnABodyAGridStepAboveASurfaceLandsOnIt)
{
    // The editor's settings: a 25 cm grid and a 10 cm surface pull. A crate put down a little above the slab has its
    // bottom rounded up to the grid line 25 cm above it; it still lands (it was saved floating before).
    const LevelDef level = slabScene();
    SnapSettings settings;
    settings.gridM = 0.25;
    settings.surfaceReachM = 0.1;
    const BlockDef crate{BlockShape::Box, "tnt", 10.0, 0.97, 0.5, 0.5, 0.0, 0.1};
    const SnapResult at = snapObject(level, Catalog::builtin(), crate, {}, settings);
    EXPECT_EQ(at.y, 0.75);
    ASSERT_TRUE(at.restsOn);
    EXPECT_EQ(*at.restsOn, (ObjectRef{ObjectKind::Block, 0}));
    // Two grid steps up it is put where it was meant: in the air, for the checks to mark.
    const SnapResult high = snapObject(level, Catalog::builtin(), withCentre(crate, 10.0, 1.47), {}, settings);
    EXPECT_EQ(high.y, 1.5);
    EXPECT_FALSE(high.restsOn);
}

TEST(Snapping, ABlockOrPigPutBelowTheGroundComesUpOntoItTerrainMaySink)
{
    const LevelDef level = emptyScene();
    const SnapResult block =
        snapObject(level, Catalog::builtin(), BlockDef{BlockShape::Box, "wood", 5.0, -3.0, 1.0, 1.0, 0.0, 0.1}, {},
                   surfacesOnly());
    EXPECT_EQ(block.y, 0.5);
    EXPECT_TRUE(block.onGround);
    const SnapResult pig = snapObject(level, Catalog::builtin(), PigDef{"large", 5.0, -2.0}, {}, surfacesOnly());
    EXPECT_EQ(pig.y, 0.5);
    const SnapResult hill =
        snapObject(level, Catalog::builtin(), TerrainDef{5.0, -3.0, 10.0, 4.0, 0.0, {}}, {}, surfacesOnly());
    EXPECT_EQ(hill.y, -3.0);
}

TEST(Snapping, ObjectsBeingMovedAreNoSurface)
{
    const LevelDef level = slabScene();
    const BlockDef slabMovedUp{BlockShape::Box, "stone", 10.0, 0.3, 3.0, 0.5, 0.0, 0.1};
    const SnapResult at = snapObject(level, Catalog::builtin(), slabMovedUp, {{ObjectKind::Block, 0}}, surfacesOnly());
    EXPECT_EQ(at.y, 0.25);
    EXPECT_TRUE(at.onGround);
}

TEST(Snapping, CleansArithmeticNoise)
{
    EXPECT_EQ(cleanMetres(0.1 + 0.2), 0.3);
    EXPECT_EQ(cleanMetres(-1.0000000000000002), -1.0);
    EXPECT_EQ(snapAngle(22.0, 15.0), 15.0);
    EXPECT_EQ(snapAngle(-37.6, 15.0), -45.0);
}

} // namespace
} // namespace abalike
