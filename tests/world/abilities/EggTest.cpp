#include "AbilityTestLevel.hpp"

#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

using namespace abalike::test;

TEST(Abilities, EggAndBirdGetEqualAndOppositeImpulses)
{
    GameSession session(abilityLevel({"white"}));
    launchAndFly(session, 45.0, 14.0, 0.4);
    const auto before = pathVelocity(session.shots().back());
    ASSERT_TRUE(session.activateAbility());
    const ShotRecord& shot = session.shots().back();
    ASSERT_EQ(shot.ability->impulses.size(), 2u);
    const AbilityImpulse& egg = shot.ability->impulses[0];
    const AbilityImpulse& bird = shot.ability->impulses[1];
    EXPECT_EQ(egg.target, "egg");
    EXPECT_EQ(bird.target, "bird");
    EXPECT_EQ(egg.impulseX + bird.impulseX, 0.0);
    EXPECT_EQ(egg.impulseY + bird.impulseY, 0.0);
    EXPECT_LT(egg.y, bird.y);
    EXPECT_EQ(session.world().projectilesInPlay(), 1);

    const double eggMass = numberOf(session.catalog(), "egg", "mass_kg");
    const double pushSpeed = numberOf(session.catalog(), "egg", "push_speed_mps");
    const double birdMass = session.catalog().findBird("white")->massKg;
    const Entity* eggEntity = nullptr;
    for (const Entity& e : session.world().entities())
        if (e.typeName == "egg")
            eggEntity = &e;
    ASSERT_NE(eggEntity, nullptr);
    EXPECT_NEAR(eggEntity->body->GetMass(), eggMass, 1e-4);
    session.step();
    const auto after = pathVelocity(shot);
    EXPECT_NEAR(after.y - before.y, eggMass * pushSpeed / birdMass, 0.5);
    EXPECT_NEAR(after.x, before.x, 0.01);

    while (session.phase() == Phase::Flying)
        session.step();
    EXPECT_EQ(session.world().projectilesInPlay(), 0) << "the egg is cleared when the shot ends";
}

} // namespace
} // namespace abalike
