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

TEST(SlingshotBand, AMasslessBandIsALinearSpringThatGivesItsEnergyToTheBird)
{
    // The teacher's example: a 1 200 N band at a 2 m full pull without moving mass, drawn back 1.6 m, launching the
    // 4 kg red bird.
    const BandDef sling{1200.0, 2.0, 0.0};
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
    EXPECT_NEAR(pull.birdEnergyJ, pull.energyJ, 1e-9);
    EXPECT_DOUBLE_EQ(pull.bandEnergyJ, 0.0);
    EXPECT_DOUBLE_EQ(band.fullEnergyJ(), 1200.0);
}

TEST(SlingshotBand, TheMovingBandSharesItsEnergyAndEvensTheSpeedsOut)
{
    // Issue 57's numbers: 8 100 N at 2 m with 14 kg moving with the bird.
    const BandDef sling{8100.0, 2.0, 14.0};
    const SlingshotBand red(sling, 4.0, 864.0);
    const BandPull full = red.atFraction(1.0);
    EXPECT_DOUBLE_EQ(full.energyJ, 8100.0);
    EXPECT_NEAR(full.speedMps, 30.0, 1e-12); // 2 m x sqrt(4050 N/m / 18 kg)
    EXPECT_NEAR(full.birdEnergyJ, 1800.0, 1e-9);
    EXPECT_NEAR(full.bandEnergyJ, 6300.0, 1e-9);
    EXPECT_NEAR(full.birdEnergyJ + full.bandEnergyJ, full.energyJ, 1e-9); // nothing lost, only shared
    EXPECT_NEAR(red.birdShare(), 4.0 / 18.0, 1e-15);
    // Momentum of the bird and band together equals the impulse the stretched spring gives: sqrt(2 E (m + m_b)).
    EXPECT_NEAR(18.0 * full.speedMps, std::sqrt(2.0 * 8100.0 * 18.0), 1e-9);
    for (const double fraction : {0.25, 0.5, 1.0})
    {
        const SlingshotBand heavy(sling, 8.0, 864.0);
        const double ratio = heavy.atFraction(fraction).speedMps / red.atFraction(fraction).speedMps;
        EXPECT_NEAR(ratio, std::sqrt(18.0 / 22.0), 1e-12) << "not 1/sqrt(2): the band's mass moves with both";
    }
}

TEST(SlingshotBand, EveryBirdLeavesWithinTenPercentOfTheRedBirdForTheSamePull)
{
    const Catalog& catalog = Catalog::builtin();
    const LevelDef earth; // no band of its own: Earth's from the catalog
    const struct
    {
        const char* bird;
        double speedMps;
        double momentumNs;
    } expected[] = {{"red", 30.0, 120.0},
                    {"blue", 32.33, 48.5},
                    {"yellow", 30.87, 92.6},
                    {"black", 27.14, 217.1},
                    {"white", 29.20, 146.0}};
    for (const auto& e : expected)
    {
        const BirdType& bird = *catalog.findBird(e.bird);
        const double v0 = maxLaunchSpeed(earth, bird, catalog);
        EXPECT_NEAR(v0, e.speedMps, 0.005) << e.bird;
        EXPECT_NEAR(bird.massKg * v0, e.momentumNs, 0.05) << e.bird;
    }
    // The rule, over every bird of the catalog and a pull that is not full.
    for (const BirdType& bird : catalog.birds())
    {
        const double ratio = slingshotBand(earth, bird, catalog).atFraction(0.6).speedMps /
                             slingshotBand(earth, *catalog.findBird("red"), catalog).atFraction(0.6).speedMps;
        EXPECT_GE(ratio, 0.9) << bird.name;
        EXPECT_LE(ratio, 1.1) << bird.name;
    }
}

TEST(SlingshotBand, EachWorldHasOneBandAndALevelMaySetItsOwn)
{
    const Catalog& catalog = Catalog::builtin();
    const BirdType& red = *catalog.findBird("red");
    const struct
    {
        double gravity;
        double redSpeedMps;
    } worlds[] = {{9.81, 30.0}, {1.62, 17.5}, {3.71, 12.5}, {1.35, 30.0}, {24.79, 50.0}};
    for (const auto& w : worlds)
    {
        LevelDef level;
        level.environment.gravity = w.gravity;
        EXPECT_NEAR(maxLaunchSpeed(level, red, catalog), w.redSpeedMps, 1e-9) << w.gravity;
    }
    LevelDef own;
    own.slingshot.maxForceN = 1200.0;
    own.slingshot.bandMassKg = 0.0;
    EXPECT_EQ(levelBand(own, catalog), (BandDef{1200.0, 2.0, 0.0}));
    EXPECT_NEAR(maxLaunchSpeed(own, red, catalog), std::sqrt(600.0), 1e-12);
}

TEST(SlingshotBand, TheCapLimitsTheSpeedAndASpeedMapsBackToItsPull)
{
    // A massless band of the loader's largest force: 1 155 m/s by the band alone. (With the catalog's 14 kg moving,
    // even that force gives the blue bird only 359 m/s.)
    const BandDef sling{1.0e6, 2.0, 0.0};
    const SlingshotBand band(sling, 1.5, 864.0);
    EXPECT_NEAR(band.fullPullSpeedMps(), std::sqrt(1.0e6 * 2.0 / 1.5), 1e-9);
    EXPECT_DOUBLE_EQ(band.maxSpeedMps(), 864.0);
    EXPECT_TRUE(band.atFraction(1.0).capped);
    EXPECT_DOUBLE_EQ(band.atFraction(1.0).speedMps, 864.0);
    const BandPull pull = band.forSpeed(300.0);
    EXPECT_NEAR(pull.fraction, 300.0 / band.fullPullSpeedMps(), 1e-15);
    EXPECT_DOUBLE_EQ(pull.speedMps, 300.0);
    EXPECT_DOUBLE_EQ(pull.birdEnergyJ, 0.5 * 1.5 * 300.0 * 300.0);
    EXPECT_DOUBLE_EQ(band.atFraction(-1.0).speedMps, 0.0);
    EXPECT_DOUBLE_EQ(band.atFraction(2.0).fraction, 1.0);
}

TEST(SlingshotBand, LevelsReadAndWriteTheFullPull)
{
    const std::string text = R"({"format": 1, "id": "t", "title": "t", "slingshot": {"x": 0, "y": 1.5,
        "max_force_n": 900, "max_pull_m": 0.5, "band_mass_kg": 0}, "birds": ["red"],
        "pigs": [{"type": "small", "x": 5, "y": 0.25}]})";
    const LevelDef level = parseLevel(text, "pull.json", Catalog::builtin());
    EXPECT_EQ(level.slingshot.maxPullM, 0.5);
    EXPECT_EQ(level.slingshot.bandMassKg, 0.0);
    // 1/2 x 900 N x 0.5 m = 225 J, all to the bird: the red bird leaves at sqrt(2 x 225 / 4) = 10.6 m/s.
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
