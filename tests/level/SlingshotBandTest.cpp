#include <abalike/game/GameSession.hpp>
#include <abalike/level/LevelFlight.hpp>
#include <abalike/level/LevelIO.hpp>
#include <abalike/level/LevelWriter.hpp>
#include <abalike/level/SlingshotBand.hpp>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

TEST(SlingshotBand, IsALinearSpringThatGivesItsEnergyToTheBird)
{
    // The teacher's example: a 1 200 N band at a 2 m full pull, drawn back 1.6 m, launching the 4 kg red bird.
    SlingshotDef sling;
    sling.maxForceN = 1200.0;
    sling.maxPullM = 2.0;
    const SlingshotBand band(sling, 4.0, 864.0);
    EXPECT_DOUBLE_EQ(band.stiffness(), 600.0);
    const BandPull pull = band.atFraction(0.8);
    EXPECT_DOUBLE_EQ(pull.pullM, 1.6);
    EXPECT_DOUBLE_EQ(pull.forceN, 960.0);                            // F = k x
    EXPECT_DOUBLE_EQ(pull.energyJ, 768.0);                           // E = 1/2 F x
    EXPECT_NEAR(pull.speedMps, std::sqrt(2.0 * 768.0 / 4.0), 1e-12); // v0 = sqrt(2 E / m) = 19.6 m/s
    EXPECT_NEAR(pull.speedMps, 19.6, 0.005);
    EXPECT_FALSE(pull.capped);
    // The kinetic energy the bird leaves with is the energy the band stored: no more, no less.
    EXPECT_NEAR(0.5 * 4.0 * pull.speedMps * pull.speedMps, pull.energyJ, 1e-9);
    EXPECT_DOUBLE_EQ(band.fullEnergyJ(), 1200.0);
}

TEST(SlingshotBand, SamePullSameEnergySoATwiceHeavierBirdIsOneOverRootTwoAsFast)
{
    const SlingshotDef sling; // the defaults: 1 800 N at 2 m, 1 800 J
    EXPECT_DOUBLE_EQ(sling.maxForceN, 1800.0);
    EXPECT_DOUBLE_EQ(sling.maxPullM, 2.0);
    const SlingshotBand light(sling, 4.0, 864.0);
    const SlingshotBand heavy(sling, 8.0, 864.0);
    for (const double fraction : {0.25, 0.5, 1.0})
    {
        const BandPull a = light.atFraction(fraction);
        const BandPull b = heavy.atFraction(fraction);
        EXPECT_DOUBLE_EQ(a.energyJ, b.energyJ);
        EXPECT_NEAR(b.speedMps / a.speedMps, 1.0 / std::sqrt(2.0), 1e-12);
        // Momentum is not the same: the heavy bird carries sqrt(2) times more.
        EXPECT_NEAR(8.0 * b.speedMps / (4.0 * a.speedMps), std::sqrt(2.0), 1e-12);
    }
}

TEST(SlingshotBand, DefaultSlingshotKeepsTheRedBirdsThirtyMetresPerSecond)
{
    const Catalog& catalog = Catalog::builtin();
    const SlingshotDef sling;
    const struct
    {
        const char* bird;
        double speedMps;
    } expected[] = {{"red", 30.0}, {"blue", 48.99}, {"yellow", 34.64}, {"black", 21.21}, {"white", 26.83}};
    for (const auto& e : expected)
        EXPECT_NEAR(maxLaunchSpeed(sling, *catalog.findBird(e.bird), catalog), e.speedMps, 0.005) << e.bird;
}

TEST(SlingshotBand, TheCapLimitsTheSpeedAndASpeedMapsBackToItsPull)
{
    SlingshotDef sling;
    sling.maxForceN = 1.0e6;
    const SlingshotBand band(sling, 1.5, 864.0);
    EXPECT_NEAR(band.fullPullSpeedMps(), std::sqrt(1.0e6 * 2.0 / 1.5), 1e-9);
    EXPECT_DOUBLE_EQ(band.maxSpeedMps(), 864.0);
    EXPECT_TRUE(band.atFraction(1.0).capped);
    EXPECT_DOUBLE_EQ(band.atFraction(1.0).speedMps, 864.0);
    const BandPull pull = band.forSpeed(300.0);
    EXPECT_NEAR(pull.fraction, 300.0 / band.fullPullSpeedMps(), 1e-15);
    EXPECT_DOUBLE_EQ(pull.speedMps, 300.0);
    EXPECT_DOUBLE_EQ(band.atFraction(-1.0).speedMps, 0.0);
    EXPECT_DOUBLE_EQ(band.atFraction(2.0).fraction, 1.0);
}

TEST(SlingshotBand, LevelsReadAndWriteTheFullPull)
{
    const std::string text = R"({"format": 1, "id": "t", "title": "t", "slingshot": {"x": 0, "y": 1.5,
        "max_force_n": 900, "max_pull_m": 0.5}, "birds": ["red"], "pigs": [{"type": "small", "x": 5, "y": 0.25}]})";
    const LevelDef level = parseLevel(text, "pull.json", Catalog::builtin());
    EXPECT_DOUBLE_EQ(level.slingshot.maxPullM, 0.5);
    // 1/2 x 900 N x 0.5 m = 225 J: the red bird leaves at sqrt(2 x 225 / 4) = 10.6 m/s.
    EXPECT_NEAR(GameSession(level).maxLaunchSpeed(), std::sqrt(112.5), 1e-12);
    LevelDef again = parseLevel(writeLevelJson(level, ""), "pull.json", Catalog::builtin());
    EXPECT_EQ(again.slingshot, level.slingshot);
    const std::string tooLong = R"({"format": 1, "id": "t", "title": "t", "slingshot": {"x": 0, "y": 1.5,
        "max_pull_m": 20}, "birds": ["red"], "pigs": [{"type": "small", "x": 5, "y": 0.25}]})";
    try
    {
        parseLevel(tooLong, "long.json", Catalog::builtin());
        FAIL() << "a 20 m pull was accepted";
    }
    catch (const LevelLoadError& e)
    {
        EXPECT_NE(std::string(e.what()).find("max_pull_m"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("10"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace abalike
