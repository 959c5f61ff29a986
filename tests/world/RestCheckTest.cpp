#include <abalike/level/LevelIO.hpp>
#include <abalike/world/RestCheck.hpp>
#include <abalike/world/StressScenes.hpp>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

const std::string kSource = ABALIKE_SOURCE_DIR;

LevelDef groundLevel()
{
    LevelDef level;
    level.birds = {"red"};
    level.pigs = {{"small", 30.0, 0.25}};
    return level;
}

TEST(RestCheck, FirstLevelStandsForTenSeconds)
{
    const LevelDef level = loadLevel(kSource + "/levels/1-1-first-flight.json", Catalog::builtin());
    const RestReport report = checkRest(level);
    EXPECT_TRUE(report.passed()) << report.summary();
    EXPECT_EQ(report.seconds, 10.0);
    EXPECT_EQ(report.bodies.size(), level.blocks.size() + level.pigs.size());
    EXPECT_TRUE(report.settled);
}

TEST(RestCheck, EveryCampaignLevelStandsWithinTheMassRatioGuidance)
{
    for (const std::string& path : loadCampaign(kSource + "/levels/campaign.json"))
    {
        const RestReport report = checkRest(loadLevel(path, Catalog::builtin()));
        std::cout << "[ level    ] " << path.substr(path.find_last_of('/') + 1) << ": " << report.summary() << '\n';
        EXPECT_TRUE(report.passed()) << path << ": " << report.summary();
        EXPECT_LE(report.worstMassRatio.ratio, 10.0) << path << ": " << report.summary();
    }
}

// Columns of hollow boxes, 2 to 10 high, in every order of two or three materials (stone on ice is 6:1), of the
// shipped sizes (1 m walls 0.1 and 0.2; Science Birds' square hole, 0.84 m walls 0.17): each stands still to the
// tenth of a millimetre. Before the settle step's contacts were told apart by fixture (a hollow box has four), such
// a column sank up to 6 mm: the bottom wall took its side wall's empty warm start.
TEST(RestCheck, TallColumnsOfHollowBoxesOfMixedMaterialsStand)
{
    const std::vector<std::vector<std::string>> orders = {
        {"wood", "ice", "stone"}, {"stone", "ice", "wood"}, {"ice", "stone"}, {"wood", "stone"}, {"wood", "ice"}};
    int columns = 0;
    for (const auto& [size, wall] : {std::pair{1.0, 0.1}, std::pair{1.0, 0.2}, std::pair{0.84, 0.17}})
        for (const std::vector<std::string>& order : orders)
            for (const int height : {2, 4, 6, 8, 10})
            {
                LevelDef level = groundLevel();
                for (int i = 0; i < height; ++i)
                {
                    BlockDef box{BlockShape::HollowBox,
                                 order[static_cast<std::size_t>(i) % order.size()],
                                 12.0,
                                 size * (i + 0.5),
                                 size,
                                 size,
                                 0.0};
                    box.wallM = wall;
                    level.blocks.push_back(box);
                }
                const RestReport report = checkRest(level, Catalog::builtin(), 5.0);
                EXPECT_TRUE(report.passed()) << height << " of " << order.front() << "... " << report.summary();
                EXPECT_LT(report.maxDisplacementM, 1e-4)
                    << height << " of " << order.front() << "... size " << size << ": " << report.summary();
                ++columns;
            }
    EXPECT_EQ(columns, 75);
}

TEST(RestCheck, AFloatingBlockFails)
{
    LevelDef level = groundLevel();
    level.blocks.push_back({BlockShape::Box, "wood", 10.0, 3.0, 1.0, 1.0, 0.0});
    const RestReport report = checkRest(level, Catalog::builtin(), 2.0);
    EXPECT_FALSE(report.passed());
    EXPECT_GT(report.maxDisplacementM, 2.0);
    EXPECT_EQ(report.worstBody, 0);
}

TEST(RestCheck, AnOverhangThatCannotStandFails)
{
    // A plank whose centre of mass is well beyond its one column tips over.
    LevelDef level = groundLevel();
    level.blocks.push_back({BlockShape::Box, "wood", 10.0, 1.0, 0.25, 2.0, 0.0});
    level.blocks.push_back({BlockShape::Box, "wood", 11.0, 2.125, 2.5, 0.25, 0.0});
    const RestReport report = checkRest(level, Catalog::builtin(), 5.0);
    EXPECT_FALSE(report.passed()) << report.summary();
    EXPECT_GT(report.maxDisplacementM, 0.1);
}

TEST(RestCheck, ReportsTheHeaviestBodyOnALighterOne)
{
    LevelDef level = groundLevel();
    level.blocks.push_back({BlockShape::Box, "ice", 10.0, 0.1, 2.0, 0.2, 0.0});   // 16 kg
    level.blocks.push_back({BlockShape::Box, "stone", 10.0, 0.7, 1.0, 1.0, 0.0}); // 240 kg: 15:1
    const RestReport report = checkRest(level, Catalog::builtin(), 1.0);
    EXPECT_GT(report.worstMassRatio.ratio, 10.0);
    EXPECT_EQ(report.worstMassRatio.heavier, "block 1 (stone)");
    EXPECT_EQ(report.worstMassRatio.lighter, "block 0 (ice)");
}

TEST(RestCheck, SummaryNamesTheVerdict)
{
    const RestReport report = checkRest(groundLevel(), Catalog::builtin(), 1.0);
    EXPECT_EQ(report.summary().rfind("stands after 1.0 s", 0), 0u) << report.summary();
}

TEST(RestCheck, AStackThatLeansIsNamedWithWhatToChange)
{
    // 20 bricks with a stone block 0.1 m off-centre on top: beyond what the world holds (docs/world-physics.md).
    const RestReport report = checkRest(offCentreLoadScene(20), Catalog::builtin(), 30.0);
    EXPECT_FALSE(report.passed());
    EXPECT_EQ(report.stackDepth, 21);
    EXPECT_EQ(report.stackSubsteps, 4);
    EXPECT_NE(report.summary().find("the deepest stack is 21 bodies, solved in 4 sub-steps"), std::string::npos)
        << report.summary();
    EXPECT_NE(report.summary().find("centre the load"), std::string::npos);
    // Half as tall, it stands.
    EXPECT_TRUE(checkRest(offCentreLoadScene(10), Catalog::builtin(), 30.0).passed());
}

} // namespace
} // namespace abalike
