// Science Birds' shapes where ours differ: a triangle's pivot lies on its long side, and its circles and pigs are
// polygons with flat bottoms. Each case is a real pattern of Phy-Q's templates or the deceptive-level generator.
#include <abalike/level/ScienceBirds.hpp>
#include <abalike/world/Catalog.hpp>
#include <abalike/world/RestCheck.hpp>

#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

ScienceBirdsLevel importShapes(const std::string& objects)
{
    return importScienceBirds("<Level><GameObjects>\n" + objects + "</GameObjects></Level>", "shapes.xml",
                              Catalog::builtin());
}

std::string messageAbout(const ScienceBirdsLevel& imported, const std::string& pointer)
{
    std::string all;
    for (const LevelIssue& issue : imported.warnings)
        if (issue.pointer == pointer)
            all += issue.message + "\n";
    return all;
}

// Science Birds' y of a body whose bottom is `above` metres over its ground (-3.5).
std::string onGround(double above)
{
    return std::to_string(-3.5 + above);
}

// A wooden <Block> whose centre is `above` metres over Science Birds' ground.
std::string woodBlock(const std::string& type, const std::string& x, double above, const std::string& rotation)
{
    return "<Block type=\"" + type + "\" material=\"wood\" x=\"" + x + "\" y=\"" + onGround(above) + "\" rotation=\"" +
           rotation + "\"/>\n";
}

// A small pig whose centre is `above` metres over Science Birds' ground.
std::string smallPig(const std::string& x, double above)
{
    return "<Pig type=\"BasicSmall\" x=\"" + x + "\" y=\"" + onGround(above) + "\"/>\n";
}

TEST(ScienceBirdsShapes, ATriangleTurnedOntoItsLongSideIsSetOntoWhatHoldsIt)
{
    // Turned 225 degrees, the right angle points up and the long side lies flat through the triangle's centre: its
    // bottom is its centre, not half a bounding box lower. It was 2.5 cm above the platform's top (1.81 m in ours).
    const ScienceBirdsLevel imported =
        importShapes("<Platform x=\"4\" y=\"-2\" scaleX=\"4\" scaleY=\"1\"/>\n"
                     "<Block type=\"Triangle\" material=\"stone\" x=\"4\" y=\"-1.665\" rotation=\"225\"/>\n" +
                     smallPig("8", 0.225));
    ASSERT_EQ(imported.level.blocks.size(), 1u);
    EXPECT_DOUBLE_EQ(imported.level.blocks[0].y, 1.81);
    EXPECT_EQ(messageAbout(imported, "/blocks/0"), "was 2.5 cm above terrain 0; set onto it (y = 1.81 in our level)\n");
    const RestReport rest = checkRest(imported.level);
    EXPECT_TRUE(rest.passed()) << rest.summary();
}

TEST(ScienceBirdsShapes, ACircleWhoseFlatBottomReachesAnEdgeIsMovedOntoIt)
{
    // Science Birds' Circle stands on a 34 cm flat side, so Phy-Q leaves circles with their centre a few centimetres
    // past a ledge's end. Ours is round and would roll off: it goes 2 cm inside the edge (the ledge spans 3.38-4.62).
    const ScienceBirdsLevel imported =
        importShapes("<Platform x=\"4\" y=\"-2\" scaleX=\"2\" scaleY=\"1\"/>\n"
                     "<Block type=\"Circle\" material=\"stone\" x=\"4.65\" y=\"-1.29\" rotation=\"0\"/>\n" +
                     smallPig("8", 0.225));
    ASSERT_EQ(imported.level.blocks.size(), 1u);
    EXPECT_DOUBLE_EQ(imported.level.blocks[0].x, 4.6);
    EXPECT_DOUBLE_EQ(imported.level.blocks[0].y, 2.21);
    EXPECT_EQ(messageAbout(imported, "/blocks/0"),
              "its centre is 3.0 cm past terrain 0's edge, where Science Birds' circle stands on its flat bottom and "
              "ours, being round, rolls off; moved 5.0 cm left onto it (x = 4.6 in our level)\n");
    const RestReport rest = checkRest(imported.level);
    EXPECT_TRUE(rest.passed()) << rest.summary();
}

TEST(ScienceBirdsShapes, APigAcrossTwoPlanksEndsSettlesIntoTheGap)
{
    // Two planks laid end to end 7 cm apart with a pig across the gap (the deceptive-level generator's pattern):
    // Science Birds' pig stands on its flat bottom; ours is set into the gap, centred and touching both edges, where
    // it would otherwise drop 3 mm and roll 1 cm when the level starts.
    const ScienceBirdsLevel imported =
        importShapes(woodBlock("RectSmall", "2", 0.11, "0") + woodBlock("RectSmall", "2.92", 0.11, "0") +
                     smallPig("2.45", 0.22 + 0.225));
    ASSERT_EQ(imported.level.pigs.size(), 1u);
    EXPECT_DOUBLE_EQ(imported.level.pigs[0].x, 2.46);
    EXPECT_NEAR(imported.level.pigs[0].y, 0.22 + std::sqrt(0.215 * 0.215 - 0.035 * 0.035), 5e-4);
    EXPECT_NE(messageAbout(imported, "/pigs/0")
                  .find("stands across the 7.0 cm gap between block 0 (wood) and block 1 (wood), where Science "
                        "Birds' pig rests on its flat bottom and ours, being round, settles into it; set into it "
                        "(x = 2.46, y = 0.432 in our level)"),
              std::string::npos)
        << messageAbout(imported, "/pigs/0");
    const RestReport rest = checkRest(imported.level);
    EXPECT_TRUE(rest.passed()) << rest.summary();
    // Set on the planks' tops where the file has it, it would not stand.
    LevelDef onTops = imported.level;
    onTops.pigs[0].x = 2.45;
    onTops.pigs[0].y = 0.22 + 0.215;
    const RestReport naive = checkRest(onTops);
    EXPECT_FALSE(naive.passed()) << naive.summary();
    EXPECT_LT(rest.maxDisplacementM, naive.maxDisplacementM / 2);
}

