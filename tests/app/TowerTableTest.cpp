#include "bench/TowerTable.hpp"

#include <gtest/gtest.h>

namespace abalike::app
{

// A three-storey wood tower 8 m out with a pig on each of its two lower floors and one beside it; a pig on the ground
// 10 m further off is near no tower; a low stone block stands alone. Of the grid's shots at 0 and 60 deg, three
// bring the tower down (a block that stood at least 2 m above its base falls 1 m or more).
TEST(TowerTable, CountsThePigsUnderOrBesideATowerAShotBringsDown)
{
    LevelDef level;
    level.id = "tower";
    level.birds = {"red"};
    for (const double base : {0.0, 2.25, 4.5})
    {
        level.blocks.push_back({BlockShape::Box, "wood", 9.0, base + 1.0, 0.25, 2.0, 0.0});
        level.blocks.push_back({BlockShape::Box, "wood", 11.0, base + 1.0, 0.25, 2.0, 0.0});
        level.blocks.push_back({BlockShape::Box, "wood", 10.0, base + 2.125, 2.5, 0.25, 0.0});
    }
    level.blocks.push_back({BlockShape::Box, "stone", 16.0, 0.5, 1.0, 1.0, 0.0});
    level.pigs = {{"small", 10.0, 0.25}, {"small", 10.0, 2.5}, {"small", 12.0, 0.25}, {"small", 22.0, 0.25}};
    const TowerTable table = measureTowers({level}, 60);
    ASSERT_EQ(table.byEpisode.size(), 1u);
    EXPECT_EQ(table.all.shots, 6); // 0 and 60 deg, three pulls each
    EXPECT_EQ(table.all.towersDown, 3);
    // Only the three pigs in or beside the tower count, for each shot that brought it down.
    EXPECT_EQ(table.all.pigsNear, 3 * table.all.towersDown);
    EXPECT_LE(table.all.pigsDefeated, table.all.pigsNear);
    const std::string md = towerTableMarkdown(table);
    EXPECT_NE(md.find("| all | 6 | "), std::string::npos) << md;
    EXPECT_NE(md.find(">= 70 %"), std::string::npos) << md;
}

} // namespace abalike::app
