#include "AbilityTestLevel.hpp"

#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

using namespace abalike::test;

TEST(Abilities, BoostAddsItsSpeedAlongTheVelocity)
{
    GameSession session(abilityLevel({"yellow"}));
    launchAndFly(session, 30.0, 15.0, 0.3);
    const auto before = pathVelocity(session.shots().back());
    ASSERT_TRUE(session.activateAbility());
    session.step();
    const ShotRecord& shot = session.shots().back();
    const auto after = pathVelocity(shot);
    const double gain = numberOf(session.catalog(), "boost", "speed_gain_mps");
    // One step of gravity and RK4 chord apart, the speed grew by the boost and the direction stayed.
    EXPECT_NEAR(std::hypot(after.x, after.y) - std::hypot(before.x, before.y), gain, 0.2);
    EXPECT_NEAR(angleOf(after.x, after.y), angleOf(before.x, before.y), 1.0);

    ASSERT_EQ(shot.ability->impulses.size(), 1u);
    const AbilityImpulse& j = shot.ability->impulses[0];
    const double mass = session.catalog().findBird("yellow")->massKg;
    EXPECT_NEAR(std::hypot(j.impulseX, j.impulseY), mass * gain, 1e-9);
    EXPECT_NEAR(angleOf(j.impulseX, j.impulseY), angleOf(before.x, before.y), 1.0);
    EXPECT_TRUE(shot.ability->changedFlight);

    while (session.phase() == Phase::Flying)
        session.step();
    EXPECT_TRUE(shot.actualContact.has_value());
    EXPECT_FALSE(shot.deviationM.has_value()) << "the prediction was for the flight without the boost";
    EXPECT_EQ(shot.accuracyPoints, 0);
}

} // namespace
} // namespace abalike
