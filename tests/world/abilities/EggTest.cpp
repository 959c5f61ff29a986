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

TEST(Abilities, WhatTheEggBreaksIsCausedByTheEggAbility)
{
    // A row of pigs under the white bird's flight: the egg dropped early lands on one of them. Its cause is the ability
    // that dropped it (named "egg" in simulate's JSON and the trace), not the shot's bird.
    LevelDef level;
    level.birds = {"white"};
    for (int i = 0; i < 30; ++i)
        level.pigs.push_back({"small", 3.0 + 0.6 * i, 0.25});
    GameSession session(level);
    launchAndFly(session, 60.0, 16.0, 0.3);
    ASSERT_TRUE(session.activateAbility());
    while (session.phase() == Phase::Flying)
        session.step();
    int byEgg = 0;
    for (const DestroyedEvent& defeat : session.destroyed())
    {
        if (defeat.cause.kind != CauseKind::Ability)
            continue;
        ++byEgg;
        ASSERT_NE(defeat.cause.ability, nullptr);
        EXPECT_EQ(defeat.cause.ability->name(), "egg");
        EXPECT_EQ(causeName(defeat.cause), "egg");
    }
    EXPECT_GE(byEgg, 1) << "the egg defeated no pig";
    EXPECT_EQ(causeName({CauseKind::Bird, -1}), "bird");
}

} // namespace
} // namespace abalike
