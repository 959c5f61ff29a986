#include <abalike/level/LevelIO.hpp>
#include <abalike/world/RestCheck.hpp>
#include <abalike/world/StressScenes.hpp>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

class StressSceneTest : public testing::TestWithParam<StressScene>
{
};

TEST_P(StressSceneTest, StandsStillForThirtySeconds)
{
    const StressScene& scene = GetParam();
    const RestReport report = checkRest(scene.level, Catalog::builtin(), 30.0);
    std::cout << "[ scene    ] " << scene.name << ": " << report.summary() << '\n';
    EXPECT_TRUE(report.passed()) << report.summary();
    EXPECT_LE(report.maxDisplacementM, 0.005);
    EXPECT_EQ(report.damagedBodies, 0);
    EXPECT_EQ(report.destroyedBodies, 0);
    EXPECT_TRUE(report.settled) << "still moving after 30 s";
    EXPECT_LE(report.worstMassRatio.ratio, 10.0)
        << report.worstMassRatio.heavier << " on " << report.worstMassRatio.lighter;
}

std::string sceneName(const testing::TestParamInfo<StressScene>& info)
{
    std::string name = info.param.name;
    for (char& c : name)
        if (c == '-')
            c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, StressSceneTest, testing::ValuesIn(stressScenes()), sceneName);
// Walls of bricks in side contact, towers whose columns change material storey by storey, packed ledges: each
// its own ctest entry, so the 1 000-block wall (about 10 s) runs beside the others.
INSTANTIATE_TEST_SUITE_P(Structures, StressSceneTest, testing::ValuesIn(structureScenes()), sceneName);

TEST(StressScenes, StoneRestsOnIceAtLeastThreeTimesItsMass)
{
    const RestReport report = checkRest(stoneOnIceScene(), Catalog::builtin(), 1.0);
    EXPECT_GE(report.worstMassRatio.ratio, 3.0);
    EXPECT_NE(report.worstMassRatio.heavier.find("stone"), std::string::npos);
    EXPECT_NE(report.worstMassRatio.lighter.find("ice"), std::string::npos);
}

TEST(StressScenes, HaveTheAdvertisedSizes)
{
    EXPECT_EQ(towerScene(20).blocks.size(), 20u);
    EXPECT_EQ(pyramidScene(15).blocks.size(), 120u);
    EXPECT_EQ(pyramidScene(40).blocks.size(), 820u);
    WallSpec wall;
    wall.columns = 20;
    wall.rows = 50;
    EXPECT_EQ(wallScene(wall).blocks.size(), 1000u); // the format's maximum
    wall.staggered = true;
    wall.rows = 10;
    EXPECT_EQ(wallScene(wall).blocks.size(), 205u); // five shifted rows of 19 bricks and two halves
    EXPECT_EQ(storeyTowerScene({8, {"stone"}, {"wood"}}).blocks.size(), 24u);
}

TEST(StressScenes, WallBricksTouchTheirNeighboursExactly)
{
    WallSpec spec;
    spec.columns = 3;
    spec.rows = 2;
    spec.staggered = true;
    const LevelDef wall = wallScene(spec);
    // Row 0: three bricks; row 1: a half brick, two bricks, a half brick, edge to edge from x = 20 to 21.5.
    ASSERT_EQ(wall.blocks.size(), 7u);
    double right = 20.0;
    for (std::size_t i = 3; i < 7; ++i)
    {
        EXPECT_DOUBLE_EQ(wall.blocks[i].x - wall.blocks[i].widthM / 2, right);
        right = wall.blocks[i].x + wall.blocks[i].widthM / 2;
        EXPECT_DOUBLE_EQ(wall.blocks[i].y - wall.blocks[i].heightM / 2, 0.25);
    }
    EXPECT_DOUBLE_EQ(right, 21.5);
}

TEST(StressScenes, StoreyTowersCycleTheirMaterials)
{
    const LevelDef tower = storeyTowerScene({3, {"stone", "wood", "ice"}, {"wood"}});
    ASSERT_EQ(tower.blocks.size(), 9u);
    EXPECT_EQ(tower.blocks[0].material, "stone");
    EXPECT_EQ(tower.blocks[3].material, "wood");
    EXPECT_EQ(tower.blocks[6].material, "ice");
    EXPECT_EQ(tower.blocks[8].material, "wood");
    EXPECT_DOUBLE_EQ(tower.pigs[0].y, 3 * 1.75 + 0.25); // on the top plank
}

TEST(StressScenes, TheStructureLevelFilesAreTheScenes)
{
    // levels/structures/NAME.json is each structure scene as a level file, for `abalike check` and for designers
    // to start from; it must not drift from the scene the tests and the bench use.
    for (const StressScene& scene : structureScenes())
    {
        const LevelDef file = loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/structures/" + scene.name + ".json",
                                        Catalog::builtin());
        const LevelDef& level = scene.level;
        ASSERT_EQ(file.blocks.size(), level.blocks.size()) << scene.name;
        for (std::size_t i = 0; i < level.blocks.size(); ++i)
        {
            const BlockDef& a = file.blocks[i];
            const BlockDef& b = level.blocks[i];
            EXPECT_TRUE(a.material == b.material && a.shape == b.shape && a.x == b.x && a.y == b.y &&
                        a.widthM == b.widthM && a.heightM == b.heightM && a.angleDeg == b.angleDeg)
                << scene.name << " block " << i;
        }
        ASSERT_EQ(file.pigs.size(), level.pigs.size()) << scene.name;
        for (std::size_t i = 0; i < level.pigs.size(); ++i)
            EXPECT_TRUE(file.pigs[i].type == level.pigs[i].type && file.pigs[i].x == level.pigs[i].x &&
                        file.pigs[i].y == level.pigs[i].y)
                << scene.name << " pig " << i;
        ASSERT_EQ(file.terrain.size(), level.terrain.size()) << scene.name;
        for (std::size_t i = 0; i < level.terrain.size(); ++i)
            EXPECT_TRUE(file.terrain[i].x == level.terrain[i].x && file.terrain[i].y == level.terrain[i].y &&
                        file.terrain[i].widthM == level.terrain[i].widthM &&
                        file.terrain[i].heightM == level.terrain[i].heightM)
                << scene.name << " terrain " << i;
    }
}

} // namespace
} // namespace abalike
