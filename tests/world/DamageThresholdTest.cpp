#include "TestCatalog.hpp"

#include <abalike/world/GameWorld.hpp>
#include <abalike/world/RestCheck.hpp>
#include <box2d/box2d.h>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

TEST(DamageThreshold, ABlockUnderAHeavyStackTakesNoDamageInThirtySeconds)
{
    // A wood block carrying five stone blocks (1200 kg on 25 kg; each stone rests on the next, the lowest on the
    // wood at 9.6:1, inside Box2D's 10:1).
    LevelDef level;
    level.birds = {"red"};
    level.pigs = {{"small", 30.0, 0.25}};
    level.blocks.push_back({BlockShape::Box, "wood", 10.0, 0.25, 1.0, 0.5, 0.0});
    for (int i = 0; i < 5; ++i)
        level.blocks.push_back({BlockShape::Box, "stone", 10.0, 1.0 + i, 1.0, 1.0, 0.0});
    const RestReport report = checkRest(level, Catalog::builtin(), 30.0);
    EXPECT_TRUE(report.passed()) << report.summary();
    EXPECT_FALSE(report.bodies[0].damaged);
    EXPECT_EQ(report.damagedBodies, 0);
    EXPECT_LE(report.worstMassRatio.ratio, 10.0);
}

/// Two equal wood blocks in zero gravity, one moving at `speed` into the other; returns the damage each took.
/// The wood is made strong enough not to break, so the whole impulse shows as damage.
std::pair<double, double> headOnDamage(double speed, double* expectedImpulse = nullptr)
{
    const Catalog catalog =
        test::catalogWith([](nlohmann::json& root) { test::materialIn(root, "wood")["strength_ns"] = 1e6; });
    LevelDef level;
    level.environment.gravity = 0.0;
    level.blocks.push_back({BlockShape::Box, "wood", 10.0, 5.0, 0.5, 0.5, 0.0});
    level.blocks.push_back({BlockShape::Box, "wood", 11.0, 5.0, 0.5, 0.5, 0.0});
    GameWorld world(level, catalog);
    b2Body* moving = world.entities()[1].body;
    moving->SetLinearVelocity(b2Vec2(static_cast<float>(speed), 0.0f));
    for (int i = 0; i < 120; ++i)
        world.step();
    if (expectedImpulse != nullptr)
    {
        // Equal masses, restitution e: the impulse is m/2 (1 + e) v.
        const double e = Catalog::builtin().findMaterial("wood")->restitution;
        // The first step rebuilt the bodies (GameWorld::box2d): the resting one is taken after it.
        *expectedImpulse = 0.5 * world.entities()[2].body->GetMass() * (1.0 + e) * speed;
    }
    return {world.entities()[1].maxHealth - world.entities()[1].health,
            world.entities()[2].maxHealth - world.entities()[2].health};
}

TEST(DamageThreshold, ABlockHitAtTenMetresPerSecondTakesTheImpulseAsDamage)
{
    double expected = 0.0;
    const auto [hitter, hit] = headOnDamage(10.0, &expected);
    EXPECT_GT(hit, 0.0);
    EXPECT_NEAR(hit, expected, 0.02 * expected); // 12.5 kg / 2 * 1.2 * 10 m/s = 75 N s
    EXPECT_NEAR(hitter, hit, 1e-9 * expected);   // action and reaction
}

TEST(DamageThreshold, ANudgeBelowTheThresholdDoesNoDamage)
{
    const double threshold = Catalog::builtin().damageSpeedThresholdMps();
    const auto [hitter, hit] = headOnDamage(0.8 * threshold);
    EXPECT_EQ(hit, 0.0);
    EXPECT_EQ(hitter, 0.0);
}

} // namespace
} // namespace abalike
