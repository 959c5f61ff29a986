#include <abalike/design/PartVariation.hpp>

#include <abalike/level/LevelIO.hpp>
#include <abalike/world/RestCheck.hpp>

#include <algorithm>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

LevelDef part(const std::string& name)
{
    return loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/parts/" + name + ".json", Catalog::builtin());
}

PartVariation stretched(double s)
{
    PartVariation v;
    v.stretch = s;
    return v;
}

TEST(PartVariation, AStretchSpreadsThePostsAndWidensThePlankSoTheFrameStillStands)
{
    const LevelDef frame = varyPart(part("frame"), stretched(1.5), Catalog::builtin());
    ASSERT_EQ(frame.blocks.size(), 3u);
    EXPECT_DOUBLE_EQ(frame.blocks[0].x, -1.5);
    EXPECT_DOUBLE_EQ(frame.blocks[1].x, 1.5);
    EXPECT_DOUBLE_EQ(frame.blocks[0].widthM, 0.25) << "posts keep their width";
    EXPECT_DOUBLE_EQ(frame.blocks[0].heightM, 2.0);
    EXPECT_DOUBLE_EQ(frame.blocks[2].widthM, 3.9) << "the plank reaches over both posts as before";
    EXPECT_DOUBLE_EQ(frame.pigs[0].x, 0.0);
    EXPECT_TRUE(checkRest(frame).passed());

    // A pyramid of squares widens as a whole: each block stays on the two below it.
    const LevelDef pyramid = varyPart(part("pyramid-3"), stretched(1.25), Catalog::builtin());
    EXPECT_DOUBLE_EQ(pyramid.blocks[0].x, -1.0);
    EXPECT_DOUBLE_EQ(pyramid.blocks[0].widthM, 1.0);
    EXPECT_DOUBLE_EQ(pyramid.blocks[0].heightM, 0.8);
    EXPECT_TRUE(checkRest(pyramid).passed());
}

TEST(PartVariation, AMirroredRoofIsTheSameRoofAndAMirroredDoubleFrameSwapsItsPigs)
{
    PartVariation mirror;
    mirror.mirror = true;
    const LevelDef roofed = part("roofed-frame");
    const LevelDef mirrored = varyPart(roofed, mirror, Catalog::builtin());
    // The left roof half (a quarter turn) lands where the right half was, unturned, and the other way round.
    ASSERT_EQ(roofed.blocks[3].shape, BlockShape::Triangle);
    EXPECT_DOUBLE_EQ(roofed.blocks[3].x, -0.65);
    EXPECT_DOUBLE_EQ(roofed.blocks[3].angleDeg, 90.0);
    EXPECT_DOUBLE_EQ(mirrored.blocks[3].x, 0.65);
    EXPECT_DOUBLE_EQ(mirrored.blocks[3].angleDeg, 0.0);
    EXPECT_DOUBLE_EQ(mirrored.blocks[4].x, -0.65);
    EXPECT_DOUBLE_EQ(mirrored.blocks[4].angleDeg, 90.0);
    EXPECT_TRUE(checkRest(mirrored).passed());

    const LevelDef doubleFrame = part("double-frame");
    ASSERT_EQ(doubleFrame.pigs.size(), 2u);
    EXPECT_EQ(doubleFrame.pigs[0].type, "small");
    EXPECT_DOUBLE_EQ(doubleFrame.pigs[0].x, -1.0);
    const LevelDef swapped = varyPart(doubleFrame, mirror, Catalog::builtin());
    EXPECT_DOUBLE_EQ(swapped.pigs[0].x, 1.0);
    EXPECT_DOUBLE_EQ(swapped.pigs[1].x, -1.0);
}

TEST(PartVariation, APigChangesSizeOnWhatItRestsOnAndOnlyWhereItFits)
{
    // The cage's small pig stands on the cage's floor (its bottom at 0.1 m): a medium pig stands there too.
    PartVariation medium;
    medium.pigTypes = {"medium"};
    const LevelDef cage = varyPart(part("cage"), medium, Catalog::builtin());
    EXPECT_EQ(cage.pigs[0].type, "medium");
    EXPECT_DOUBLE_EQ(cage.pigs[0].y, 0.45);
    EXPECT_TRUE(checkRest(cage).passed());

    // Under a plank 0.55 m above the floor a medium pig (0.7 m) does not fit: every draw keeps the small one.
    LevelDef low;
    low.blocks = {{BlockShape::Box, "wood", 0.0, 0.675, 2.0, 0.25, 0.0, 0.1}};
    low.pigs = {{"small", 0.0, 0.25}};
    int kept = 0;
    for (std::uint64_t seed = 0; seed < 30; ++seed)
    {
        GeneratorRng rng(seed, 0);
        const PartVariation v = drawPartVariation(low, rng, Catalog::builtin());
        ASSERT_EQ(v.pigTypes.size(), 1u);
        kept += v.pigTypes[0] == "small" ? 1 : 0;
    }
    EXPECT_EQ(kept, 30);
}

TEST(PartVariation, DrawsStayWithinWhatThePartAllows)
{
    const LevelDef fortress = part("fortress");  // 10.65 m wide: never stretched
    const LevelDef crate = part("tnt-on-frame"); // not all wood: never ice
    const LevelDef frame = part("frame");
    int frameIce = 0;
    int frameStretched = 0;
    int pigsChanged = 0;
    for (std::uint64_t seed = 0; seed < 200; ++seed)
    {
        GeneratorRng a(seed, 0);
        EXPECT_DOUBLE_EQ(drawPartVariation(fortress, a, Catalog::builtin()).stretch, 1.0);
        GeneratorRng b(seed, 0);
        EXPECT_FALSE(drawPartVariation(crate, b, Catalog::builtin()).ice);
        GeneratorRng c(seed, 0);
        const PartVariation v = drawPartVariation(frame, c, Catalog::builtin());
        frameIce += v.ice ? 1 : 0;
        frameStretched += v.stretch != 1.0 ? 1 : 0;
        pigsChanged += v.pigTypes.at(0) == "medium" ? 1 : 0;
        const LevelDef varied = varyPart(frame, v, Catalog::builtin());
        EXPECT_TRUE(std::all_of(varied.blocks.begin(), varied.blocks.end(),
                                [&](const BlockDef& block) { return block.material == (v.ice ? "ice" : "wood"); }));
    }
    // A quarter, two thirds and a half of 200 draws, within a generous margin.
    EXPECT_GT(frameIce, 30);
    EXPECT_LT(frameIce, 70);
    EXPECT_GT(frameStretched, 110);
    EXPECT_LT(frameStretched, 160);
    EXPECT_GT(pigsChanged, 70);
    EXPECT_LT(pigsChanged, 130);
}

} // namespace
} // namespace abalike