TEST(ScienceBirdsShapes, ASmallPigFitsUnderAPlankOnPostsOfItsHeight)
{
    // Science Birds' small pig is 0.45 m tall and its flat top carries a plank laid on 0.43 m posts beside it.
    // Ours is round and cannot carry it, so Science Birds' small pig becomes sb-small, 0.43 m: the plank rests on
    // the posts and the pig stands under it.
    const ScienceBirdsLevel imported =
        importShapes(woodBlock("SquareSmall", "2", 0.215, "0") + woodBlock("SquareSmall", "2.92", 0.215, "0") +
                     woodBlock("RectSmall", "2.46", 0.45 + 0.11, "0") + smallPig("2.46", 0.225));
    ASSERT_EQ(imported.level.pigs.size(), 1u);
    EXPECT_EQ(imported.level.pigs[0].type, "sb-small");
    EXPECT_DOUBLE_EQ(imported.level.pigs[0].y, 0.215);
    EXPECT_DOUBLE_EQ(imported.level.blocks[2].y, 0.54) << "the plank on the posts";
    const RestReport rest = checkRest(imported.level);
    EXPECT_TRUE(rest.passed()) << rest.summary();
}

TEST(ScienceBirdsShapes, ASettledSceneTiltedByADegreeOrTwoStartsSquare)
{
    // The deceptive-level generator records scenes after they settled: a post and its plank 1.3 and 1.4 degrees off.
    // Read as written, the plank stands on one corner and slides; square, they stand. A 12 degree tilt is designed.
    const ScienceBirdsLevel imported =
        importShapes(woodBlock("RectSmall", "2", 0.425, "88.7") + woodBlock("RectSmall", "2", 0.96, "358.6") +
                     woodBlock("RectSmall", "6", 0.2, "12") + smallPig("9", 0.225));
    ASSERT_EQ(imported.level.blocks.size(), 3u);
    EXPECT_EQ(imported.level.blocks[0].angleDeg, 90.0);
    EXPECT_EQ(imported.level.blocks[1].angleDeg, 0.0);
    EXPECT_EQ(imported.level.blocks[2].angleDeg, 12.0);
    EXPECT_EQ(messageAbout(imported, ""), "2 rotation(s) within 5 degrees of square read as square (the most by 1.40 "
                                          "degrees): Science Birds' generators write the angles a settled scene ended "
                                          "at, and ours starts square\n");
}

TEST(ScienceBirdsShapes, ASceneShotLeftwardsIsMirrored)
{
    // NovPhy's mirrored scenes put the slingshot right of the pigs; ours shoot to the right, so x becomes -x. A
    // mirrored right triangle is ours turned a quarter; a box's tilt changes sign.
    const ScienceBirdsLevel imported = importScienceBirds(
        "<Level><Slingshot x=\"12\" y=\"-2.5\"/><GameObjects>\n"
        "<Platform x=\"1\" y=\"-2.67\" scaleX=\"3\" scaleY=\"1\"/>\n"
        "<Pig type=\"BasicSmall\" x=\"1\" y=\"-2.135\"/>\n" +
            woodBlock("Triangle", "-2", 0.41, "0") + woodBlock("RectSmall", "-4", 0.3, "20") + "</GameObjects></Level>",
        "mirrored.xml", Catalog::builtin());
    EXPECT_DOUBLE_EQ(imported.level.slingshot.x, -12.0);
    ASSERT_EQ(imported.level.pigs.size(), 1u);
    EXPECT_DOUBLE_EQ(imported.level.pigs[0].x, -1.0);
    ASSERT_EQ(imported.level.terrain.size(), 1u);
    EXPECT_DOUBLE_EQ(imported.level.terrain[0].x, -1.0);
    ASSERT_EQ(imported.level.blocks.size(), 2u);
    EXPECT_DOUBLE_EQ(imported.level.blocks[0].x, 2.0);
    EXPECT_EQ(imported.level.blocks[0].angleDeg, 90.0);
    EXPECT_DOUBLE_EQ(imported.level.blocks[1].x, 4.0);
    EXPECT_EQ(imported.level.blocks[1].angleDeg, -20.0);
    EXPECT_EQ(messageAbout(imported, "/slingshot"),
              "the slingshot stands right of every pig (x = 12): the scene is mirrored (every x becomes -x) so that it "
              "shoots to the right, as ours does\n");
}

} // namespace
} // namespace abalike
