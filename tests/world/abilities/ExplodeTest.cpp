#include "../TestCatalog.hpp"
#include "AbilityTestLevel.hpp"

#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

using namespace abalike::test;

TEST(Abilities, ExplosionPushesAndDamagesWithLinearFalloff)
{
    const LevelDef level = abilityLevel({"black"});
    GameWorld world(level, Catalog::builtin());
    world.step();
    const BirdType& black = *Catalog::builtin().findBird("black");
    FlightModel model;
    model.massKg = black.massKg;
    world.launchBird(black, model, {{18.5, 1.0}, {1.0, 0.0}}); // 1.5 m left of the tower
    std::vector<double> healthBefore;
    for (const Entity& e : world.entities())
        healthBefore.push_back(e.health);
    const std::optional<AbilityUse> use = world.activateAbility();
    ASSERT_TRUE(use.has_value());
    EXPECT_EQ(use->ability, "explode");
    EXPECT_EQ(world.bird(), nullptr) << "the bird is gone with the blast";

    const double radius = numberOf(Catalog::builtin(), "explode", "radius_m");
    const double impulse = numberOf(Catalog::builtin(), "explode", "impulse_ns");
    EXPECT_EQ(use->reachM, radius);
    ASSERT_FALSE(use->impulses.empty());
    for (const AbilityImpulse& j : use->impulses)
    {
        const double d = std::hypot(j.x - use->x, j.y - use->y);
        EXPECT_LT(d, radius);
        EXPECT_NEAR(std::hypot(j.impulseX, j.impulseY), impulse * (1.0 - d / radius), 1e-3);
        // Radial: the impulse points away from the bird.
        EXPECT_GT(j.impulseX * (j.x - use->x) + j.impulseY * (j.y - use->y), 0.0);
    }
    // The two lowest wood blocks (centres 1.58 m away) took 118 N s each: more than wood's 60.
    EXPECT_FALSE(world.entities()[1].alive);
    EXPECT_FALSE(world.entities()[2].alive);
    // The far pig is untouched.
    EXPECT_EQ(world.entities().back().health, healthBefore.back());
}

TEST(Abilities, TheBlackBirdsBlastBreaksStoneBesideIt)
{
    // A 1 m stone block and the bird exploding as it touches its side: the bird's centre 0.8 m from the block's.
    LevelDef level;
    level.birds = {"black"};
    level.blocks.push_back({BlockShape::Box, "stone", 10.0, 0.5, 1.0, 1.0, 0.0, 0.1});
    level.pigs = {{"small", 30.0, 0.25}};
    GameWorld world(level, Catalog::builtin());
    world.step();
    const BirdType& black = *Catalog::builtin().findBird("black");
    FlightModel model;
    model.massKg = black.massKg;
    world.launchBird(black, model, {{10.0 - 0.8, 0.5}, {0.0, 0.0}});
    ASSERT_TRUE(world.activateAbility().has_value());
    EXPECT_FALSE(world.entities()[1].alive) << "500 N s x (1 - 0.8 / 3) = 367 N s against stone's 300";
}

TEST(Abilities, ABodyTheBlastFlingsStopsAtAThinPlank)
{
    // A pig tough enough to survive the blast, 0.6 m from it, is sent off at about 68 m/s: more than a metre a step.
    // A 0.2 m stone plank, made too strong to break here, stands 4 m away. Swept as a bullet until it slows, the pig
    // stops at the plank instead of stepping through it.
    const Catalog catalog = test::catalogWith(
        [](nlohmann::json& root)
        {
            for (nlohmann::json& pig : root["pigs"])
                pig["health_ns"] = 5000.0;
            for (nlohmann::json& material : root["materials"])
                material["strength_ns"] = 1.0e6;
        });
    LevelDef level;
    level.birds = {"black"};
    level.pigs = {{"small", 5.6, 0.25}};
    level.blocks.push_back({BlockShape::Box, "stone", 9.6, 1.0, 0.2, 2.0, 0.0, 0.1});
    GameWorld world(level, catalog);
    world.step();
    const BirdType& black = *catalog.findBird("black");
    FlightModel model;
    model.massKg = black.massKg;
    world.launchBird(black, model, {{5.0, 0.25}, {0.0, 0.0}});
    ASSERT_TRUE(world.activateAbility().has_value());
    const b2Body* pig = world.entities()[2].body;
    ASSERT_NE(pig, nullptr);
    EXPECT_GT(pig->GetLinearVelocity().x, 50.0f) << "the blast should fling it fast";
    EXPECT_TRUE(pig->IsBullet());
    for (int i = 0; i < 60; ++i)
        world.step();
    ASSERT_TRUE(world.entities()[2].alive);
    EXPECT_LT(world.entities()[2].body->GetPosition().x, 9.6f) << "the pig passed through the plank";
    EXPECT_FALSE(world.entities()[2].body->IsBullet()) << "slowed down: an ordinary body again";
}

} // namespace
} // namespace abalike
