#include "AbilityTestLevel.hpp"

#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

using namespace abalike::test;

TEST(Abilities, SplitAddsTwoBirdsAtPlusMinusTheAngleAndLeavesTheBirdOnItsPredictedPath)
{
    GameSession session(abilityLevel({"blue"}));
    launchAndFly(session, 20.0, 20.0, 0.25);
    ASSERT_TRUE(session.canActivateAbility());
    ASSERT_TRUE(session.activateAbility());
    EXPECT_FALSE(session.canActivateAbility()) << "an ability is used once";
    EXPECT_EQ(session.world().projectilesInPlay(), 2);

    const ShotRecord& shot = session.shots().back();
    ASSERT_TRUE(shot.ability.has_value());
    EXPECT_EQ(shot.ability->ability, "split");
    EXPECT_TRUE(shot.ability->beforeContact);
    EXPECT_FALSE(shot.ability->changedFlight);
    ASSERT_EQ(shot.ability->impulses.size(), 2u);
    const double mass = session.catalog().findBird("blue")->massKg;
    const double split = numberOf(session.catalog(), "split", "angle_deg");
    // The bird's own velocity now: the RK4 state the world flies it on.
    std::vector<double> offsets;
    for (const Entity& e : session.world().entities())
    {
        if (e.kind != EntityKind::Bird || !e.alive || &e == session.world().bird())
            continue;
        const b2Vec2 v = e.body->GetLinearVelocity();
        const AbilityImpulse& j = shot.ability->impulses[offsets.size()];
        EXPECT_NEAR(std::hypot(j.impulseX, j.impulseY), mass * v.Length(), 1e-4 * mass * v.Length());
        offsets.push_back(angleOf(v.x, v.y));
    }
    ASSERT_EQ(offsets.size(), 2u);
    EXPECT_NEAR(offsets[0] - offsets[1], 2.0 * split, 1e-3);

    while (session.phase() == Phase::Flying)
        session.step();
    ASSERT_TRUE(shot.deviationM.has_value()) << "a split does not change the bird's own flight";
    EXPECT_LT(*shot.deviationM, 0.01);
}

} // namespace
} // namespace abalike
