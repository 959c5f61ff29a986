#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelIO.hpp>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

LevelDef scoringLevel()
{
    return loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/1-1-first-flight.json", Catalog::builtin());
}

TEST(Scoring, AccuracyFallsLinearlyToZeroAtTheTolerance)
{
    EXPECT_EQ(accuracyPointsFor(0.0, 1000, 0.05), 1000);
    EXPECT_EQ(accuracyPointsFor(0.0003, 1000, 0.05), 990);   // 994 in steps of ten
    EXPECT_EQ(accuracyPointsFor(0.00005, 1000, 0.05), 1000); // 999: a perfect shot to the eye
    EXPECT_EQ(accuracyPointsFor(0.025, 1000, 0.05), 500);
    EXPECT_EQ(accuracyPointsFor(0.05, 1000, 0.05), 0);
    EXPECT_EQ(accuracyPointsFor(3.0, 1000, 0.05), 0);
    EXPECT_EQ(accuracyPointsFor(-1.0, 1000, 0.05), 0);
}

TEST(Scoring, TheBreakdownAddsUpAndExplainsEachLine)
{
    const auto session = simulateShots(scoringLevel(), {{55.0, 17.0}, {10.0, 23.0}});
    ASSERT_EQ(session->phase(), Phase::Won);
    const ScoreBreakdown s = session->score();
    const ScoringRules& rules = session->catalog().scoring();
    EXPECT_EQ(s.total(), s.blockPoints + s.pigPoints + s.unusedBirdBonus + s.efficiencyBonus + s.accuracyBonus);
    EXPECT_EQ(s.unusedBirds, 2) << "two of 1-1's four birds were left";
    EXPECT_EQ(s.unusedBirdBonus, 2 * rules.pointsPerUnusedBird);
    // The first shot defeats two pigs: one of them is the efficiency bonus.
    ASSERT_EQ(session->shots().size(), 2u);
    EXPECT_EQ(session->shots()[0].pigsDefeated, 2);
    EXPECT_EQ(session->shots()[1].pigsDefeated, 1);
    EXPECT_EQ(s.efficiencyBonus, rules.efficiencyPointsPerExtraPig);
    // Both shots met the towers where the preview said (our world follows the RK4 path to about a micrometre).
    EXPECT_EQ(s.accurateShots, 2);
    int accuracy = 0;
    for (const ShotRecord& shot : session->shots())
    {
        ASSERT_TRUE(shot.deviationM.has_value());
        EXPECT_EQ(shot.accuracyPoints,
                  accuracyPointsFor(*shot.deviationM, rules.accuracyPointsPerShot, rules.accuracyToleranceM));
        accuracy += shot.accuracyPoints;
    }
    EXPECT_EQ(s.accuracyBonus, accuracy);
    EXPECT_GE(s.accuracyBonus, 2 * rules.accuracyPointsPerShot - 2);
}

TEST(Scoring, AShotIntoTheGroundEarnsNoAccuracy)
{
    const auto session = simulateShots(scoringLevel(), {{5.0, 8.0}});
    const ShotRecord& shot = session->shots()[0];
    ASSERT_TRUE(shot.deviationM.has_value());
    EXPECT_EQ(shot.firstTouched, EntityKind::Ground);
    EXPECT_EQ(shot.accuracyPoints, 0);
    EXPECT_EQ(session->score().accuracyBonus, 0);
}

TEST(Scoring, StarsFollowTheLevelsThresholds)
{
    EXPECT_EQ(starsFor(50000, false, {10, 20, 30}), 0);
    EXPECT_EQ(starsFor(5, true, {10, 20, 30}), 1);
    EXPECT_EQ(starsFor(20, true, {10, 20, 30}), 2);
    EXPECT_EQ(starsFor(30, true, {10, 20, 30}), 3);
}

TEST(Slingshot, SamePullSendsAHeavyBirdSlowerAndTheErrorNamesTheTopSpeed)
{
    LevelDef level = scoringLevel();
    level.birds = {"blue", "black"};
    level.slingshot.maxForceN = 1200.0; // 1 200 J at the full 2 m pull
    level.slingshot.bandMassKg = 0.0;   // a massless band: all of it to the bird
    GameSession session(level);
    const double blue = session.band()->atFraction(0.5).speedMps;
    EXPECT_DOUBLE_EQ(session.band()->forSpeed(blue).fraction, 0.5);
    EXPECT_DOUBLE_EQ(blue, std::sqrt(2.0 * 300.0 / 1.5)); // half the pull stores a quarter of the energy: 300 J
    try
    {
        session.launch(45.0, session.maxLaunchSpeed() + 1.0);
        FAIL() << "launched faster than the slingshot allows";
    }
    catch (const LaunchError& e)
    {
        EXPECT_NE(std::string(e.what()).find("can be launched at most 40 m/s"), std::string::npos) << e.what();
    }
    session.launch(45.0, 10.0);
    while (session.phase() == Phase::Flying)
        session.step();
    EXPECT_LT(session.band()->atFraction(0.5).speedMps, blue) << "black (8 kg) is slower than blue (1.5 kg)";
    EXPECT_DOUBLE_EQ(session.maxLaunchSpeed(), std::sqrt(2.0 * 1200.0 / 8.0));
}

} // namespace
} // namespace abalike
