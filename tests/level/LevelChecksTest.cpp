#include <abalike/level/LevelIO.hpp>
#include <abalike/world/Catalog.hpp>

#include <algorithm>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

/// A level with the given blocks (JSON array items), extra top-level keys, and one pig at x.
std::string levelWith(const std::string& blocks, const std::string& extra = "", const std::string& pigX = "30",
                      const std::string& birds = R"(["red"])", const std::string& pigY = "0.25")
{
    return R"({"format": 1, "id": "c", "title": "C", "slingshot": {"x": 0, "y": 1.5}, "birds": )" + birds +
           R"(, "pigs": [{"type": "small", "x": )" + pigX + R"(, "y": )" + pigY + R"(}], "blocks": [)" + blocks + "]" +
           extra + "}";
}

std::string errorsOf(const std::string& text)
{
    try
    {
        parseLevel(text, "c.json", Catalog::builtin());
    }
    catch (const LevelLoadError& e)
    {
        std::string all;
        for (const LevelIssue& issue : e.issues())
            all += issue.format() + "\n";
        return all;
    }
    return "";
}

TEST(LevelChecks, StackedBoxesTouchWithoutOverlap)
{
    EXPECT_EQ(errorsOf(levelWith(R"({"material": "stone", "x": 10, "y": 0.5, "w": 1, "h": 1},
                                    {"material": "wood", "x": 10, "y": 1.5, "w": 1, "h": 1},
                                    {"material": "wood", "x": 11, "y": 0.5, "w": 1, "h": 1})")),
              "");
}

TEST(LevelChecks, CircleOnBoxCornerIsNotOverlap)
{
    // The circle touches the top face; its bounding box overlaps the block's corner region.
    EXPECT_EQ(errorsOf(levelWith(R"({"material": "wood", "x": 10, "y": 0.5, "w": 1, "h": 1},
                                    {"shape": "circle", "material": "ice", "x": 10.4, "y": 1.5, "w": 1})")),
              "");
}

TEST(LevelChecks, RotatedPlankLeaningIntoABlockOverlaps)
{
    const std::string errors = errorsOf(levelWith(R"({"material": "wood", "x": 10, "y": 1, "w": 1, "h": 2},
        {"material": "wood", "x": 10.9, "y": 1.5, "w": 3, "h": 0.2, "angle_deg": 45})"));
    EXPECT_NE(errors.find("/blocks/1: overlaps /blocks/0"), std::string::npos) << errors;
}

TEST(LevelChecks, TriangleHypotenuseLeavesRoomForABox)
{
    // The right triangle's right angle is at its bottom left: a box tucked against the hypotenuse's
    // upper-right side (but inside the bounding box corner) does not overlap it.
    EXPECT_EQ(errorsOf(levelWith(R"({"shape": "triangle", "material": "stone", "x": 10, "y": 1, "w": 2, "h": 2},
                                    {"material": "wood", "x": 10.8, "y": 1.8, "w": 0.4, "h": 0.4})")),
              "");
}

TEST(LevelChecks, APigMaySitInsideAHollowBox)
{
    EXPECT_EQ(errorsOf(levelWith(R"({"shape": "hollow_box", "material": "stone", "x": 10, "y": 1, "w": 2, "h": 2,
                                     "wall": 0.2})",
                                 "", "10", R"(["red"])", "0.45")),
              "");
}

TEST(LevelChecks, AHollowBoxWallThroughAPigIsOneOverlap)
{
    const std::string errors = errorsOf(levelWith(R"({"shape": "hollow_box", "material": "wood", "x": 10, "y": 1,
                                                       "w": 2, "h": 2, "wall": 0.2})",
                                                  "", "9"));
    EXPECT_NE(errors.find("/pigs/0: overlaps /blocks/0 (expected bodies to touch at most"), std::string::npos)
        << errors;
    EXPECT_EQ(std::count(errors.begin(), errors.end(), '\n'), 1) << errors;
}

TEST(LevelChecks, TerrainPiecesMayOverlapEachOther)
{
    EXPECT_EQ(errorsOf(levelWith("", R"(, "terrain": [{"x": 20, "y": 1, "w": 10, "h": 2},
                                                       {"x": 24, "y": 2, "w": 4, "h": 4}])")),
              "");
}

TEST(LevelChecks, EveryOverlapIsReported)
{
    const std::string errors = errorsOf(levelWith(R"({"material": "wood", "x": 10, "y": 0.5, "w": 1, "h": 1},
        {"material": "wood", "x": 10.5, "y": 0.5, "w": 1, "h": 1},
        {"material": "wood", "x": 11, "y": 0.5, "w": 1, "h": 1})"));
    EXPECT_NE(errors.find("/blocks/1: overlaps /blocks/0"), std::string::npos) << errors;
    EXPECT_NE(errors.find("/blocks/2: overlaps /blocks/1"), std::string::npos) << errors;
}

TEST(LevelChecks, WindPushesReachBackwards)
{
    // A pig behind the slingshot: unreachable in still air, reachable with a strong wind towards -x.
    EXPECT_NE(errorsOf(levelWith("", "", "-8")).find("/pigs/0: out of the slingshot's reach"), std::string::npos);
    EXPECT_EQ(errorsOf(levelWith("", R"(, "environment": {"air_density": 1.2, "wind": [-60, 0]})", "-8")), "");
}

TEST(LevelChecks, ReachUsesTheFastestBird)
{
    // Too far for red (30 m/s, about 93 m), within blue's reach (32.3 m/s, 109 m): the band's moving mass weighs
    // less with the 1.5 kg blue bird.
    EXPECT_NE(errorsOf(levelWith("", "", "100")).find("out of the slingshot's reach"), std::string::npos);
    EXPECT_EQ(errorsOf(levelWith("", "", "100", R"(["red", "blue"])")), "");
}

} // namespace
} // namespace abalike
