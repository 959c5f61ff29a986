#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <algorithm>
#include <box2d/b2_body.h>
#include <gtest/gtest.h>
#include <string>

namespace abalike
{
namespace
{

LevelDef oneBirdScene(const std::string& blocks)
{
    return parseLevel(R"({"format": 1, "id": "t", "title": "scene", "ground": {"y": 0.0},
        "slingshot": {"x": 0.0, "y": 1.5}, "birds": ["red"], "blocks": [)" +
                          blocks + R"(], "pigs": [{"type": "small", "x": 40.0, "y": 0.25}], "stars": [1, 2, 3]})",
                      "scene.json", Catalog::builtin());
}

const Entity& blockNumbered(const GameSession& session, int defIndex)
{
    const auto& entities = session.world().entities();
    const auto it =
        std::find_if(entities.begin(), entities.end(),
                     [defIndex](const Entity& e) { return e.kind == EntityKind::Block && e.defIndex == defIndex; });
    EXPECT_NE(it, entities.end());
    return *it;
}

// A red bird at 11.7 m/s (47 N s) into a fresh 1 x 2 m wood block (100 kg, 50 N s) 5 m away: stopping its approach
// takes about 45 N s, so the block breaks only on the rebound Box2D adds (restitution 0.3), 58 N s in all. A block
// that fails at its peak load has nothing left to spring back with: the bird goes on with the block instead of
// turning back. Under the rule before (WorldSettings::breakingBodyYields = false) the block kept 50 N s of the
// rebound's impulse and threw the bird back towards the slingshot.
TEST(BreakingBodyYields, ABlockThatBreaksOnlyOnTheReboundDoesNotThrowTheBirdBack)
{
    const LevelDef wall = oneBirdScene(R"({"material": "wood", "x": 5.5, "y": 1.0, "w": 1.0, "h": 2.0})");
    for (const bool yields : {true, false})
    {
        WorldSettings settings;
        settings.breakingBodyYields = yields;
        GameSession session(wall, Catalog::builtin(), settings);
        session.launch(0.0, 11.7);
        for (int i = 0; i < 60; ++i)
            session.step();
        const ShotRecord& shot = session.shots().at(0);
        ASSERT_TRUE(shot.impact) << yields;
        EXPECT_TRUE(shot.impact->broke) << yields;
        EXPECT_GT(shot.impact->damageNs, 0.0);
        if (yields)
        {
            // The bird moves on with the block it broke (their common speed along the normal), a little forward.
            EXPECT_GE(shot.impact->birdAfter.vx, 0.0);
            EXPECT_LT(shot.impact->birdAfter.vx, 1.0);
        }
        else
            EXPECT_LT(shot.impact->birdAfter.vx, -0.5);
    }
}

// A 2 x 0.5 m wood plank (50 kg) dropped 1 m onto a 0.5 m stone cube (60 kg) lying on the ground: the plank breaks
// (about 260 N s against its 60), the stone holds (300 N s). The cube lost no momentum to the plank, the ground took
// the blow, so the break gives it nothing back: it stays on the ground. Refunding the plank's contact impulse as if
// the cube had been stopped by it threw the cube up at 0.7 m/s, and its fall back broke it.
TEST(BreakingBodyYields, ABodyPinnedToTheGroundUnderABreakingBlockIsNotFlungOffIt)
{
    const LevelDef drop = oneBirdScene(R"({"material": "stone", "x": 20.0, "y": 0.25, "w": 0.5, "h": 0.5},
        {"material": "wood", "x": 20.0, "y": 1.75, "w": 2.0, "h": 0.5})");
    GameSession session(drop, Catalog::builtin(), WorldSettings{});
    bool broke = false;
    double fastestUp = 0.0;
    double highest = 0.0;
    for (int i = 0; i < 90; ++i)
    {
        session.step();
        broke = broke || !blockNumbered(session, 1).alive;
        const b2Body* cube = blockNumbered(session, 0).body;
        ASSERT_NE(cube, nullptr);
        if (broke)
        {
            fastestUp = std::max(fastestUp, static_cast<double>(cube->GetLinearVelocity().y));
            highest = std::max(highest, static_cast<double>(cube->GetPosition().y));
        }
    }
    EXPECT_TRUE(broke) << "the plank should break on the stone";
    EXPECT_TRUE(blockNumbered(session, 0).alive);
    EXPECT_LT(fastestUp, 0.1);
    EXPECT_LT(highest, 0.26);
}

} // namespace
} // namespace abalike
