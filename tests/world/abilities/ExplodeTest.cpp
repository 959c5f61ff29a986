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
    world.launchBird(black, model, {18.5, 1.0, 1.0, 0.0}); // 1.5 m left of the tower
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

} // namespace
} // namespace abalike
