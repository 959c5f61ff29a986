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

INSTANTIATE_TEST_SUITE_P(Scenes, StressSceneTest, testing::ValuesIn(stressScenes()),
                         [](const testing::TestParamInfo<StressScene>& info)
                         {
                             std::string name = info.param.name;
                             for (char& c : name)
                                 if (c == '-')
                                     c = '_';
                             return name;
                         });

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
}

} // namespace
} // namespace abalike
