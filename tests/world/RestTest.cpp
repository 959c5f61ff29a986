#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

TEST(WorldAtRest, FirstLevelStandsStillForTenSeconds)
{
    const LevelDef level =
        loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/1-1-first-flight.json", Catalog::builtin());
    GameWorld world(level, Catalog::builtin());
    const int steps = static_cast<int>(std::round(10.0 / world.dt()));
    for (int i = 0; i < steps; ++i)
        world.step();
    for (const Entity& e : world.entities())
    {
        if (e.kind != EntityKind::Block && e.kind != EntityKind::Pig)
            continue;
        ASSERT_TRUE(e.alive) << e.typeName << " " << e.defIndex;
        EXPECT_EQ(e.health, e.maxHealth) << e.typeName << " " << e.defIndex;
        const double x0 = e.kind == EntityKind::Block ? level.blocks[e.defIndex].x : level.pigs[e.defIndex].x;
        const double y0 = e.kind == EntityKind::Block ? level.blocks[e.defIndex].y : level.pigs[e.defIndex].y;
        const b2Vec2 p = e.body->GetPosition();
        EXPECT_LT(std::hypot(p.x - x0, p.y - y0), 0.005) << e.typeName << " " << e.defIndex;
    }
    EXPECT_TRUE(world.isSettled());
}

TEST(WorldAtRest, BoxRestsExactlyOnItsDesignedSurface)
{
    LevelDef level;
    level.birds = {"red"};
    level.blocks = {{BlockShape::Box, "stone", 5.0, 0.5, 1.0, 1.0, 0.0},
                    {BlockShape::Box, "wood", 5.0, 1.5, 1.0, 1.0, 0.0}};
    level.pigs = {{"small", 8.0, 0.25}};
    GameWorld world(level, Catalog::builtin());
    for (int i = 0; i < 120; ++i)
        world.step();
    // Box2D's skin would leave each contact 15 mm apart; the world compensates so stacks keep their height.
    EXPECT_NEAR(world.entities()[1].body->GetPosition().y, 0.5, 0.001);
    EXPECT_NEAR(world.entities()[2].body->GetPosition().y, 1.5, 0.001);
    EXPECT_NEAR(world.entities()[3].body->GetPosition().y, 0.25, 0.001);
}

} // namespace
} // namespace abalike
