#include "AbilityTestLevel.hpp"

#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

using namespace abalike::test;

TEST(Abilities, FollowTheRules)
{
    GameSession session(abilityLevel({"red", "blue", "black"}));
    EXPECT_FALSE(session.activateAbility()) << "nothing to activate while aiming";
    launchAndFly(session, 30.0, 10.0, 0.2);
    EXPECT_FALSE(session.canActivateAbility()) << "red has no ability";
    while (session.phase() == Phase::Flying)
        session.step();

    // Split only in free flight: after the first contact it is too late.
    session.launch(-10.0, 8.0);
    while (session.world().birdInFreeFlight())
        session.step();
    EXPECT_FALSE(session.activateAbility());
    while (session.phase() == Phase::Flying)
        session.step();

    // Explode also after contact.
    session.launch(-10.0, 8.0);
    while (session.world().birdInFreeFlight())
        session.step();
    EXPECT_TRUE(session.activateAbility());
    EXPECT_FALSE(session.shots().back().ability->beforeContact);
}

TEST(Abilities, ScriptedShotsUseThemAtTheirTimeAndReplayIdentically)
{
    const LevelDef level = abilityLevel({"yellow", "white"});
    const std::vector<ScriptedShot> shots{{20.0, 15.0, 0.2}, {40.0, 14.0, 0.5}};
    const auto a = simulateShots(level, shots);
    const auto b = simulateShots(level, shots);
    ASSERT_EQ(a->shots().size(), 2u);
    for (std::size_t i = 0; i < 2; ++i)
    {
        ASSERT_TRUE(a->shots()[i].ability.has_value()) << i;
        EXPECT_NEAR(a->shots()[i].ability->tS, *shots[i].abilityAtS, 1.0 / 60.0) << i;
        EXPECT_EQ(a->shots()[i].actualPath, b->shots()[i].actualPath) << i;
    }
    EXPECT_EQ(a->score().total(), b->score().total());
    EXPECT_THROW(simulateShots(abilityLevel({"red"}), {{20.0, 15.0, 0.2}}), LaunchError);
}

} // namespace
} // namespace abalike
