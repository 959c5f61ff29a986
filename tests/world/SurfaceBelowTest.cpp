#include <abalike/level/LevelIO.hpp>
#include <abalike/world/GameWorld.hpp>
#include <gtest/gtest.h>
#include <string>

namespace abalike
{
namespace
{

TEST(SurfaceBelow, TheSlingshotOnTheCliffStandsOnTheCliffTop)
{
    // 1-8: the cliff is a 8 x 10 m box centred at (-3, 5), the slingshot's pouch at (0, 10.5).
    const LevelDef level =
        loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/1-8-from-the-cliff.json", Catalog::builtin());
    const GameWorld world(level, Catalog::builtin());
    EXPECT_NEAR(world.surfaceBelow(0.0, 10.5), 10.0, 0.01);  // the collision skin keeps it under 1 cm
    EXPECT_NEAR(world.surfaceBelow(-6.5, 10.5), 10.0, 0.01); // the queue of birds, further back on the top
    EXPECT_DOUBLE_EQ(world.surfaceBelow(2.0, 10.5), 0.0);    // past the cliff's edge: the ground
    // Blocks and pigs move: they are no floor. Under the tower on the ground, the ground.
    EXPECT_DOUBLE_EQ(world.surfaceBelow(level.pigs.front().x, 20.0), 0.0);
    // From below the ground, the ground.
    EXPECT_DOUBLE_EQ(world.surfaceBelow(0.0, -1.0), 0.0);
}

} // namespace
} // namespace abalike
