#include <abalike/design/ModelPlayer.hpp>
#include <abalike/level/LevelIO.hpp>
#include <cmath>
#include <gtest/gtest.h>

namespace abalike
{
namespace
{

LevelDef level(const std::string& name)
{
    return loadLevel(std::string(ABALIKE_SOURCE_DIR) + "/levels/" + name, Catalog::builtin());
}

TEST(ModelPlayer, AimsItsFirstShotAtAWinWhenOneIsInItsBudget)
{
    // 1-1's first bird can win alone at full pull (the solver's first shot wins with two birds to spare).
    const LevelDef l = level("1-1-first-flight.json");
    std::size_t simulations = 0;
    const ScriptedShot shot = modelPlayerShot(l, {}, Catalog::builtin(), &simulations);
    EXPECT_EQ(simulations, 57u); // 19 angles (-10 to 80 degrees) x 3 pulls
    EXPECT_EQ(std::fmod(shot.angleDeg, 5.0), 0.0);
    EXPECT_LE(shot.angleDeg, 80.0);
    EXPECT_FALSE(shot.abilityAtS);
}

TEST(ModelPlayer, AMeasurementInPartsIsTheMeasurementOfAllItsRuns)
{
    // check --solve's first estimate: run 0 first, runs 1-2 after it, the first aim made once.
    const LevelDef l = level("1-1-first-flight.json");
    ModelPlayerOptions options;
    options.runs = 3;
    const PlayerDifficulty whole = measurePlayerDifficulty(l, Catalog::builtin(), options);
    options.runs = 1;
    const PlayerDifficulty first = measurePlayerDifficulty(l, Catalog::builtin(), options);
    options.runs = 2;
    options.firstRun = 1;
    options.firstShot = first.firstShot;
    const PlayerDifficulty joined = joinDifficulty(first, measurePlayerDifficulty(l, Catalog::builtin(), options));
    EXPECT_EQ(joined.runs, 3u);
    EXPECT_EQ(joined.wins, whole.wins);
    EXPECT_EQ(joined.winScores, whole.winScores);
    EXPECT_EQ(joined.simulations, whole.simulations);
    EXPECT_EQ(joined.low90, whole.low90);
    ASSERT_TRUE(whole.firstShot && joined.firstShot);
    EXPECT_EQ(joined.firstShot->angleDeg, whole.firstShot->angleDeg);
}

TEST(ModelPlayer, TheSameSeedGivesTheSameDifficultyOnAnyNumberOfThreads)
{
    const LevelDef l = level("2-8-dominoes.json");
    ModelPlayerOptions options;
    options.runs = 6;
    options.threads = 1;
    const PlayerDifficulty one = measurePlayerDifficulty(l, Catalog::builtin(), options);
    options.threads = 2;
    const PlayerDifficulty two = measurePlayerDifficulty(l, Catalog::builtin(), options);
    EXPECT_EQ(one.wins, two.wins);
    EXPECT_EQ(one.simulations, two.simulations);
    EXPECT_EQ(one.runs, 6u);
    EXPECT_GT(one.simulations, 57u);
    // The Wilson interval holds the share and stays in [0, 1].
    EXPECT_LE(one.low90, one.winShare);
    EXPECT_GE(one.high90, one.winShare);
    EXPECT_GE(one.low90, 0.0);
    EXPECT_LE(one.high90, 1.0);
}

TEST(ModelPlayer, TheWilsonIntervalOfTwentyNineOfFortyIsSixtyToEightyTwo)
{
    // 1-1 as measured (levels/README.md): 29 of 40 runs won. z = 1.645: centre (0.725 + z^2/80) / (1 + z^2/40) =
    // 0.7107, half-width z sqrt(0.725 * 0.275 / 40 + z^2 / 6400) / (1 + z^2/40) = 0.1133.
    const auto [low, high] = wilsonInterval90(29, 40);
    EXPECT_NEAR(low, 0.5975, 5e-4);
    EXPECT_NEAR(high, 0.8240, 5e-4);
    // None of 40 still leaves room above zero; all of 40 below one.
    EXPECT_DOUBLE_EQ(wilsonInterval90(0, 40)[0], 0.0);
    EXPECT_NEAR(wilsonInterval90(0, 40)[1], 0.0634, 5e-4);
    EXPECT_NEAR(wilsonInterval90(40, 40)[0], 0.9366, 5e-4);
}

TEST(ModelPlayer, ALevelWithoutBirdsOrPigsHasNothingToMeasure)
{
    LevelDef l = level("1-1-first-flight.json");
    l.pigs.clear();
    EXPECT_EQ(measurePlayerDifficulty(l).wins, 0u);
}

} // namespace
} // namespace abalike
